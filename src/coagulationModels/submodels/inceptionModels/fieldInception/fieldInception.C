/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "fieldInception.H"
#include "caseChecks.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace coagulation
{
namespace inceptionModels
{
    defineTypeNameAndDebug(field, 0);
    addToRunTimeSelectionTable(inceptionModel, field, dictionary);
}
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coagulation::inceptionModels::field::field
(
    const dictionary& dict,
    const fvMesh& mesh,
    const scalar particleWeight
)
:
    inceptionModel(dict, particleWeight, {"field"}, false),
    rate_
    (
        flowFields::of(mesh).cellField
        (
            dict,
            "inception model 'field'",
            "field",
            dict.get<word>("field"),
            dimensionSet(0, -3, -1, 0, 0),
            false
        )
    ),
    cellRates_(rate_().primitiveField()),
    version_(rate_.version())
{
    setRate(gMax(cellRates_));

    label nCells = 0;
    forAll(cellRates_, celli)
    {
        nCells += incepts(celli);
    }
    Info<< "Inception rate from field " << rate_.name() << ": "
        << gMin(cellRates_) << " to " << gMax(cellRates_)
        << " per unit volume and time, "
        << returnReduce(nCells, sumOp<label>()) << " cells with a rate > 0"
        << endl;
}


// ************************************************************************* //
