/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
\*---------------------------------------------------------------------------*/

#include "coagulationParticle.H"
#include "coagulationCloud.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(coagulationParticle, 0);
    defineTemplateTypeNameAndDebug(Cloud<coagulationParticle>, 0);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::coagulationParticle::move
(
    coagulationCloud& cloud,
    trackingData& td,
    const scalar trackTime
)
{
    td.switchProcessor = false;
    td.keepParticle = true;
    td.resetWall();

    while (td.keepParticle && !td.switchProcessor && stepFraction() < 1)
    {
        // The carrier velocity is constant within a cell: track to the
        // next face (or the end of the step) in one straight segment
        const scalar f = 1 - stepFraction();
        trackToAndHitFace(f*trackTime*td.velocity(cell()), f, cloud, td);
    }

    return td.keepParticle;
}


bool Foam::coagulationParticle::hitPatch
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

    return false;
}


void Foam::coagulationParticle::hitProcessorPatch
(
    coagulationCloud&,
    trackingData& td
)
{
    td.switchProcessor = true;
}


void Foam::coagulationParticle::hitWallPatch
(
    coagulationCloud&,
    trackingData& td
)
{
    td.hitWall(normal());
}


// ************************************************************************* //
