/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "constantDispersion.H"
#include "caseChecks.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace coagulation
{
namespace dispersionModels
{
    defineTypeNameAndDebug(constantDispersion, 0);
    addToRunTimeSelectionTable(dispersionModel, constantDispersion, dictionary);
}
}
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coagulation::dispersionModels::constantDispersion::constantDispersion
(
    const dictionary& dict,
    const fvMesh& mesh
)
:
    dispersionModel(mesh),
    D_(0)
{
    caseChecks::keywords(dict, {"type", "D"});
    D_ = caseChecks::nonNegative(dict, "D");
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar
Foam::coagulation::dispersionModels::constantDispersion::diffusivity
(
    const coagulationParticle&,
    vector&
) const
{
    return D_;
}


// ************************************************************************* //
