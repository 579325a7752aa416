// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#include "coagulation/aerosol/AerosolProperties.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace coag {

void requirePositive(const char* who, const char* what, double v)
{
    if (!(v > 0.0) || !std::isfinite(v)) {
        std::ostringstream os;
        os << who << ": " << what << " must be positive and finite, got " << v;
        throw std::invalid_argument(os.str());
    }
}

void GasState::check() const
{
    requirePositive("coag::GasState", "the temperature T [K]", T);
    requirePositive("coag::GasState", "the pressure p [Pa]", p);
    requirePositive("coag::GasState", "the dynamic viscosity mu [Pa s]", mu);
    requirePositive("coag::GasState", "the molar mass [kg/mol]", molarMass);
}

double GasState::meanFreePath() const
{
    using namespace constants;
    return 2.0 * mu / (p * std::sqrt(8.0 * molarMass / (pi * gasConstant * T)));
}

double sutherlandViscosity(double T, double As, double Ts)
{
    return As * std::sqrt(T) / (1.0 + Ts / T);
}

void ParticleMaterial::check() const
{
    requirePositive("coag::ParticleMaterial", "the density [kg/m3]", density);
    requirePositive("coag::ParticleMaterial", "the mass unit [kg]", massUnit);
}

double ParticleMaterial::diameter(double mass) const
{
    return std::cbrt(6.0 * mass * massUnit / (constants::pi * density));
}

double ParticleMaterial::mass(double diameter) const
{
    return density * constants::pi * diameter * diameter * diameter / 6.0 / massUnit;
}

double stokesEinsteinDiffusivity(double kT, double C, double mu, double d)
{
    return kT * C / (3.0 * constants::pi * mu * d);
}

} // namespace coag
