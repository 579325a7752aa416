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
    tets_(meshTets::New(mesh)),
    gradient_(),
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

    // The gradient in every tet, once per nut instead of once per particle
    // and step
    if (drift_)
    {
        gradient_.setSize(tets_.size());
        tets_.forAllTets
        (
            [this](const label i, const tetIndices& tetIs)
            {
                gradient_[i] = gradient(tetIs);
            }
        );
    }
}


Foam::vector
Foam::coagulation::dispersionModels::turbulentDispersion::gradient
(
    const tetIndices& tetIs
) const
{
    // D linear in the tet (interpolationCellPoint): the centre's value and
    // the face triangle's points' values; its gradient from
    // (x_k - x_0) . g = v_k - v_0, k = 1, 2, 3
    const triFace& tri = tets_.points(tets_.index(tetIs));
    const scalar v0 = cellD_[tetIs.cell()];
    const tetPointRef t = tetIs.tet(mesh_);
    const tensor edges(t.b() - t.a(), t.c() - t.a(), t.d() - t.a());
    // A tet of no volume (a face without a valid base point) holds no
    // particle: no gradient
    if (!(mag(det(edges)) > VSMALL))
    {
        return Zero;
    }
    return
        inv(edges)
      & vector
        (
            pointD_[tri[0]] - v0, pointD_[tri[1]] - v0, pointD_[tri[2]] - v0
        );
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
    // D linear in the particle's tet (the cell's value at the centre, the
    // points' values at the face points), its gradient constant there
    const tetIndices tetIs = p.currentTetIndices();
    scalar D = max
    (
        tets_.interpolate(cellD_, pointD_, p.coordinates(), tetIs),
        scalar(0)
    );
    drift = drift_ ? gradient_[tets_.index(tetIs)] : Zero;

    if (brownian_)
    {
        D += coag::brownianDiffusivity(p.mass(), gas_);
    }

    return D;
}


// ************************************************************************* //
