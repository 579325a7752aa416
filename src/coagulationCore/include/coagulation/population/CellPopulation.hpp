// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_CELLPOPULATION_HPP
#define COAGULATION_CELLPOPULATION_HPP

#include "coagulation/population/LargeArray.hpp"
#include "coagulation/population/Particle.hpp"

#include <vector>

namespace coag {

//- A cell's particle records: a std::vector whose big allocations lie on huge pages
//  (LargeArray.hpp), since the event loop reads them at random
using ParticleVector = std::vector<Particle, LargeArrayAllocator<Particle>>;

//- One homogeneous cell: the density of physical particles is sum(weight)/volume.
//  The volume is the "sample volume" n V_1 of the paper (DSA number control may change it).
struct CellPopulation {
    ParticleVector particles;
    double volume = 1.0;
};

} // namespace coag

#endif
