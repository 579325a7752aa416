/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "massBalance.H"
#include "IFstream.H"
#include "OFstream.H"
#include "OStringStream.H"
#include "coagulationCloud.H"
#include "OSspecific.H"

#include "coagulation/statistics/CompensatedSum.hpp"

namespace Foam
{
namespace coagulation
{
namespace cloudFunctions
{
    defineTypeNameAndDebug(massBalance, 0);

    //- The rows of sources.csv
    static const wordList sourceNames
    ({
        "inflow", "inception", "growth", "loss"
    });
}
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coagulation::cloudFunctions::massBalance::massBalance
(
    coagulationCloud& cloud
)
:
    cloudFunction(cloud),
    initial_(),
    inflow_(),
    outflow_(),
    patches_(cloud.pMesh().boundaryMesh().size()),
    previous_(cloud.pMesh().boundaryMesh().size()),
    previousSources_(sourceNames.size()),
    stalled_(0)
{
    initial_ = domain();

    // A restart: what the sources brought before it (written by the master)
    const fileName sources
    (
        cloud.mesh().time().timePath()/"uniform"/"coagulationSourceBalance"
    );
    if (Pstream::master() && isFile(sources))
    {
        IFstream is(sources);
        const dictionary dict(is);
        forAll(sourceNames, i)
        {
            if (dict.found(sourceNames[i]))
            {
                const dictionary& d = dict.subDict(sourceNames[i]);
                previousSources_[i].particles = d.get<label>("particles");
                previousSources_[i].number = d.get<scalar>("number");
                previousSources_[i].mass = d.get<scalar>("mass");
            }
        }
    }

    // A restart: what left per patch before it (written by the master)
    const fileName file
    (
        cloud.mesh().time().timePath()/"uniform"/"coagulationPatchBalance"
    );
    if (Pstream::master() && isFile(file))
    {
        IFstream is(file);
        const dictionary dict(is);
        const polyBoundaryMesh& boundary = cloud.pMesh().boundaryMesh();
        forAll(boundary, patchi)
        {
            const word& name = boundary[patchi].name();
            if (dict.found(name))
            {
                const dictionary& d = dict.subDict(name);
                previous_[patchi].particles = d.get<label>("particles");
                previous_[patchi].number = d.get<scalar>("number");
                previous_[patchi].mass = d.get<scalar>("mass");
            }
        }
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::coagulation::particleBalance
Foam::coagulation::cloudFunctions::massBalance::incepted() const
{
    const coag::StepStatistics& events = cloud_.events();
    const scalar W = cloud_.scaling().particleWeight();
    particleBalance b;
    b.particles = label(events.inceptions);
    b.number = events.inceptions*W;
    b.mass = events.inceptions*W*cloud_.inception().core().type.mass;
    return b;
}


Foam::coagulation::particleBalance
Foam::coagulation::cloudFunctions::massBalance::domain() const
{
    // Compensated sums: a population of one size (a monodisperse start)
    // sums equal terms, whose plain sum drifts by up to half a rounding per
    // particle
    coag::CompensatedSum number, mass;
    particleBalance b;
    for (const coagulationParticle& p : cloud_)
    {
        number.add(p.weight());
        mass.add(p.weight()*p.mass());
        ++b.particles;
    }
    b.number = number.value();
    b.mass = mass.value();
    reduce(b.particles, sumOp<label>());
    reduce(b.number, sumOp<scalar>());
    reduce(b.mass, sumOp<scalar>());
    return b;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::coagulation::cloudFunctions::massBalance::postMove
(
    const transportModel::outflow& out
)
{
    forAll(out.particles, patchi)
    {
        outflow_.particles += out.particles[patchi];
        outflow_.number += out.number[patchi];
        outflow_.mass += out.mass[patchi];
        patches_[patchi].particles += out.particles[patchi];
        patches_[patchi].number += out.number[patchi];
        patches_[patchi].mass += out.mass[patchi];
    }
    stalled_ += out.stalled;
}


Foam::scalar Foam::coagulation::cloudFunctions::massBalance::massError() const
{
    const scalar inflow = returnReduce(inflow_.mass, sumOp<scalar>());
    const scalar incepted = returnReduce(this->incepted().mass, sumOp<scalar>());
    const scalar outflow = returnReduce(outflow_.mass, sumOp<scalar>());
    const scalar control =
        returnReduce(cloud_.events().controlMass, sumOp<scalar>());
    const scalar grown =
        returnReduce(cloud_.events().grownMass, sumOp<scalar>());
    const scalar lost =
        returnReduce(cloud_.events().lostMass, sumOp<scalar>());

    const particleBalance now = domain();
    const scalar expected =
        initial_.mass + inflow + incepted + grown - outflow - lost + control;
    const scalar scale =
        max
        (
            max(now.mass, initial_.mass + inflow + incepted + max(grown, 0)),
            VSMALL
        );

    return (now.mass - expected)/scale;
}


Foam::label
Foam::coagulation::cloudFunctions::massBalance::particleError() const
{
    label change =
        inflow_.particles + incepted().particles - outflow_.particles
      - cloud_.removedInCells();
    reduce(change, sumOp<label>());

    return domain().particles - initial_.particles - change;
}


void Foam::coagulation::cloudFunctions::massBalance::check() const
{
    const scalar mError = massError();
    const label pError = particleError();
    if (!(mag(mError) <= 1e-9) || pError != 0)
    {
        FatalErrorInFunction
            << "The balances do not close at time "
            << cloud_.mesh().time().timeName() << ": relative mass error "
            << mError << ", particle count error " << pError << nl
            << "    Particles or mass were lost: please report this case"
            << nl << exit(FatalError);
    }
}


void Foam::coagulation::cloudFunctions::massBalance::writePatches() const
{
    // Per patch since the case's first start: the log, one row per patch
    // and write time in postProcessing/coagulationBalance/patches.csv, and
    // the totals in <time>/uniform for a restart from this time
    const polyBoundaryMesh& boundary = cloud_.pMesh().boundaryMesh();
    const boolList& stick = cloud_.patchInteraction().stick();
    const Time& time = cloud_.mesh().time();
    autoPtr<OFstream> csv;
    dictionary totals;
    if (Pstream::master())
    {
        const fileName dir(time.globalPath()/"postProcessing"/"coagulationBalance");
        mkDir(dir);
        const fileName file(dir/"patches.csv");
        const bool fresh = !isFile(file);
        csv.reset(new OFstream(file, IOstream::ASCII, IOstream::currentVersion,
                               IOstream::UNCOMPRESSED, true));
        if (fresh)
        {
            csv() << "time,patch,kind,particles,number,mass" << nl;
        }
    }
    // The patches every processor has, in the same order: the processor
    // patches come after them and differ in number between processors, so
    // a reduction per processor patch would pair one processor's reductions
    // with another's next collective (three or more ranks: the middle ones
    // have two processor patches)
    for (label patchi = 0; patchi < boundary.nNonProcessor(); ++patchi)
    {
        particleBalance b(patches_[patchi]);
        reduce(b.particles, sumOp<label>());
        reduce(b.number, sumOp<scalar>());
        reduce(b.mass, sumOp<scalar>());
        b.particles += previous_[patchi].particles;
        b.number += previous_[patchi].number;
        b.mass += previous_[patchi].mass;
        if (b.particles == 0)
        {
            continue;
        }
        if (Pstream::master())
        {
            dictionary d;
            d.add("particles", b.particles);
            d.add("number", b.number);
            d.add("mass", b.mass);
            totals.add(boundary[patchi].name(), d);
        }
        const word kind(stick[patchi] ? "deposited" : "outflow");
        Info<< "    " << kind << " " << boundary[patchi].name() << ": "
            << b.particles << " particles, number " << b.number
            << ", mass " << b.mass << nl;
        if (csv)
        {
            csv() << time.timeName() << ',' << boundary[patchi].name() << ','
                << kind << ',' << b.particles << ',' << b.number << ','
                << b.mass << nl;
        }
    }
    Info<< endl;

    if (Pstream::master())
    {
        const fileName dir(time.timePath()/"uniform");
        mkDir(dir);
        OFstream os(dir/"coagulationPatchBalance");
        os.precision(17);
        totals.write(os, false);
    }
}


void Foam::coagulation::cloudFunctions::massBalance::writeSources() const
{
    const coag::StepStatistics& events = cloud_.events();
    List<particleBalance> now(sourceNames.size());
    now[0] = inflow_;
    now[1] = incepted();
    now[2].mass = events.grownMass;
    now[3].particles = label(events.lostParticles);
    now[3].number = events.lostNumber;
    now[3].mass = events.lostMass;

    const Time& time = cloud_.mesh().time();
    dictionary totals;
    OStringStream rows;
    forAll(now, i)
    {
        particleBalance b(now[i]);
        reduce(b.particles, sumOp<label>());
        reduce(b.number, sumOp<scalar>());
        reduce(b.mass, sumOp<scalar>());
        b.particles += previousSources_[i].particles;
        b.number += previousSources_[i].number;
        b.mass += previousSources_[i].mass;
        dictionary d;
        d.add("particles", b.particles);
        d.add("number", b.number);
        d.add("mass", b.mass);
        totals.add(sourceNames[i], d);
        rows.precision(17);
        rows<< time.timeName() << ',' << sourceNames[i] << ',' << b.particles
            << ',' << b.number << ',' << b.mass << nl;
    }
    if (!Pstream::master())
    {
        return;
    }
    const fileName dir(time.globalPath()/"postProcessing"/"coagulationBalance");
    mkDir(dir);
    const fileName file(dir/"sources.csv");
    const bool fresh = !isFile(file);
    OFstream csv
    (
        file, IOstream::ASCII, IOstream::currentVersion,
        IOstream::UNCOMPRESSED, true
    );
    if (fresh)
    {
        csv << "time,source,particles,number,mass" << nl;
    }
    csv << rows.str().c_str();

    const fileName uniform(time.timePath()/"uniform");
    mkDir(uniform);
    OFstream os(uniform/"coagulationSourceBalance");
    os.precision(17);
    totals.write(os, false);
}


void Foam::coagulation::cloudFunctions::massBalance::write()
{
    particleBalance inflow(inflow_), incepted(this->incepted());
    particleBalance outflow(outflow_);
    reduce(inflow.mass, sumOp<scalar>());
    reduce(incepted.mass, sumOp<scalar>());
    reduce(outflow.mass, sumOp<scalar>());
    reduce(inflow.particles, sumOp<label>());
    reduce(incepted.particles, sumOp<label>());
    reduce(outflow.particles, sumOp<label>());

    const coag::StepStatistics& events = cloud_.events();
    const scalar coagulations =
        returnReduce(scalar(events.coagulations), sumOp<scalar>());
    const scalar fictitious =
        returnReduce(scalar(events.fictitious), sumOp<scalar>());
    const scalar control = returnReduce(events.controlMass, sumOp<scalar>());
    const scalar grown = returnReduce(events.grownMass, sumOp<scalar>());
    const scalar lost = returnReduce(events.lostMass, sumOp<scalar>());
    const scalar lostParticles =
        returnReduce(scalar(events.lostParticles), sumOp<scalar>());
    const label stalled = returnReduce(stalled_, sumOp<label>());

    const particleBalance now = domain();

    Info<< "Coagulation cloud:" << nl
        << "    particles in domain        = " << now.particles << nl
        << "    physical particles         = " << now.number << nl
        << "    coagulation events         = " << coagulations
        << " (fictitious " << fictitious << ", "
        << (coagulations > 0 ? fictitious/coagulations : scalar(0))
        << " per real one)" << nl
        << "    particles in/incepted/out  = " << inflow.particles << " / "
        << incepted.particles << " / " << outflow.particles << nl;
    if (cloud_.growth().active())
    {
        // Growth is active on every processor or on none
        Info<< "    particles gone by shrinking = " << lostParticles
            << " (number " << returnReduce(events.lostNumber, sumOp<scalar>())
            << ")" << nl;
    }
    // The growth terms where growth models act
    const bool grows = cloud_.growth().active();
    Info<< "    mass initial + inflow + inception"
        << (grows ? " + growth - outflow - loss" : " - outflow")
        << " + control = " << initial_.mass << " + " << inflow.mass << " + "
        << incepted.mass;
    if (grows)
    {
        Info<< " + " << grown << " - " << outflow.mass << " - " << lost;
    }
    else
    {
        Info<< " - " << outflow.mass;
    }
    Info<< " + " << control << nl
        << "    mass in domain             = " << now.mass << nl
        << "    mass balance error (rel.)  = " << massError() << nl
        << "    particle balance error     = " << particleError() << nl
        << "    particles held at a face   = " << stalled << endl;

    writePatches();
    writeSources();
    check();
}


// ************************************************************************* //
