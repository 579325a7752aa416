// coagulationCore. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#include "coagulation/transport/Dispersion.hpp"

#include <stdexcept>

namespace coag {

double sphereDiameter(double mass, const BrownianGas& gas)
{
    return ParticleMaterial{gas.density, gas.massUnit}.diameter(mass);
}

double slipCorrection(double diameter, const BrownianGas& gas)
{
    return gas.slip(2.0 * gas.meanFreePath / diameter);
}

double brownianDiffusivity(double mass, const BrownianGas& gas)
{
    if (!(mass > 0)) {
        throw std::invalid_argument("brownianDiffusivity: the particle mass must be positive");
    }
    const double d = sphereDiameter(mass, gas);
    return stokesEinsteinDiffusivity(constants::boltzmann * gas.temperature,
                                      slipCorrection(d, gas), gas.viscosity, d);
}

} // namespace coag
