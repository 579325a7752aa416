// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#include "coagulation/statistics/Moments.hpp"

#include <cmath>
#include <stdexcept>

namespace coag {

std::array<double, 4> moments(const CellPopulation& pop)
{
    std::array<double, 4> m{0.0, 0.0, 0.0, 0.0};
    for (const Particle& p : pop.particles) {
        const double x = p.type.mass;
        const double w = p.weight;
        m[0] += w;
        m[1] += w * x;
        m[2] += w * x * x;
        m[3] += w * x * x * x;
    }
    for (double& v : m) v /= pop.volume;
    return m;
}

} // namespace coag
