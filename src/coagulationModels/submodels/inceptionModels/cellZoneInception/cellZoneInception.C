/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "cellZoneInception.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace coagulation
{
namespace inceptionModels
{
    defineTypeNameAndDebug(cellZone, 0);
    addToRunTimeSelectionTable(inceptionModel, cellZone, dictionary);
}
}
}


Foam::coagulation::inceptionModels::cellZone::cellZone
(
    const dictionary& dict,
    const fvMesh& mesh,
    const scalar particleWeight
)
:
    inceptionModel(dict, particleWeight, {"cellZone"}),
    inZone_(mesh.nCells(), false)
{
    const word zoneName(dict.get<word>("cellZone"));
    const label zonei = mesh.cellZones().findZoneID(zoneName);
    if (zonei < 0)
    {
        FatalIOErrorInFunction(dict)
            << "cellZone '" << zoneName << "' (entry 'cellZone' in "
            << dict.name() << ") is not in the mesh; its cellZones are "
            << mesh.cellZones().names() << nl
            << exit(FatalIOError);
    }
    for (const label celli : mesh.cellZones()[zonei])
    {
        inZone_[celli] = true;
    }
}


// ************************************************************************* //
