/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "momentFields.H"
#include "coagulationCloud.H"
#include "zeroGradientFvPatchFields.H"

namespace Foam
{
namespace coagulation
{
namespace cloudFunctions
{
    defineTypeNameAndDebug(momentFields, 0);
}
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coagulation::cloudFunctions::momentFields::momentFields
(
    coagulationCloud& cloud
)
:
    cloudFunction(cloud),
    moments_(4)
{
    const fvMesh& mesh = cloud.mesh();
    for (label k = 0; k < 4; ++k)
    {
        moments_.set
        (
            k,
            new volScalarField
            (
                IOobject
                (
                    "M" + Foam::name(k),
                    mesh.time().timeName(),
                    mesh,
                    IOobject::NO_READ,
                    IOobject::AUTO_WRITE
                ),
                mesh,
                dimensionedScalar(dimless/dimVolume, Zero),
                zeroGradientFvPatchScalarField::typeName
            )
        );
    }
    if (cloud.growth().active())
    {
        growthRate_.reset
        (
            new volScalarField
            (
                IOobject
                (
                    "growthRate",
                    mesh.time().timeName(),
                    mesh,
                    IOobject::NO_READ,
                    IOobject::AUTO_WRITE
                ),
                mesh,
                dimensionedScalar(dimless/dimVolume/dimTime, Zero),
                zeroGradientFvPatchScalarField::typeName
            )
        );
        grown_.setSize(mesh.nCells(), Zero);
    }
    update();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::coagulation::cloudFunctions::momentFields::postCellStep()
{
    if (growthRate_)
    {
        const cellStepper& step = cloud_.stepper();
        forAll(grown_, celli)
        {
            grown_[celli] += step.grownMass(celli);
        }
    }
}


void Foam::coagulation::cloudFunctions::momentFields::postStep()
{
    update();
    if (growthRate_)
    {
        growthRate_->primitiveFieldRef() =
            grown_/(cloud_.mesh().V()*cloud_.splitDeltaT());
        growthRate_->correctBoundaryConditions();
        grown_ = Zero;
    }
}


void Foam::coagulation::cloudFunctions::momentFields::update()
{
    // The sort is kept for the next cell step: nothing changes the cloud in
    // between
    cellParticleIndex& index = cloud_.index();
    const fvMesh& mesh = cloud_.mesh();
    const label nCells = mesh.nCells();
    index.sort(cloud_, nCells);

    scalarField& M0 = moments_[0].primitiveFieldRef();
    scalarField& M1 = moments_[1].primitiveFieldRef();
    scalarField& M2 = moments_[2].primitiveFieldRef();
    scalarField& M3 = moments_[3].primitiveFieldRef();
    const scalarField& V = mesh.V();
    const labelList& cellStart = index.cellStart();
    const DynamicList<coagulationParticle*>& particles = index.cellParticles();

    // Each cell sums its particles in list order, whatever the thread count
    #pragma omp parallel for schedule(static) num_threads(cloud_.nThreads())
    for (label celli = 0; celli < nCells; ++celli)
    {
        scalar s0 = 0, s1 = 0, s2 = 0, s3 = 0;
        for (label i = cellStart[celli]; i < cellStart[celli + 1]; ++i)
        {
            const coagulationParticle& p = *particles[i];
            const scalar w = p.weight();
            const scalar m = p.mass();
            s0 += w;
            s1 += w*m;
            s2 += w*m*m;
            s3 += w*m*m*m;
        }
        M0[celli] = s0/V[celli];
        M1[celli] = s1/V[celli];
        M2[celli] = s2/V[celli];
        M3[celli] = s3/V[celli];
    }

    for (volScalarField& Mk : moments_)
    {
        Mk.correctBoundaryConditions();
    }
}


// ************************************************************************* //
