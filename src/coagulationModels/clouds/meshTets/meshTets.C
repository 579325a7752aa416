/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "meshTets.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace coagulation
{
    defineTypeNameAndDebug(meshTets, 0);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coagulation::meshTets::meshTets(const polyMesh& mesh)
:
    MeshObject<polyMesh, TopologicalMeshObject, meshTets>(mesh),
    faceTets_(2*mesh.nFaces(), -1),
    points_()
{
    // A cell's tets together: the particles of a cell, moved one after the
    // other, find them in the cache
    const cellList& cells = mesh.cells();
    const faceList& faces = mesh.faces();
    const labelList& owner = mesh.faceOwner();
    label n = 0;
    forAll(cells, celli)
    {
        for (const label facei : cells[celli])
        {
            faceTets_[2*facei + (owner[facei] == celli ? 0 : 1)] = n;
            n += faces[facei].size() - 2;
        }
    }
    points_.setSize(n);
    forAllTets
    (
        [&](const label i, const tetIndices& tetIs)
        {
            points_[i] = tetIs.faceTriIs(mesh);
        }
    );
}


// ************************************************************************* //
