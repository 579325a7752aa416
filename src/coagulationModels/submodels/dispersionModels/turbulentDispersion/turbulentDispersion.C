/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "turbulentDispersion.H"
#include "coagulationParticle.H"
#include "caseChecks.H"
#include "volFields.H"
#include "volPointInterpolation.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace coagulation
{
namespace dispersionModels
{
    defineTypeNameAndDebug(turbulentDispersion, 0);
    addToRunTimeSelectionTable(dispersionModel, turbulentDispersion, dictionary);
}
}
}

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coagulation::dispersionModels::turbulentDispersion::turbulentDispersion
(
    const dictionary& dict,
    const fvMesh& mesh
)
:
    dispersionModel(mesh),
    nut_
    (
        (
            caseChecks::keywords
            (
                dict, {"type", "Sct", "nut", "drift", "Brownian"}
            ),
            flowFields::of(mesh).cellField
            (
                dict,
                "dispersion model " + typeName,
                "nut",
                dict.getOrDefault<word>("nut", "nut"),
                dimViscosity,
                false
            )
        )
    ),
    Sct_(caseChecks::positive(dict, "Sct")),
    nutVersion_(-1),
    cellD_(),
    pointD_(),
    faceTets_(),
    tets_(),
    drift_(dict.getOrDefault<bool>("drift", true)),
    brownian_(dict.found("Brownian")),
    gas_()
{
    if (brownian_)
    {
        gas_ = readBrownianGas(dict.subDict("Brownian"));
    }
    makeD();

    Info<< "    turbulent diffusivity nut/Sct in [" << gMin(cellD_) << ", "
        << gMax(cellD_) << "] m^2/s, drift " << (drift_ ? "on" : "off")
        << (brownian_ ? ", plus Brownian" : "") << endl;
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::coagulation::dispersionModels::turbulentDispersion::makeD()
{
    const volScalarField D("Dt", nut_()/Sct_);
    cellD_ = D.primitiveField();
    pointD_ =
        volPointInterpolation::New(mesh_).interpolate(D)().primitiveField();
    nutVersion_ = nut_.version();

    // The values of every tet, once per nut instead of once per particle
    // and step: the tets of face f are tetPt = 1 .. f.size() - 2 of its
    // owner and of its neighbour; a cell's tets together, so that the
    // particles of a cell, moved one after the other, find them in the cache
    const faceList& faces = mesh_.faces();
    const cellList& cells = mesh_.cells();
    const labelList& owner = mesh_.faceOwner();
    faceTets_.setSize(2*faces.size());
    faceTets_ = -1;
    tets_.clear();
    forAll(cells, celli)
    {
        for (const label facei : cells[celli])
        {
            faceTets_[2*facei + (owner[facei] == celli ? 0 : 1)] =
                label(tets_.size());
            for (label tetPt = 1; tetPt < faces[facei].size() - 1; ++tetPt)
            {
                tets_.push_back(values(tetIndices(celli, facei, tetPt)));
            }
        }
    }
}


Foam::coagulation::dispersionModels::turbulentDispersion::tetData
Foam::coagulation::dispersionModels::turbulentDispersion::values
(
    const tetIndices& tetIs
) const
{
    // D linear in the tet (interpolationCellPoint): the centre's value and
    // the face triangle's points' values; its gradient from
    // (x_k - x_0) . g = v_k - v_0, k = 1, 2, 3
    const triFace tri = tetIs.faceTriIs(mesh_);
    const scalar v0 = cellD_[tetIs.cell()];
    tetData t;
    t.pointD = vector(pointD_[tri[0]], pointD_[tri[1]], pointD_[tri[2]]);
    const tetPointRef tp = tetIs.tet(mesh_);
    const tensor edges(tp.b() - tp.a(), tp.c() - tp.a(), tp.d() - tp.a());
    t.gradient =
        inv(edges)
      & vector(t.pointD.x() - v0, t.pointD.y() - v0, t.pointD.z() - v0);
    return t;
}


const Foam::coagulation::dispersionModels::turbulentDispersion::tetData&
Foam::coagulation::dispersionModels::turbulentDispersion::tet
(
    const tetIndices& tetIs
) const
{
    const label facei = tetIs.face();
    return tets_
    [
        faceTets_[2*facei + (mesh_.faceOwner()[facei] == tetIs.cell() ? 0 : 1)]
      + tetIs.tetPt() - 1
    ];
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::coagulation::dispersionModels::turbulentDispersion::correct()
{
    if (nut_.version() != nutVersion_)
    {
        makeD();
        return true;
    }
    return false;
}


Foam::scalar
Foam::coagulation::dispersionModels::turbulentDispersion::diffusivity
(
    const coagulationParticle& p,
    vector& drift
) const
{
    // D linear in the particle's tet: the centre's value and the three
    // face points' values, weighted by the barycentric coordinates
    // (interpolationCellPoint); its gradient constant there
    const tetIndices tetIs = p.currentTetIndices();
    const tetData& t = tet(tetIs);
    const vector& v = t.pointD;
    const barycentric& b = p.coordinates();
    scalar D = max
    (
        b[0]*cellD_[tetIs.cell()] + b[1]*v.x() + b[2]*v.y() + b[3]*v.z(),
        scalar(0)
    );
    drift = drift_ ? t.gradient : Zero;

    if (brownian_)
    {
        D += coag::brownianDiffusivity(p.mass(), gas_);
    }

    return D;
}


// ************************************************************************* //
