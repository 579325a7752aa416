/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "constantGrowth.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace coagulation
{
namespace growthModels
{
    defineTypeNameAndDebug(constantGrowth, 0);
    addToRunTimeSelectionTable(growthModel, constantGrowth, dictionary);
}
}
}


Foam::coagulation::growthModels::constantGrowth::constantGrowth
(
    const word& name,
    const dictionary& dict,
    const scalar exponent,
    const word& model
)
:
    growthModel(name, dict, {"rate"}),
    rate_(finite(dict, "rate")),
    exponent_(exponent)
{
    Info<< "Growth " << name << ": " << model << ", rate " << rate_ << endl;
}


Foam::coagulation::growthModels::constantGrowth::constantGrowth
(
    const word& name,
    const dictionary& dict,
    const fvMesh&
)
:
    constantGrowth(name, dict, 0, typeName)
{}


// ************************************************************************* //
