/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "coagulationParticle.H"
#include "coagulationCloud.H"
#include "meshTools.H"
#include "emptyPolyPatch.H"
#include "symmetryPolyPatch.H"
#include "symmetryPlanePolyPatch.H"
#include "wallPolyPatch.H"
#include "processorPolyPatch.H"
#include "cyclicPolyPatch.H"
#include "wedgePolyPatch.H"
#include "cyclicAMIPolyPatch.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace coagulation
{
    defineTypeNameAndDebug(coagulationParticle, 0);
}

    // The cloud's type name as before the namespace: the class of its
    // particle files ('Cloud<coagulationParticle>')
    defineTemplateTypeNameAndDebugWithName
    (
        Cloud<coagulation::coagulationParticle>,
        "Cloud<coagulationParticle>",
        0
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::coagulation::coagulationParticle::move
(
    coagulationCloud& cloud,
    trackingData& td,
    const scalar trackTime
)
{
    td.switchProcessor = false;
    td.keepParticle = true;
    td.resetReflection();

    const Vector<label>& solutionD = mesh().solutionD();
    label stalled = 0;

    while (td.keepParticle && !td.switchProcessor && stepFraction() < 1)
    {
        // The step's displacement: the advection with the carrier velocity
        // plus the random walk (zero without one), both mirrored in the
        // faces the particle rebounded from. With the velocity constant
        // within a cell, one straight segment to the next face (or the end
        // of the step); with the velocity varying within the cell, a segment
        // of at most maxCo of the cell's length scale with the velocity at
        // its start. Within the solved directions of a 1-D/2-D mesh
        const scalar before = stepFraction();
        scalar f = 1 - before;
        vector displacement;
        if (td.interpolated())
        {
            const vector s = trackTime*td.velocity(*this);
            const scalar l = td.cellLength(cell());
            f = min(f, td.maxCo()*l/max(SMALL*l, mag(s)));
            displacement = f*(s + dispersal_);
        }
        else
        {
            displacement =
                f*trackTime*td.velocity(cell()) + f*dispersal_;
        }
        meshTools::constrainDirection(mesh(), solutionD, displacement);

        trackToAndHitFace(displacement, f, cloud, td);

        // A particle wedged between faces (a corner hit again and again)
        // must not stop the run: hold it for the rest of the step. Progress
        // is more than a round-off share of the segment: a particle pushed
        // into a face again and again may creep by round-off and would
        // otherwise never count as stalled
        if (stepFraction() - before > 1e-9*f)
        {
            stalled = 0;
        }
        else if (++stalled >= maxStalledHits)
        {
            td.bookStalled();
            stepFraction() = 1;
        }
    }

    // The walk is made (or the particle is gone); a particle handed to
    // another processor keeps the rest of it
    if (!td.switchProcessor)
    {
        dispersal_ = Zero;
    }

    return td.keepParticle;
}


bool Foam::coagulation::coagulationParticle::hitPatch
(
    coagulationCloud&,
    trackingData& td
)
{
    const polyPatch& pp = mesh().boundaryMesh()[patch()];

    // Generic patches (inlets, outlets, openings) are where particles leave
    if (pp.type() == polyPatch::typeName)
    {
        td.bookOutflow(patch(), *this);
        td.keepParticle = false;
        return true;
    }

    // A wall set to stick (patchInteractionModel): the particle deposits,
    // booked on that wall like an outflow
    if (isA<wallPolyPatch>(pp) && td.sticks(patch()))
    {
        td.bookOutflow(patch(), *this);
        td.keepParticle = false;
        return true;
    }

    // Rebound: mirror the rest of the move in the face (an empty patch is
    // reached only by round-off, the displacement being constrained)
    if
    (
        isA<wallPolyPatch>(pp)
     || isA<symmetryPlanePolyPatch>(pp)
     || isA<symmetryPolyPatch>(pp)
     || isA<emptyPolyPatch>(pp)
    )
    {
        reflect(td, normal());
        return true;
    }

    // OpenFOAM's own handling: processor, cyclic, wedge
    if
    (
        isA<processorPolyPatch>(pp)
     || isA<cyclicPolyPatch>(pp)
     || isA<cyclicAMIPolyPatch>(pp)
     || isA<wedgePolyPatch>(pp)
    )
    {
        return false;
    }

    // Anything else (mapped, cyclicACMI, ...): stop the particle here and
    // let the cloud stop the run with the patch's name
    td.bookUnhandled(patch());
    td.keepParticle = false;
    return true;
}


void Foam::coagulation::coagulationParticle::hitProcessorPatch
(
    coagulationCloud&,
    trackingData& td
)
{
    td.switchProcessor = true;
}


Foam::tensor Foam::coagulation::coagulationParticle::crossingRotation
(
    const coupledPolyPatch& receive
) const
{
    // The receiving patch's rotation, as OpenFOAM's crossing applies it to
    // the position: uniform, or the one of the face the particle is on
    if (receive.parallel())
    {
        return I;
    }
    const tensorField& T = receive.forwardT();
    const label facei = face() - receive.start();
    if (T.size() == 1)
    {
        return T[0];
    }
    return facei >= 0 && facei < receive.size() ? T[facei] : I;
}


void Foam::coagulation::coagulationParticle::hitCyclicPatch
(
    coagulationCloud& cloud,
    trackingData& td
)
{
    const cyclicPolyPatch& send =
        refCast<const cyclicPolyPatch>(mesh().boundaryMesh()[patch()]);
    particle::hitCyclicPatch(cloud, td);
    td.rotate(crossingRotation(send.neighbPatch()));
}


void Foam::coagulation::coagulationParticle::hitCyclicAMIPatch
(
    coagulationCloud& cloud,
    trackingData& td,
    const vector& direction
)
{
    const cyclicAMIPolyPatch& send =
        refCast<const cyclicAMIPolyPatch>(mesh().boundaryMesh()[patch()]);
    particle::hitCyclicAMIPatch(cloud, td, direction);
    if (td.keepParticle)
    {
        td.rotate(crossingRotation(send.neighbPatch()));
    }
}


void Foam::coagulation::coagulationParticle::transformProperties
(
    const tensor& T
)
{
    particle::transformProperties(T);
    dispersal_ = transform(T, dispersal_);
}


void Foam::coagulation::coagulationParticle::transformProperties
(
    const vector& separation
)
{
    particle::transformProperties(separation);
}


// ************************************************************************* //
