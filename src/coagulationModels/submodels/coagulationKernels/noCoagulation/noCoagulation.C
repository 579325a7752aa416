/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "noCoagulation.H"
#include "caseChecks.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace coagulation
{
namespace coagulationKernels
{
    defineTypeNameAndDebug(noCoagulation, 0);
    addToRunTimeSelectionTable(coagulationKernel, noCoagulation, dictionary);
}
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coagulation::coagulationKernels::noCoagulation::noCoagulation
(
    const dictionary& dict,
    const fvMesh&
)
:
    coagulationKernel(0, std::make_unique<coag::NoCoagulationKernel>())
{
    caseChecks::keywords(dict, {"type"});
}


// ************************************************************************* //
