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
    // other, find them in the cache. A face's first tet (tetPt 1) marks
    // where its tets start
    const labelList& owner = mesh.faceOwner();
    DynamicList<triFace> points;
    forAllTets
    (
        [&](const label i, const tetIndices& tetIs)
        {
            const label facei = tetIs.face();
            if (tetIs.tetPt() == 1)
            {
                faceTets_[2*facei + (owner[facei] == tetIs.cell() ? 0 : 1)] = i;
            }
            points.append(tetIs.faceTriIs(mesh));
        }
    );
    points_.transfer(points);
}


// ************************************************************************* //
