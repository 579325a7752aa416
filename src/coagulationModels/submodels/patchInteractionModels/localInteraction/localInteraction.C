/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "localInteraction.H"
#include "caseChecks.H"
#include "wallPolyPatch.H"
#include "DynamicList.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace coagulation
{
namespace patchInteractionModels
{
    defineTypeNameAndDebug(localInteraction, 0);
    addToRunTimeSelectionTable
    (
        patchInteractionModel,
        localInteraction,
        dictionary
    );
}
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coagulation::patchInteractionModels::localInteraction::localInteraction
(
    const dictionary& dict,
    const polyMesh& mesh
)
:
    patchInteractionModel(mesh)
{
    caseChecks::keywords(dict, {"type", "patches"});
    const dictionary& patches = dict.subDict("patches");
    const polyBoundaryMesh& boundary = mesh.boundaryMesh();

    // Every entry: a valid interaction that matches at least one wall
    for (const entry& e : patches)
    {
        const word value(e.stream());
        if (value != "rebound" && value != "stick")
        {
            FatalIOErrorInFunction(patches)
                << "Entry '" << e.keyword() << "' in " << patches.name()
                << " is '" << value << "'; valid interactions are"
                << " (rebound stick)" << nl << exit(FatalIOError);
        }
        bool matched = false;
        DynamicList<word> walls;
        forAll(boundary, patchi)
        {
            if (isA<wallPolyPatch>(boundary[patchi]))
            {
                walls.append(boundary[patchi].name());
                matched = matched || e.keyword().match(boundary[patchi].name());
            }
        }
        if (!matched)
        {
            FatalIOErrorInFunction(patches)
                << "Entry '" << e.keyword() << "' in " << patches.name()
                << " matches no wall patch; the wall patches are "
                << walls << nl << exit(FatalIOError);
        }
    }

    // Every wall: an interaction (the last matching entry, as dictionary
    // lookups of regular expressions do)
    forAll(boundary, patchi)
    {
        if (!isA<wallPolyPatch>(boundary[patchi]))
        {
            continue;
        }
        const entry* ePtr =
            patches.findEntry(boundary[patchi].name(), keyType::REGEX);
        if (!ePtr)
        {
            FatalIOErrorInFunction(patches)
                << "Wall patch '" << boundary[patchi].name() << "' has no"
                << " interaction in " << patches.name()
                << ": set it to rebound or stick" << nl << exit(FatalIOError);
        }
        stick_[patchi] = (word(ePtr->stream()) == "stick");
    }
}


// ************************************************************************* //
