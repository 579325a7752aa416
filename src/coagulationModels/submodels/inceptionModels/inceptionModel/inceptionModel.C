/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "inceptionModel.H"
#include "particleMaterial.H"
#include "caseChecks.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace coagulation
{
    defineTypeNameAndDebug(inceptionModel, 0);
    defineRunTimeSelectionTable(inceptionModel, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coagulation::inceptionModel::inceptionModel
(
    const dictionary& dict,
    const scalar particleWeight,
    const wordList& keywords,
    const bool rateEntry
)
:
    core_()
{
    wordList valid({"type", "mass", "diameter"});
    if (rateEntry)
    {
        valid.append("rate");
    }
    valid.append(keywords);
    caseChecks::keywords(dict, valid);
    core_.rate = rateEntry ? caseChecks::nonNegative(dict, "rate") : 0;
    core_.type.mass = readParticleMass(dict, "inception");
    core_.weight = particleWeight;
}


// * * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::coagulation::inceptionModel>
Foam::coagulation::inceptionModel::New
(
    const dictionary& dict,
    const fvMesh& mesh,
    const scalar particleWeight
)
{
    // Without a 'type', a named cellZone selects the cellZone model
    const word zone(dict.getOrDefault<word>("cellZone", "none"));
    const word modelType
    (
        dict.getOrDefault<word>("type", zone == "none" ? "uniform" : "cellZone")
    );

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "inceptionModel",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<inceptionModel>(cstrIter()(dict, mesh, particleWeight));
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::coagulation::inceptionModel::nCells
(
    const label nMeshCells
) const
{
    label n = 0;
    for (label celli = 0; celli < nMeshCells; ++celli)
    {
        n += incepts(celli);
    }
    return n;
}


// ************************************************************************* //
