/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "linearGrowth.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace coagulation
{
namespace growthModels
{
    defineTypeNameAndDebug(linearGrowth, 0);
    addToRunTimeSelectionTable(growthModel, linearGrowth, dictionary);
}
}
}


Foam::coagulation::growthModels::linearGrowth::linearGrowth
(
    const word& name,
    const dictionary& dict,
    const fvMesh&
)
:
    constantGrowth(name, dict, 1, typeName)
{}


// ************************************************************************* //
