/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "surfaceGrowth.H"
#include "particleMaterial.H"
#include "addToRunTimeSelectionTable.H"

#include <cmath>

namespace Foam
{
namespace coagulation
{
namespace growthModels
{
    defineTypeNameAndDebug(surfaceGrowth, 0);
    addToRunTimeSelectionTable(growthModel, surfaceGrowth, dictionary);
}
}
}


Foam::coagulation::growthModels::surfaceGrowth::surfaceGrowth
(
    const word& name,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    growthModel(name, dict, {"rate", "factor"}),
    rate_
    (
        dict, "growth model '" + name + "'", "rate",
        dimMass/dimArea/dimTime, mesh, sign::any
    ),
    coefficient_(0)
{
    const coag::ParticleMaterial material =
        readParticleMaterial(dict.topDict(), "growth model '" + name + "'");
    const scalar factor = dict.found("factor") ? finite(dict, "factor") : 1;
    // dm/dt [kg/s] = k_s pi d^2, d = (6 m massUnit / (pi rho))^(1/3); in mass
    // units: k_s pi (6/(pi rho))^(2/3) massUnit^(-1/3) m^(2/3)
    const scalar pi = coag::constants::pi;
    coefficient_ =
        factor*pi*std::pow(6/(pi*material.density), 2.0/3.0)
       /std::cbrt(material.massUnit);

    Info<< "Growth " << name << ": surface, k_s " << rate_.range().c_str();
    if (factor != 1)
    {
        Info<< " times " << factor;
    }
    Info<< " kg/(m2 s), d(d)/dt = 2 k_s/rho" << endl;
}


// ************************************************************************* //
