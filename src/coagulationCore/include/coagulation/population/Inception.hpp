// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_INCEPTION_HPP
#define COAGULATION_INCEPTION_HPP

#include "coagulation/population/ParticleType.hpp"

namespace coag {

//- Constant-rate inception of particles of one type.
struct InceptionModel {
    double rate = 0.0;    //!< physical particles per unit volume per unit time, >= 0
    ParticleType type{};  //!< type of the incepted particles
    double weight = 1.0;  //!< statistical weight of an incepted computational particle (> 0)
};

} // namespace coag

#endif
