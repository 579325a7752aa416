// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_PARTICLE_HPP
#define COAGULATION_PARTICLE_HPP

#include "coagulation/population/ParticleType.hpp"

#include <cstdint>

namespace coag {

//- One computational particle of a cell population: 24 bytes, so that the large cells of
//  high-n runs stay dense in the caches. Anything else the caller keeps (a position, the
//  OpenFOAM particle) it finds through the tag.
struct Particle {
    ParticleType type;
    double weight = 1.0;                 //!< statistical weight: number of physical particles represented
    std::int64_t tag = -1;               //!< caller's handle; -1 for particles the algorithm created
};

} // namespace coag

#endif
