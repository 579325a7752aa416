/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "condensationGrowth.H"
#include "particleMaterial.H"
#include "caseChecks.H"
#include "addToRunTimeSelectionTable.H"

#include <cmath>

namespace Foam
{
namespace coagulation
{
namespace growthModels
{
    defineTypeNameAndDebug(condensationGrowth, 0);
    addToRunTimeSelectionTable(growthModel, condensationGrowth, dictionary);
}
}
}

const Foam::Enum
<
    Foam::coagulation::growthModels::condensationGrowth::regime
>
Foam::coagulation::growthModels::condensationGrowth::regimeNames
({
    { regime::transition, "transition" },
    { regime::continuum, "continuum" },
    { regime::freeMolecular, "freeMolecular" }
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coagulation::growthModels::condensationGrowth::condensationGrowth
(
    const word& name,
    const dictionary& dict,
    const fvMesh& mesh
)
:
    growthModel
    (
        name, dict,
        {
            "concentration", "saturationConcentration", "molarMass",
            "diffusivity", "accommodation", "T", "regime"
        }
    ),
    concentration_
    (
        dict, "growth model '" + name + "'", "concentration",
        dimDensity, mesh, sign::nonNegative
    ),
    saturation_
    (
        dict.found("saturationConcentration")
      ? cellValue
        (
            dict, "growth model '" + name + "'", "saturationConcentration",
            dimDensity, mesh, sign::nonNegative
        )
      : cellValue(0)
    ),
    T_
    (
        dict, "growth model '" + name + "'", "T", dimTemperature, mesh,
        sign::positive
    ),
    molarMass_(caseChecks::positive(dict, "molarMass")),
    diffusivity_(caseChecks::positive(dict, "diffusivity")),
    accommodation_
    (
        dict.found("accommodation")
      ? caseChecks::positive(dict, "accommodation") : 1
    ),
    regime_
    (
        regimeNames.getOrDefault("regime", dict, regime::transition)
    ),
    massUnit_(1),
    b_(0)
{
    if (accommodation_ > 1)
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'accommodation' in " << dict.name() << " is "
            << accommodation_ << "; it must lie in (0, 1]" << nl
            << exit(FatalIOError);
    }
    const coag::ParticleMaterial material =
        readParticleMaterial(dict.topDict(), "growth model '" + name + "'");
    massUnit_ = material.massUnit;
    b_ = material.diameter(1);

    Info<< "Growth " << name << ": condensation (" << regimeNames[regime_]
        << "), c " << concentration_.range().c_str() << ", c_s "
        << saturation_.range().c_str() << " kg/m3, T "
        << T_.range().c_str() << " K" << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::coagulation::growthModels::condensationGrowth::addTo
(
    const label celli,
    coag::GrowthLaw& law
) const
{
    const scalar dc = concentration_[celli] - saturation_[celli];
    if (dc == 0)
    {
        return;
    }
    const scalar pi = coag::constants::pi;
    // In mass units: dm/dt [kg/s] / massUnit, d = b m^(1/3)
    const scalar a = 2*pi*diffusivity_*dc/massUnit_;
    switch (regime_)
    {
        case regime::continuum:
        {
            law.addPower(a*b_, 1.0/3.0);
            break;
        }
        case regime::freeMolecular:
        {
            const scalar cBar = std::sqrt
            (
                8*coag::constants::gasConstant*T_[celli]/(pi*molarMass_)
            );
            law.addPower
            (
                0.25*pi*accommodation_*cBar*dc*b_*b_/massUnit_, 2.0/3.0
            );
            break;
        }
        case regime::transition:
        {
            const scalar cBar = std::sqrt
            (
                8*coag::constants::gasConstant*T_[celli]/(pi*molarMass_)
            );
            law.addTransition(a, b_, 3*diffusivity_/cBar, accommodation_);
            break;
        }
    }
}


// ************************************************************************* //
