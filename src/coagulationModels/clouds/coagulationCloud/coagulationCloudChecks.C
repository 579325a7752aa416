/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
-------------------------------------------------------------------------------
Description
    The cloud's checks of its input (start time, particles, flow) and of its
    size, and the completion marker of a written time.

\*---------------------------------------------------------------------------*/

#include "coagulationCloud.H"
#include "OFstream.H"
#include "caseChecks.H"
#include "restartPrecision.H"
#include "fvMesh.H"
#include "surfaceFields.H"
#include "OSspecific.H"
#include "IFstream.H"

#include <fstream>
#include <string>

#include <sys/resource.h>
#include <unistd.h>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- The name of the completion marker in <time>/uniform
const Foam::word completeMarker("coagulationCloudComplete");

//- The mesh's size and volume, as recorded with a written time
Foam::dictionary meshSignature(const Foam::fvMesh& mesh)
{
    // The whole mesh's, so that a time decomposed or reconstructed (a serial
    // start that goes on in parallel) matches it (not the face and point
    // counts: v1912's global ones count processor faces and points twice)
    const Foam::globalMeshData& global = mesh.globalData();
    Foam::dictionary dict;
    dict.add("nCells", global.nTotalCells());
    dict.add
    (
        "volume",
        Foam::returnReduce(Foam::sum(mesh.V().field()), Foam::sumOp<Foam::scalar>())
    );
    return dict;
}

//- The completion marker of the start time, or an empty dictionary
Foam::dictionary startMarker(const Foam::Time& runTime)
{
    const Foam::fileName file(runTime.timePath()/"uniform"/completeMarker);
    if (!Foam::isFile(file))
    {
        return Foam::dictionary();
    }
    Foam::IFstream is(file);
    return Foam::dictionary(is);
}


//- On a processor without an error of its own while another has one: wait
//  in a collective that the erring processor never joins; its FatalError
//  (MPI_Abort) ends this process too, so the error is said once
void awaitFatalErrorElsewhere()
{
    Foam::returnReduce(Foam::label(0), Foam::sumOp<Foam::label>());
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::coagulation::coagulationCloud::availableMemory
(
    std::string& limitedBy
)
{
    // The machine's memory not in use now
    scalar bytes = 1e18;
    limitedBy = "the memory available on this machine";
    {
        std::ifstream meminfo("/proc/meminfo");
        std::string key;
        double kB = 0;
        std::string unit;
        while (meminfo >> key >> kB >> unit)
        {
            if (key == "MemAvailable:")
            {
                bytes = 1024*kB;
                break;
            }
        }
    }

    // ... or what the process may still map under its limit (ulimit -v),
    // whichever is less
    struct rlimit limit;
    if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
    {
        double pages = 0;
        std::ifstream statm("/proc/self/statm");
        statm >> pages;
        const scalar left =
            max(scalar(limit.rlim_cur) - pages*sysconf(_SC_PAGESIZE), scalar(0));
        if (left < bytes)
        {
            bytes = left;
            limitedBy =
                "the process's address space limit (ulimit -v "
              + std::to_string(limit.rlim_cur/1024) + ")";
        }
    }
    return bytes;
}


Foam::scalar Foam::coagulation::coagulationCloud::bytesPerParticle()
{
    // The particle and its heap block; list, cell and sort arrays; the
    // core's copy (coag::Particle) and a share of the sum tree in the cell
    // step
    return sizeof(coagulationParticle) + 16 + 4*sizeof(void*) + 64;
}


void Foam::coagulation::coagulationCloud::checkMemory() const
{
    const scalar bytes = this->size()*bytesPerParticle();
    if (bytes > memoryLimit_)
    {
        FatalErrorInFunction
            << "The cloud holds " << this->size() << " particles (about "
            << bytes/(1 << 30) << " GiB), more than the "
            << memoryLimit_/(1 << 30) << " GiB it may take (three quarters"
            << " of " << memoryLimitedBy_.c_str() << " at the start)."
            << nl << "    Lower statisticalWeight/n or set numberControl/"
            << "maxParticlesPerCell in " << properties_.objectPath() << nl
            << exit(FatalError);
    }
}


void Foam::coagulation::coagulationCloud::checkStep()
{
    if (!flowChecked_)
    {
        checkVelocity(U_);
        flowChecked_ = true;
    }

    // A controlDict edited while the run runs (runTimeModifiable) can set
    // another deltaT: the samples' fixed interval, the split steps of the
    // random streams and the restart records all assume the step of the
    // start, so a change stops the run instead of stepping on silently
    const Time& runTime = mesh_.time();
    const scalar deltaT = runTime.deltaTValue();
    if (mag(deltaT - deltaT_) > 1e-9*deltaT_)
    {
        FatalIOErrorInFunction(runTime.controlDict())
            << "Entry 'deltaT' in " << runTime.controlDict().name()
            << " changed from " << Foam::name(deltaT_) << " to "
            << Foam::name(deltaT)
            << " at time " << runTime.timeName() << " while the run ran:"
            << " the particle population steps with the fixed deltaT of the"
            << " start (its samples, random streams and restarts are on that"
            << " step)." << nl << "    Set deltaT back to "
            << Foam::name(deltaT_) << ", or stop the run and restart it"
            << " from its latest written time with the new deltaT" << nl
            << exit(FatalIOError);
    }
}


Foam::word Foam::coagulation::coagulationCloud::readAlgorithmName
(
    const dictionary& dict
)
{
    // Checked before the entries that are given per algorithm
    // (statisticalWeight/V1 { SWA ...; DSA1 ...; }) are read by its name
    const word name(dict.get<word>("algorithm"));
    const auto* table = cellAlgorithm::componentsConstructorTablePtr_;
    if (!table || !table->found(name))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'algorithm' in " << dict.name() << " is '" << name
            << "'; valid algorithms are "
            << (table ? table->sortedToc() : wordList()) << nl
            << exit(FatalIOError);
    }
    return name;
}


