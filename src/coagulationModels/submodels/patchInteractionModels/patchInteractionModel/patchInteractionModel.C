/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "patchInteractionModel.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace coagulation
{
    defineTypeNameAndDebug(patchInteractionModel, 0);
    defineRunTimeSelectionTable(patchInteractionModel, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coagulation::patchInteractionModel::patchInteractionModel
(
    const polyMesh& mesh
)
:
    stick_(mesh.boundaryMesh().size(), false)
{}


// * * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::coagulation::patchInteractionModel>
Foam::coagulation::patchInteractionModel::New
(
    const dictionary& dict,
    const polyMesh& mesh
)
{
    const word modelType(dict.getOrDefault<word>("type", "localInteraction"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "patchInteractionModel",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<patchInteractionModel>(cstrIter()(dict, mesh));
}


// ************************************************************************* //
