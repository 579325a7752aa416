// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_AEROSOLPROPERTIES_HPP
#define COAGULATION_AEROSOLPROPERTIES_HPP

// The gas around the particles and the particles' material, in SI units, and the
// single-particle quantities of aerosol mechanics that the Brownian kernels and the Brownian
// random walk are made of (Seinfeld & Pandis, Atmospheric Chemistry and Physics, chapter 9;
// Hinds, Aerosol Technology, chapters 3 and 7).

#include <cmath>

namespace coag {

namespace constants {
constexpr double boltzmann = 1.380649e-23;      //!< k [J/K] (exact, SI 2019)
constexpr double gasConstant = 8.314462618;     //!< R [J/(mol K)]
constexpr double pi = 3.14159265358979323846;
constexpr double airMolarMass = 0.0289647;      //!< M of dry air [kg/mol]
} // namespace constants

//- Throws std::invalid_argument "who: what must be positive and finite, got v" unless v is.
void requirePositive(const char* who, const char* what, double v);

//- The gas at a point: temperature T [K], pressure p [Pa], dynamic viscosity mu [Pa s],
//  molar mass M [kg/mol]. check() throws std::invalid_argument unless all are positive and
//  finite.
struct GasState {
    double T = 298.15;
    double p = 101325.0;
    double mu = 1.8e-5;
    double molarMass = constants::airMolarMass;

    void check() const;

    //- The mean free path of the gas molecules,
    //      lambda = 2 mu / (p sqrt(8 M / (pi R T)))
    //  (kinetic theory with the mean molecular speed sqrt(8RT/(pi M)); Seinfeld & Pandis
    //  eq. 9.6): about 65 nm for air at 298 K and 1 atm.
    double meanFreePath() const;
};

//- The dynamic viscosity of Sutherland's law as OpenFOAM's thermophysical models write it,
//  mu = As sqrt(T) / (1 + Ts/T); air: As = 1.458e-6 Pa s K^-1/2, Ts = 110.4 K.
double sutherlandViscosity(double T, double As = 1.458e-6, double Ts = 110.4);

//- The particles' material: a particle of mass m (in units of massUnit kg) is a sphere of
//  the material's density rho [kg/m3] (its volume-equivalent diameter).
struct ParticleMaterial {
    double density = 1000.0;
    double massUnit = 1.0;  //!< kg per unit of the particles' masses (1: masses in kg)

    void check() const;

    //- d = (6 m massUnit / (pi rho))^(1/3) [m]
    double diameter(double mass) const;

    //- m = rho pi d^3 / 6 / massUnit
    double mass(double diameter) const;
};

//- The Cunningham slip correction of a sphere of Knudsen number Kn = 2 lambda / d,
//      C = 1 + Kn (A1 + A2 exp(-A3 / Kn)),
//  by default with A1 = 1.257, A2 = 0.400, A3 = 1.10 (Davies 1945, as in Hinds eq. 3.20 and
//  Seinfeld & Pandis eq. 9.34). Between 1 and 1 + (A1 + A2) Kn (bound()), which the
//  continuum kernel's majorant uses.
struct SlipCorrection {
    double A1 = 1.257;
    double A2 = 0.400;
    double A3 = 1.10;

    double operator()(double Kn) const { return 1.0 + Kn * (A1 + A2 * std::exp(-A3 / Kn)); }
    double bound(double Kn) const { return 1.0 + (A1 + A2) * Kn; }
};

//- The Stokes-Einstein diffusivity with slip, D = kT C / (3 pi mu d) [m2/s], of a sphere of
//  diameter d [m] with slip correction C in a gas of viscosity mu [Pa s] at kT [J].
double stokesEinsteinDiffusivity(double kT, double C, double mu, double d);

} // namespace coag

#endif
