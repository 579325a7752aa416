// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_MOMENTS_HPP
#define COAGULATION_MOMENTS_HPP

#include "coagulation/population/CellPopulation.hpp"

#include <array>

namespace coag {

//- Mass moments M_k = sum_j w_j m_j^k / volume, k = 0..3 (Patterson & Wagner eq 37 with
//  volume = n V_1).
std::array<double, 4> moments(const CellPopulation& pop);

} // namespace coag

#endif
