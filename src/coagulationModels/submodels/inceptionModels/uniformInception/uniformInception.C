/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "uniformInception.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace coagulation
{
namespace inceptionModels
{
    defineTypeNameAndDebug(uniform, 0);
    addToRunTimeSelectionTable(inceptionModel, uniform, dictionary);
}
}
}


Foam::coagulation::inceptionModels::uniform::uniform
(
    const dictionary& dict,
    const fvMesh&,
    const scalar particleWeight
)
:
    inceptionModel(dict, particleWeight, {"cellZone"})
{
    const word zone(dict.getOrDefault<word>("cellZone", "none"));
    if (zone != "none")
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'cellZone' = " << zone << " in " << dict.name()
            << " with 'type uniform': uniform inception is in every cell;"
            << " use 'type cellZone' or 'cellZone none'" << nl
            << exit(FatalIOError);
    }
}


// ************************************************************************* //
