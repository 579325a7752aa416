/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "cellTetSampler.H"
#include "polyMeshTetDecomposition.H"

#include <algorithm>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coagulation::cellTetSampler::cellTetSampler(const polyMesh& mesh)
:
    cellTets_(mesh.nCells()),
    cellTetVolumes_(mesh.nCells()),
    cellTetTotal_(mesh.nCells(), Zero)
{
    forAll(cellTets_, celli)
    {
        cellTets_[celli] =
            polyMeshTetDecomposition::cellTetIndices(mesh, celli);
        const List<tetIndices>& tets = cellTets_[celli];
        scalarList& volumes = cellTetVolumes_[celli];
        volumes.setSize(tets.size());
        forAll(tets, i)
        {
            volumes[i] = tets[i].tet(mesh).mag();
            cellTetTotal_[celli] += volumes[i];
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::coagulation::cellTetSampler::point
Foam::coagulation::cellTetSampler::sample
(
    const label celli,
    coag::Rng& rng
) const
{
    const List<tetIndices>& tets = cellTets_[celli];
    const scalarList& tetVolumes = cellTetVolumes_[celli];

    scalar target = rng.uniform()*cellTetTotal_[celli];
    label chosen = tets.size() - 1;
    forAll(tets, i)
    {
        target -= tetVolumes[i];
        if (target <= 0)
        {
            chosen = i;
            break;
        }
    }

    scalar u[3] = {rng.uniform(), rng.uniform(), rng.uniform()};
    std::sort(u, u + 3);

    point p;
    p.coordinates = barycentric(u[0], u[1] - u[0], u[2] - u[1], 1 - u[2]);
    p.tetFace = tets[chosen].face();
    p.tetPt = tets[chosen].tetPt();
    return p;
}


// ************************************************************************* //
