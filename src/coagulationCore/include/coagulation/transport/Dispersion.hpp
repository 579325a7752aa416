// coagulationCore: the random-walk half of particle transport. Copyright (C) 2025-2026 the
// coagulationFoam authors. SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_DISPERSION_HPP
#define COAGULATION_DISPERSION_HPP


#include "coagulation/aerosol/AerosolProperties.hpp"

namespace coag {

//- The gas and material that set a particle's Brownian diffusivity (the mean free path
//  given, not derived from a pressure).
struct BrownianGas {
    double temperature = 293.15;   //- T [K]
    double viscosity = 1.81e-5;    //- dynamic viscosity mu [Pa s]
    double meanFreePath = 6.65e-8; //- lambda [m]
    double density = 1000;         //- material density of the (spherical) particles [kg/m^3]
    double massUnit = 1;           //- kg per unit of particle mass (1: masses in kg)
    SlipCorrection slip;           //- Cunningham's C(Kn), Kn = 2 lambda / d
};

//- Diameter [m] of a sphere of the given mass (in BrownianGas::massUnit units).
double sphereDiameter(double mass, const BrownianGas& gas);

//- Cunningham slip correction for a sphere of diameter d [m].
double slipCorrection(double diameter, const BrownianGas& gas);

//- Stokes-Einstein diffusivity with slip, D = k T Cc / (3 pi mu d) [m^2/s], of a sphere of
//  the given mass; the mass must be positive.
double brownianDiffusivity(double mass, const BrownianGas& gas);

} // namespace coag

#endif
