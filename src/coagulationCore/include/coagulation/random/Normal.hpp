// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_NORMAL_HPP
#define COAGULATION_NORMAL_HPP

#include <cmath>

namespace coag {

//- Two independent standard normals.
struct NormalPair {
    double first, second;
};

//- The Box-Muller transform (Box & Muller, Ann. Math. Statist. 29, 1958): from two
//  independent uniforms u1, u2 on (0,1), r = sqrt(-2 ln u1) and a = 2 pi u2 give the
//  independent standard normals r cos a and r sin a. The project's one normal generator.
inline NormalPair boxMuller(double u1, double u2)
{
    constexpr double twoPi = 6.283185307179586476925286766559;
    const double r = std::sqrt(-2.0 * std::log(u1));
    const double a = twoPi * u2;
    return {r * std::cos(a), r * std::sin(a)};
}

} // namespace coag

#endif
