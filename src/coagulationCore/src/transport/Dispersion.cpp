// coagulationCore. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#include "coagulation/transport/Dispersion.hpp"

#include <cmath>
#include <stdexcept>

namespace coag {

double sphereDiameter(double mass, const BrownianGas& gas)
{
    constexpr double pi = 3.14159265358979323846;
    return std::cbrt(6.0 * mass * gas.massUnit / (pi * gas.density));
}

double slipCorrection(double diameter, const BrownianGas& gas)
{
    const double kn = 2.0 * gas.meanFreePath / diameter;
    return 1.0 + kn * (gas.A1 + gas.A2 * std::exp(-gas.A3 / kn));
}

double brownianDiffusivity(double mass, const BrownianGas& gas)
{
    constexpr double pi = 3.14159265358979323846;
    if (!(mass > 0)) {
        throw std::invalid_argument("brownianDiffusivity: the particle mass must be positive");
    }
    const double d = sphereDiameter(mass, gas);
    return boltzmann * gas.temperature * slipCorrection(d, gas) / (3.0 * pi * gas.viscosity * d);
}

} // namespace coag