void Foam::coagulation::coagulationCloud::checkExpectedSize
(
    const volVectorField& U
) const
{
    // SWA never removes a computational particle but by outflow or halving:
    // inception over one residence time (volume over outflow), or over the
    // run if that is shorter, is how many the cloud will hold
    if (algorithm_->equalWeights() || inception_->core().rate <= 0)
    {
        return;
    }

    const Time& runTime = mesh_.time();
    // Physical particles incepted per unit time (each cell at its own rate)
    scalar inceptionRate = 0;
    forAll(mesh_.V(), celli)
    {
        inceptionRate += inception_->cellRate(celli)*mesh_.V()[celli];
    }
    reduce(inceptionRate, sumOp<scalar>());

    scalar outflow = 0;
    forAll(mesh_.boundaryMesh(), patchi)
    {
        const polyPatch& pp = mesh_.boundaryMesh()[patchi];
        if (pp.type() == polyPatch::typeName)
        {
            outflow += sum
            (
                max
                (
                    U.boundaryField()[patchi] & mesh_.Sf().boundaryField()[patchi],
                    scalar(0)
                )
            );
        }
    }
    reduce(outflow, sumOp<scalar>());

    // stopAt nextWrite, writeNow or noWriteNow: OpenFOAM sets endTime to
    // GREAT, and the run's length is unknown
    const scalar volume = gSum(mesh_.V());
    const bool openEnded = runTime.endTime().value() > 0.5*GREAT;
    scalar residence = runTime.endTime().value() - runTime.value();
    if (outflow > 0)
    {
        residence = min(residence, volume/outflow);
    }
    else if (openEnded)
    {
        return;
    }

    scalar expected =
        inceptionRate*residence
       /scaling_.particleWeight();
    const label maxPerCell = label(algorithm_->control().maxParticles);
    if (maxPerCell > 0)
    {
        expected = min
        (
            expected,
            scalar(maxPerCell)*returnReduce(mesh_.nCells(), sumOp<label>())
        );
    }

    const scalar bytes = expected*bytesPerParticle();
    if (bytes > memoryLimit_)
    {
        FatalIOErrorInFunction(properties_)
            << "Entry 'statisticalWeight/n' = " << scaling_.n() << " in "
            << properties_.objectPath() << " asks for about " << expected
            << " particles (inception over " << residence << " s, the"
            << " residence time or the run), about " << bytes/(1 << 30)
            << " GiB: more than the " << memoryLimit_/(1 << 30)
            << " GiB the cloud may take (three quarters of "
            << memoryLimitedBy_.c_str() << ")." << nl
            << "    Lower n, or set numberControl { maxParticlesPerCell N; }"
            << nl << exit(FatalIOError);
    }
}


