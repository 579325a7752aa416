/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "noDispersion.H"
#include "caseChecks.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace coagulation
{
namespace dispersionModels
{
    defineTypeNameAndDebug(noDispersion, 0);
    addToRunTimeSelectionTable(dispersionModel, noDispersion, dictionary);
}
}
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coagulation::dispersionModels::noDispersion::noDispersion
(
    const dictionary& dict,
    const fvMesh& mesh
)
:
    dispersionModel(mesh)
{
    caseChecks::keywords(dict, {"type"});
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::coagulation::dispersionModels::noDispersion::diffusivity
(
    const coagulationParticle&,
    vector&
) const
{
    return 0;
}


// ************************************************************************* //
