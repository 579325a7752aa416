/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "brownianDispersion.H"
#include "coagulationParticle.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace coagulation
{
namespace dispersionModels
{
    defineTypeNameAndDebug(brownianDispersion, 0);
    addToRunTimeSelectionTable(dispersionModel, brownianDispersion, dictionary);
}
}
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coagulation::dispersionModels::brownianDispersion::brownianDispersion
(
    const dictionary& dict,
    const fvMesh& mesh
)
:
    dispersionModel(mesh),
    gas_(readBrownianGas(dict, {"type"}))
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar
Foam::coagulation::dispersionModels::brownianDispersion::diffusivity
(
    const coagulationParticle& p,
    vector&
) const
{
    return coag::brownianDiffusivity(p.mass(), gas_);
}


// ************************************************************************* //