void Foam::coagulation::coagulationCloud::checkStartTime() const
{
    const Time& runTime = mesh_.time();

    // A time that OpenFOAM wrote (it has uniform/time) is complete once the
    // run has marked it so, after every field and function object wrote;
    // in a decomposed case on every processor
    const fileName uniform(runTime.timePath()/"uniform");
    labelList incomplete(Pstream::nProcs(), 0);
    incomplete[Pstream::myProcNo()] =
        isFile(uniform/"time") && !isFile(uniform/completeMarker);
    // In a flow solver (the coagulationCloud function object) a time the
    // solver wrote before the cloud ever ran (no time up to it holds the
    // cloud's particles or M0) is a fresh start
    if (liveFlow_ && incomplete[Pstream::myProcNo()])
    {
        bool cloudBefore = false;
        for (const instant& t : Time::findTimes(runTime.path()))
        {
            const fileName dir(runTime.path()/t.name());
            if
            (
                t.name() != "constant" && t.value() <= runTime.value()
             && (isDir(dir/cloud::prefix/name()) || isFile(dir/"M0"))
            )
            {
                cloudBefore = true;
                break;
            }
        }
        incomplete[Pstream::myProcNo()] = cloudBefore;
    }
    Pstream::gatherList(incomplete);
    Pstream::scatterList(incomplete);

    if (findIndex(incomplete, 1) != -1)
    {
        const word previous(latestCompleteTime());

        // One message, the master's, naming the processors
        if (!Pstream::master())
        {
            awaitFatalErrorElsewhere();
        }
        OStringStream where;
        if (Pstream::parRun())
        {
            where << " on";
            forAll(incomplete, proci)
            {
                if (incomplete[proci])
                {
                    where << " processor" << proci;
                }
            }
        }
        const fileName timeDir
        (
            Pstream::parRun()
          ? runTime.globalPath()/"processor*"/runTime.timeName()
          : runTime.timePath()
        );
        FatalErrorInFunction
            << "Time " << runTime.timeName() << " of case "
            << runTime.globalPath() << " is incomplete" << where.str().c_str()
            << ": it has no uniform/" << completeMarker << ", so the run that"
            << " wrote it stopped while writing." << nl
            << "    Restart from the latest complete time, " << previous
            << ": remove (or rename) " << timeDir << ", or set 'startFrom"
            << " startTime; startTime " << previous << ";' in "
            << runTime.globalPath()/"system"/"controlDict" << nl
            << exit(FatalError);
    }

    // Particles from another mesh would sit in the wrong cells
    const fileName marker(uniform/completeMarker);
    const dictionary current(meshSignature(mesh_));  // on every processor
    const dictionary written(startMarker(runTime));
    if (!written.empty())
    {
        for (const word key : {"nCells"})
        {
            if (written.get<label>(key) != current.get<label>(key))
            {
                FatalIOErrorInFunction(written)
                    << "Time " << runTime.timeName() << " was written on a"
                    << " mesh with " << key << " " << written.get<label>(key)
                    << " (" << marker << "), but this mesh has "
                    << current.get<label>(key) << ": its particles belong to"
                    << " another mesh." << nl << exit(FatalIOError);
            }
        }
        const scalar V0 = written.get<scalar>("volume");
        const scalar V = current.get<scalar>("volume");
        if (mag(V - V0) > 1e-9*max(mag(V0), VSMALL))
        {
            FatalIOErrorInFunction(written)
                << "Time " << runTime.timeName() << " was written on a mesh"
                << " of volume " << V0 << " (" << marker << "), but this mesh"
                << " has " << V << ": its particles belong to another mesh."
                << nl << exit(FatalIOError);
        }
    }
}


