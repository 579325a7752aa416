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
    // points' values, weighted by the barycentric coordinates
    // (interpolationCellPoint)
    const tetIndices tetIs = p.currentTetIndices();
    const triFace tri = tetIs.faceTriIs(mesh_);
    const barycentric& b = p.coordinates();
    const scalar v0 = cellD_[tetIs.cell()];
    const scalar v1 = pointD_[tri[0]];
    const scalar v2 = pointD_[tri[1]];
    const scalar v3 = pointD_[tri[2]];
    scalar D = max(b[0]*v0 + b[1]*v1 + b[2]*v2 + b[3]*v3, scalar(0));

    // Its gradient in the tet: (x_k - x_0) . g = v_k - v_0, k = 1, 2, 3
    drift = Zero;
    if (drift_)
    {
        const tetPointRef t = tetIs.tet(mesh_);
        const tensor edges(t.b() - t.a(), t.c() - t.a(), t.d() - t.a());
        drift = inv(edges) & vector(v1 - v0, v2 - v0, v3 - v0);
    }

    if (brownian_)
    {
        D += coag::brownianDiffusivity(p.mass(), gas_);
    }

    return D;
}


// ************************************************************************* //
