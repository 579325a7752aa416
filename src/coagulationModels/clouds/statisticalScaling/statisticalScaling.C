/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "statisticalScaling.H"
#include "caseChecks.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coagulation::statisticalScaling::statisticalScaling
(
    const dictionary& dict,
    const word& algorithm,
    const fvMesh& mesh
)
:
    n_(0),
    V1_(0),
    particleWeight_(0)
{
    caseChecks::keywords(dict, {"n", "V1"});
    n_ = caseChecks::positive(dict, "n");
    if (dict.isDict("V1"))
    {
        caseChecks::keywords(dict.subDict("V1"), {"SWA", "DSA1", "DSA2"});
        V1_ = caseChecks::positive(dict.subDict("V1"), algorithm);
    }
    else
    {
        V1_ = caseChecks::positive(dict, "V1");
    }

    const scalar meanCellVolume =
        gSum(mesh.V())/returnReduce(mesh.nCells(), sumOp<label>());
    particleWeight_ = meanCellVolume/(n_*V1_);
}


// ************************************************************************* //