Foam::word Foam::coagulation::coagulationCloud::latestCompleteTime() const
{
    // The latest time before the start time that the run that wrote it
    // marked complete (or that no run wrote, as 0), on every processor
    const Time& runTime = mesh_.time();
    scalar latest = -GREAT;
    const instantList times = runTime.times();
    forAllReverse(times, i)
    {
        if (times[i].value() < runTime.value() - 0.5*runTime.deltaTValue())
        {
            const fileName dir(runTime.path()/times[i].name()/"uniform");
            if (!isFile(dir/"time") || isFile(dir/completeMarker))
            {
                latest = times[i].value();
                break;
            }
        }
    }
    reduce(latest, minOp<scalar>());
    return latest > -GREAT ? Time::timeName(latest) : word("none");
}


void Foam::coagulation::coagulationCloud::checkParticleFiles() const
{
    // Every particle field of a processor holds as many particles as its
    // coordinates, and all processors together as many as the completion
    // marker records for the time (the whole case's count, so that a time
    // decomposed or reconstructed since checks too); otherwise a file is of
    // another time (a copy, a write cut short), and reading it would mix
    // particles
    const Time& runTime = mesh_.time();
    const fileName dir(runTime.timePath()/cloud::prefix/this->name());
    const fileName coordinates
    (
        dir/(isFile(dir/"coordinates") ? "coordinates" : "positions")
    );

    fileName file;
    label found = -1;
    label expected = this->size();
    if (expected > 0)
    {
        for (const word field : {"mass", "weight"})
        {
            if (!isFile(dir/field))
            {
                file = dir/field;
                break;
            }
            IFstream is(dir/field);
            IOobject io
            (
                field, runTime.timeName(), mesh_,
                IOobject::NO_READ, IOobject::NO_WRITE, false
            );
            io.readHeader(is);
            const label n = readLabel(is);
            if (n != expected)
            {
                file = dir/field;
                found = n;
                break;
            }
        }
    }

    label total = -1;
    startMarker(runTime).readIfPresent("totalParticles", total);
    const label read = returnReduce(this->size(), sumOp<label>());
    const bool totalWrong = total >= 0 && read != total;

    // The time to restart from, agreed by every processor
    bool bad = !file.empty() || totalWrong;
    reduce(bad, orOp<bool>());
    if (!bad)
    {
        return;
    }
    const word previous(latestCompleteTime());

    OStringStream what;
    if (totalWrong)
    {
        // The same on every processor: the master's message
        if (!Pstream::master())
        {
            awaitFatalErrorElsewhere();
        }
        file =
            Pstream::parRun()
          ? fileName
            (
                runTime.globalPath()/"processor*"/runTime.timeName()
               /cloud::prefix/this->name()/coordinates.name()
            )
          : coordinates;
        what<< " hold " << read << " particles in all";
        expected = total;
    }
    else if (file.empty())
    {
        awaitFatalErrorElsewhere();
    }
    else if (found < 0)
    {
        what<< " is missing";
    }
    else
    {
        what<< " holds " << found << " particles";
    }

    FatalErrorInFunction
        << "The particle file " << file << what.str().c_str() << ", but time "
        << runTime.timeName() << " has " << expected
        << (totalWrong ? " (its uniform/" : " (its ")
        << (totalWrong ? word(completeMarker) : coordinates.name())
        << "): the file is of another time, or was cut short." << nl
        << "    Put back the file written with time " << runTime.timeName()
        << ", or restart from the latest complete time, " << previous
        << " ('startFrom startTime; startTime " << previous << ";' in "
        << runTime.globalPath()/"system"/"controlDict" << ")" << nl
        << exit(FatalError);
}


