/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "patchInflow.H"
#include "meshTools.H"
#include "particleMaterial.H"
#include "coagulationCloud.H"
#include "caseChecks.H"
#include "surfaceFields.H"
#include "addToRunTimeSelectionTable.H"

#include <random>

namespace Foam
{
namespace coagulation
{
namespace injectionModels
{
    defineTypeNameAndDebug(patchInflow, 0);
    addToRunTimeSelectionTable(injectionModel, patchInflow, dictionary);
}
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coagulation::injectionModels::patchInflow::patchInflow
(
    const dictionary& dict,
    coagulationCloud& cloud
)
:
    injectionModel(cloud),
    dict_(dict),
    patches_(),
    density_(0),
    mass_(1),
    rng_(0)
{
    caseChecks::keywords
    (
        dict, {"type", "patches", "density", "mass", "diameter"}
    );
    const wordList patchNames(dict.get<wordList>("patches"));
    density_ = caseChecks::nonNegative(dict, "density");
    mass_ = readParticleMass(dict, "inflow");

    if (density_ > 0 && patchNames.empty())
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'patches' in " << dict.name() << " lists no patch, but"
            << " 'density' = " << density_ << " asks for inflow." << nl
            << "    Name the inlet patches, or set density 0 for no inflow"
            << nl << exit(FatalIOError);
    }

    const polyBoundaryMesh& boundary = cloud.pMesh().boundaryMesh();
    patches_.setSize(patchNames.size());
    forAll(patchNames, i)
    {
        patches_[i] = boundary.findPatchID(patchNames[i]);
        if (patches_[i] < 0)
        {
            FatalIOErrorInFunction(dict)
                << "Inflow patch '" << patchNames[i] << "' (entry 'patches' in "
                << dict.name() << ") is not in the mesh; its patches are "
                << boundary.names() << nl
                << exit(FatalIOError);
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::coagulation::injectionModels::patchInflow::checkFlow
(
    const volVectorField& U
) const
{
    if (density_ <= 0)
    {
        return;
    }

    const fvMesh& mesh = U.mesh();
    for (const label patchi : patches_)
    {
        const scalar inward = -gSum
        (
            min
            (
                U.boundaryField()[patchi] & mesh.Sf().boundaryField()[patchi],
                scalar(0)
            )
        );
        if (!(inward > 0))
        {
            FatalIOErrorInFunction(dict_)
                << "Inflow patch '" << mesh.boundaryMesh()[patchi].name()
                << "' (entry 'patches' in " << dict_.name() << ") has no"
                << " inward flow: U on it points out of the domain or"
                << " along it, so nothing would enter." << nl
                << "    Name the inlet patch, or check U there" << nl
                << exit(FatalIOError);
        }
    }
}


void Foam::coagulation::injectionModels::patchInflow::inject
(
    const volVectorField& U,
    const scalar dt,
    const streamSeeds::purpose stream,
    particleBalance& entered
)
{
    if (density_ <= 0)
    {
        return;
    }

    const fvMesh& mesh = U.mesh();
    const scalar W = cloud_.scaling().particleWeight();
    const pointField& points = mesh.points();
    const volVectorField& C = mesh.C();

    // The share of the way from the face to the cell centre at which a new
    // particle is placed before it is tracked: inside the cell, off its face
    constexpr scalar inset = 1e-6;

    for (const label patchi : patches_)
    {
        const polyPatch& pp = mesh.boundaryMesh()[patchi];
        const vectorField& Sf = mesh.Sf().boundaryField()[patchi];
        const vectorField& Ub = U.boundaryField()[patchi];

        forAll(pp, facei)
        {
            const scalar inwardFlux = -(Ub[facei] & Sf[facei]);
            if (inwardFlux <= 0)
            {
                continue;
            }

            // Computational particles entering over dt: Poisson with mean
            // c_in * flux * dt / W
            rng_.engine().seed
            (
                cloud_.seeds()(pp.start() + facei, stream)
            );
            std::poisson_distribution<label> count(density_*inwardFlux*dt/W);
            const label nNew = count(rng_.engine());

            const face& f = pp[facei];
            const point fc = f.centre(points);
            const label owner = pp.faceCells()[facei];
            const vector Uin = U[owner];

            for (label i = 0; i < nNew; ++i)
            {
                // Uniform point on the face (fan of triangles about its
                // centre, chosen by area), then the distance travelled since
                // crossing it, uniform over the step
                scalar target = rng_.uniform()*f.mag(points);
                label tri = f.size() - 1;
                forAll(f, k)
                {
                    target -= triPointRef
                    (
                        fc, points[f[k]], points[f.nextLabel(k)]
                    ).mag();
                    if (target <= 0)
                    {
                        tri = k;
                        break;
                    }
                }
                scalar a = rng_.uniform();
                scalar b = rng_.uniform();
                if (a + b > 1)
                {
                    a = 1 - a;
                    b = 1 - b;
                }
                const point onFace =
                    fc
                  + a*(points[f[tri]] - fc)
                  + b*(points[f.nextLabel(tri)] - fc);

                // Placed just inside the owner cell, then moved by OpenFOAM's
                // tracking over the distance travelled through the cells
                // it crosses (within the mesh's solved directions); a
                // boundary face on the way (a wall at the inlet's edge, where
                // the owner cell's velocity points out of the mesh) ends the
                // move there
                const point start = onFace + inset*(C[owner] - onFace);
                coagulationParticle* pPtr = new coagulationParticle
                (
                    mesh, start, owner, mass_, W
                );
                vector travelled = rng_.uniform()*dt*Uin;
                meshTools::constrainDirection
                (
                    mesh, mesh.solutionD(), travelled
                );
                pPtr->track(travelled, 0);
                cloud_.addParticle(pPtr);
                cloud_.index().append(pPtr, pPtr->cell());

                entered.add(W, mass_);
            }
        }
    }
}


// ************************************************************************* //
