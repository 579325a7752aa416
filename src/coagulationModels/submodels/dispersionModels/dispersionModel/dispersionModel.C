/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "dispersionModel.H"
#include "particleMaterial.H"
#include "coagulationParticle.H"
#include "caseChecks.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace coagulation
{
    defineTypeNameAndDebug(dispersionModel, 0);
    defineRunTimeSelectionTable(dispersionModel, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coagulation::dispersionModel::dispersionModel(const fvMesh& mesh)
:
    mesh_(mesh),
    cellStickStart_(mesh.nCells() + 1, Zero),
    stickFaces_()
{}


// * * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * //

Foam::autoPtr<Foam::coagulation::dispersionModel>
Foam::coagulation::dispersionModel::New
(
    const dictionary& dict,
    const fvMesh& mesh
)
{
    const word modelType(dict.getOrDefault<word>("type", "none"));

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "dispersionModel",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    Info<< "Selecting dispersion model " << modelType << endl;

    return autoPtr<dispersionModel>(cstrIter()(dict, mesh));
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::coagulation::dispersionModel::setStickWalls(const boolList& stick)
{
    const polyBoundaryMesh& patches = mesh_.boundaryMesh();
    List<DynamicList<label>> near(mesh_.nCells());
    forAll(patches, patchi)
    {
        if (!stick[patchi])
        {
            continue;
        }
        const polyPatch& pp = patches[patchi];
        forAll(pp, i)
        {
            const label facei = pp.start() + i;
            for (const label pointi : mesh_.faces()[facei])
            {
                for (const label celli : mesh_.pointCells()[pointi])
                {
                    if (!near[celli].found(facei))
                    {
                        near[celli].append(facei);
                    }
                }
            }
        }
    }
    DynamicList<stickFace> faces;
    forAll(near, celli)
    {
        cellStickStart_[celli] = faces.size();
        for (const label facei : near[celli])
        {
            const vector n = normalised(mesh_.faceAreas()[facei]);
            const stickFace sf
            {
                facei,
                patches.whichPatch(facei),
                n,
                n & mesh_.faceCentres()[facei]
            };
            faces.append(sf);
        }
    }
    cellStickStart_[mesh_.nCells()] = faces.size();
    stickFaces_.transfer(faces);
}


Foam::vector Foam::coagulation::dispersionModel::displacement
(
    const coagulationParticle& p,
    const scalar dt,
    const vector& advection,
    coag::CounterStream& s,
    label& wallFace
) const
{
    wallFace = -1;
    vector drift(Zero);
    const scalar D = diffusivity(p, drift);

    // Ito-Euler step of dX = grad(D) dt + sqrt(2 D) dW (eq. 8 of the
    // coagulation-diffusion paper, with D varying in space)
    double xi[3];
    s.normal3(xi);
    const vector step =
        drift*dt + sqrt(2*D*dt)*vector(xi[0], xi[1], xi[2]);

    const label celli = p.cell();
    if (!nearStickWall(celli) || !(D > 0))
    {
        return step;
    }

    // Bridge correction at stick walls: per patch the face plane the bridge
    // most likely touched, P = exp(-a b/(D dt)) with both ends inside. The
    // end is that of the whole move, advection included: a Brownian bridge
    // does not depend on the drift
    const vector x0 = p.position();
    const vector move = step + advection;
    scalar survive = 1;
    scalar bestP = 0;
    label bestFace = -1;
    label lastPatch = -1;
    scalar patchP = 0;
    label patchFace = -1;
    auto closePatch = [&]()
    {
        survive *= 1 - patchP;
        if (patchP > bestP)
        {
            bestP = patchP;
            bestFace = patchFace;
        }
        patchP = 0;
    };
    for
    (
        label i = cellStickStart_[celli];
        i < cellStickStart_[celli + 1];
        ++i
    )
    {
        const stickFace& sf = stickFaces_[i];
        if (sf.patch != lastPatch)
        {
            closePatch();
            lastPatch = sf.patch;
        }
        const scalar a = sf.offset - (sf.normal & x0);
        const scalar b = a - (move & sf.normal);
        if (a > 0 && b > 0)
        {
            const scalar P = exp(-a*b/(D*dt));
            if (P > patchP)
            {
                patchP = P;
                patchFace = sf.face;
            }
        }
    }
    closePatch();

    if (bestP > 0 && s.uniform() > survive)
    {
        wallFace = bestFace;
        return Zero;
    }
    return step;
}


coag::BrownianGas Foam::coagulation::dispersionModel::readBrownianGas
(
    const dictionary& dict,
    const wordList& otherKeys
)
{
    caseChecks::movedEntries
    (
        dict,
        {
            {"rho", "the particles' material, 'particles { density ...; }',"},
            {"massUnit", "the particles' material, 'particles { massUnit ...; }',"}
        }
    );
    wordList valid{"T", "mu", "lambda", "A1", "A2", "A3"};
    valid.append(otherKeys);
    caseChecks::keywords(dict, valid);

    coag::BrownianGas gas;
    gas.temperature = caseChecks::positive(dict, "T");
    gas.viscosity = caseChecks::positive(dict, "mu");
    gas.meanFreePath = caseChecks::positive(dict, "lambda");
    // The particles' sizes from the material every model shares
    const coag::ParticleMaterial material =
        readParticleMaterial(dict.topDict(), "Brownian dispersion");

    gas.density = material.density;
    gas.massUnit = material.massUnit;
    if (dict.found("A1")) gas.slip.A1 = caseChecks::nonNegative(dict, "A1");
    if (dict.found("A2")) gas.slip.A2 = caseChecks::nonNegative(dict, "A2");
    if (dict.found("A3")) gas.slip.A3 = caseChecks::positive(dict, "A3");
    return gas;
}


// ************************************************************************* //