void Foam::coagulation::coagulationCloud::checkParticles() const
{
    const label nCells = mesh_.nCells();
    const label nFaces = mesh_.nFaces();
    const fileName dir
    (
        mesh_.time().timePath()/cloud::prefix/this->name()
    );

    label i = 0;
    for (const coagulationParticle& p : *this)
    {
        const label celli = p.cell();
        const label facei = p.tetFace();
        const bool inMesh =
            celli >= 0 && celli < nCells && facei >= 0 && facei < nFaces
         && mesh_.cells()[celli].found(facei)
         && p.tetPt() >= 1 && p.tetPt() < mesh_.faces()[facei].size() - 1;
        if (!inMesh)
        {
            FatalErrorInFunction
                << "Particle " << i << " of " << dir/"positions"
                << " is in cell " << celli << " (tet face " << facei
                << ", point " << p.tetPt() << "), which is not a valid place"
                << " in this mesh of " << nCells << " cells: the particles"
                << " were written for another mesh" << nl << exit(FatalError);
        }

        const bool massOk = p.mass() > 0 && std::isfinite(p.mass());
        if (!massOk || !(p.weight() > 0) || !std::isfinite(p.weight()))
        {
            FatalErrorInFunction
                << "Particle " << i << " has mass " << p.mass()
                << " and weight " << p.weight() << " in "
                << dir/(massOk ? "weight" : "mass")
                << ": both must be positive and finite" << nl
                << exit(FatalError);
        }
        ++i;
    }

    // DSA carries particles of the one weight W: those of a run with
    // weighted particles (SWA) or another weight cannot go on under it
    if (algorithm_->equalWeights())
    {
        const scalar W = scaling_.particleWeight();
        scalar wMin = GREAT;
        scalar wMax = -GREAT;
        for (const coagulationParticle& p : *this)
        {
            wMin = min(wMin, p.weight());
            wMax = max(wMax, p.weight());
        }
        reduce(wMin, minOp<scalar>());
        reduce(wMax, maxOp<scalar>());
        if (wMax > -GREAT && (wMin != W || wMax != W))
        {
            word writtenBy("unknown");
            startMarker(mesh_.time()).readIfPresent("algorithm", writtenBy);
            // The same algorithm: the weight W changed (statisticalWeight)
            OStringStream keep;
            if (writtenBy == algorithmName_)
            {
                keep<< "Keep the entries of 'statisticalWeight' of the run"
                    << " that wrote this time";
            }
            else
            {
                keep<< "Keep 'algorithm " << writtenBy << ";'";
            }
            FatalIOErrorInFunction(properties_)
                << "Entry 'algorithm' = " << algorithmName_ << " in "
                << properties_.objectPath() << " keeps every particle of"
                << " the one weight " << W << ", but the particles of the"
                << " start time " << mesh_.time().timeName() << " ("
                << dir/"weight" << ") have weights from " << wMin << " to "
                << wMax << ": this restart continues a run of algorithm "
                << writtenBy << " with other weights." << nl
                << "    " << keep.str().c_str() << " to go on from this"
                << " time, or start afresh (remove the times after 0, or set"
                << " 'startFrom startTime; startTime 0;' in "
                << mesh_.time().globalPath()/"system"/"controlDict" << ")"
                << nl << exit(FatalIOError);
        }
    }
}


void Foam::coagulation::coagulationCloud::checkFlow
(
    const volVectorField& U
) const
{
    caseChecks::emptyPatches(mesh_);
    caseChecks::timeControls(mesh_.time());
    if (!flowChecked_)
    {
        // A flow solver's velocity before the population starts (a
        // function object's timeStart) is checked at the first split step
        Info<< "The velocity is checked at the population's first step"
            << nl << endl;
        return;
    }
    checkVelocity(U);
}


void Foam::coagulation::coagulationCloud::checkVelocity
(
    const volVectorField& U
) const
{
    caseChecks::velocity(U);
    caseChecks::courant(U, stepInterval_);

    // Inflow asked for must find an inlet
    if (injection_)
    {
        injection_->checkFlow(U);
    }

    checkExpectedSize(U);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::coagulation::coagulationCloud::completeWrite()
{
    if (pendingWrite_.empty())
    {
        return;
    }

    // The particle count and the mesh: what a restart from here checks
    IOdictionary marker
    (
        IOobject
        (
            completeMarker,
            pendingWrite_,
            "uniform",
            mesh_,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        ),
        meshSignature(mesh_)
    );
    // The whole case's count: a time decomposed or reconstructed since
    // holds the same number
    marker.add("totalParticles", returnReduce(this->size(), sumOp<label>()));
    marker.add("algorithm", algorithmName_);
    // All digits: the volume is compared at a restart. Written to the
    // folder of that time: regIOobject::writeObject would write to the
    // time now (in a flow solver the next step's, where the marker is due)
    const restartPrecision allDigits;
    const fileName dir(mesh_.time().path()/pendingWrite_/"uniform");
    mkDir(dir);
    OFstream os(dir/completeMarker);
    marker.writeHeader(os);
    marker.writeData(os);
    IOobject::writeEndDivider(os);
    pendingWrite_.clear();
}


// ************************************************************************* //
