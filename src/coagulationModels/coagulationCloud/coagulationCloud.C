/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "coagulationCloud.H"
#include "fvMesh.H"
#include "surfaceFields.H"
#include "polyMeshTetDecomposition.H"
#include "zeroGradientFvPatchFields.H"
#include "processorPolyPatch.H"
#include "registerSwitch.H"
#include "caseChecks.H"

#include <cfenv>

#include <random>
#include <cstdlib>
#include <string>

#ifdef _OPENMP
#include <omp.h>
#endif

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

int Foam::coagulationCloud::cloudMove
(
    Foam::debug::optimisationSwitch("coagulationCloudMove", 0)
);
registerOptSwitch
(
    "coagulationCloudMove",
    int,
    Foam::coagulationCloud::cloudMove
);

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- SplitMix64 finaliser: decorrelates the seeds of neighbouring streams
inline uint64_t mix64(uint64_t z)
{
    z += 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30))*0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27))*0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

//- A positive scalar entry, or a FatalIOError naming the entry
Foam::scalar getPositive(const Foam::dictionary& dict, const Foam::word& key)
{
    const Foam::scalar value = dict.get<Foam::scalar>(key);
    if (!(value > 0) || !std::isfinite(value))
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' = " << value << " in " << dict.name()
            << " must be positive and finite" << Foam::nl
            << Foam::exit(Foam::FatalIOError);
    }
    return value;
}

//- A non-negative scalar entry, or a FatalIOError naming the entry
Foam::scalar getNonNegative(const Foam::dictionary& dict, const Foam::word& key)
{
    const Foam::scalar value = dict.get<Foam::scalar>(key);
    if (!(value >= 0) || !std::isfinite(value))
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' = " << value << " in " << dict.name()
            << " must be finite and not negative" << Foam::nl
            << Foam::exit(Foam::FatalIOError);
    }
    return value;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::coagulationCloud::readInception(const dictionary& dict)
{
    caseChecks::keywords(dict, {"rate", "mass", "cellZone"});
    inception_.rate = getNonNegative(dict, "rate");
    inception_.type.mass = getPositive(dict, "mass");
    inception_.weight = particleWeight_;

    const word zoneName(dict.getOrDefault<word>("cellZone", "none"));

    if (zoneName == "none")
    {
        inceptionCell_ = true;
        return;
    }

    const label zonei = mesh_.cellZones().findZoneID(zoneName);
    if (zonei < 0)
    {
        FatalIOErrorInFunction(dict)
            << "cellZone '" << zoneName << "' (entry 'cellZone' in "
            << dict.name() << ") is not in the mesh; its cellZones are "
            << mesh_.cellZones().names() << nl
            << exit(FatalIOError);
    }
    inceptionCell_ = false;
    for (const label celli : mesh_.cellZones()[zonei])
    {
        inceptionCell_[celli] = true;
    }
}


void Foam::coagulationCloud::readInflow(const dictionary& dict)
{
    caseChecks::keywords(dict, {"patches", "density", "mass"});
    const wordList patchNames(dict.get<wordList>("patches"));
    inflowDensity_ = getNonNegative(dict, "density");
    inflowMass_ = getPositive(dict, "mass");

    if (inflowDensity_ > 0 && patchNames.empty())
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'patches' in " << dict.name() << " lists no patch, but"
            << " 'density' = " << inflowDensity_ << " asks for inflow." << nl
            << "    Name the inlet patches, or set density 0 for no inflow"
            << nl << exit(FatalIOError);
    }

    inflowPatches_.setSize(patchNames.size());
    forAll(patchNames, i)
    {
        inflowPatches_[i] = mesh_.boundaryMesh().findPatchID(patchNames[i]);
        if (inflowPatches_[i] < 0)
        {
            FatalIOErrorInFunction(dict)
                << "Inflow patch '" << patchNames[i] << "' (entry 'patches' in "
                << dict.name() << ") is not in the mesh; its patches are "
                << mesh_.boundaryMesh().names() << nl
                << exit(FatalIOError);
        }
    }
}


uint64_t Foam::coagulationCloud::streamSeed
(
    const label index,
    const label purpose
) const
{
    uint64_t s = mix64(seed_);
    s = mix64(s ^ uint64_t(Pstream::myProcNo()));
    s = mix64(s ^ uint64_t(index));
    s = mix64(s ^ uint64_t(mesh_.time().timeIndex()));
    s = mix64(s ^ uint64_t(purpose));
    return s;
}


void Foam::coagulationCloud::reseed(const label index, const label purpose)
{
    rng_.engine().seed(streamSeed(index, purpose));
}


void Foam::coagulationCloud::sortByCell()
{
    if (sorted_)
    {
        return;
    }

    const label nCells = mesh_.nCells();

    // The cloud in list order (kept by the steps, or one pass over the
    // linked list), then a stable counting sort on the arrays: within a
    // cell, list order
    listCloud();
    const label nParticles = listParticles_.size();

    cellStart_.setSize(nCells + 1);
    cellStart_ = 0;
    for (label k = 0; k < nParticles; ++k)
    {
        ++cellStart_[listCells_[k] + 1];
    }
    for (label celli = 0; celli < nCells; ++celli)
    {
        cellStart_[celli + 1] += cellStart_[celli];
    }

    cellParticles_.setSize(nParticles);
    cellListIndex_.setSize(nParticles);
    cellNext_ = SubList<label>(cellStart_, nCells);
    for (label k = 0; k < nParticles; ++k)
    {
        const label pos = cellNext_[listCells_[k]]++;
        cellParticles_[pos] = listParticles_[k];
        cellListIndex_[pos] = k;
    }

    sorted_ = true;
}


void Foam::coagulationCloud::listCloud()
{
    if (listValid_)
    {
        return;
    }

    const label nParticles = this->size();
    listParticles_.setSize(nParticles);
    listCells_.setSize(nParticles);
    label i = 0;
    for (coagulationParticle& p : *this)
    {
        listParticles_[i] = &p;
        listCells_[i] = p.cell();
        ++i;
    }
    listValid_ = true;
}


void Foam::coagulationCloud::compactList(const std::vector<char>& removed)
{
    const label n = listParticles_.size();
    label kept = 0;
    for (label k = 0; k < n; ++k)
    {
        if (!removed[k])
        {
            listParticles_[kept] = listParticles_[k];
            listCells_[kept] = listCells_[k];
            ++kept;
        }
    }
    listParticles_.setSize(kept);
    listCells_.setSize(kept);
}


void Foam::coagulationCloud::placeInCell
(
    const label celli,
    coag::Rng& rng,
    bornParticle& born
) const
{
    // Pick a tet of the cell's decomposition with probability proportional
    // to its volume, then a point uniformly in it (Dirichlet(1,1,1,1)
    // barycentric coordinates from three sorted uniforms)
    const List<tetIndices>& tets = cellTets_[celli];
    const scalarList& tetVolumes = cellTetVolumes_[celli];

    scalar target = rng.uniform()*cellTetTotal_[celli];
    label chosen = tets.size() - 1;
    forAll(tets, i)
    {
        target -= tetVolumes[i];
        if (target <= 0)
        {
            chosen = i;
            break;
        }
    }

    scalar u[3] = {rng.uniform(), rng.uniform(), rng.uniform()};
    std::sort(u, u + 3);
    born.coordinates = barycentric(u[0], u[1] - u[0], u[2] - u[1], 1 - u[2]);
    born.tetFace = tets[chosen].face();
    born.tetPt = tets[chosen].tetPt();
}


void Foam::coagulationCloud::moveOnThreads
(
    const volVectorField& U,
    coagulationParticle::trackingData& td,
    const scalar dt
)
{
    // What a move did with a particle (zero: kept, so that the array marks
    // the particles to compact away). Tracking itself drops a particle
    // (unbooked, as in Cloud::move) only on patch types the particle does not
    // handle; the particle balance then shows it
    enum : char { keptByMove = 0, leftByOutflow, droppedByTracking };

    // The threads only read the mesh: its demand-driven parts that tracking
    // uses are built here, serially, first
    (void)mesh_.tetBasePtIs();
    (void)mesh_.cells();
    (void)mesh_.cellCentres();
    (void)mesh_.geometricD();

    listCloud();
    const label nParticles = listParticles_.size();
    moveOutcome_.resize(nParticles);

    const label nPatches = mesh_.boundaryMesh().size();

    #pragma omp parallel num_threads(nThreads_)
    {
        // A particle's move changes only that particle; what it books as
        // outflow here is discarded and booked below in list order, so that
        // the sums do not depend on the thread count
        List<label> outParticles(nPatches, Zero);
        List<scalar> outNumber(nPatches, Zero);
        List<scalar> outMass(nPatches, Zero);
        coagulationParticle::trackingData threadTd
        (
            *this, U, outParticles, outNumber, outMass
        );

        #pragma omp for schedule(dynamic, 4096)
        for (label k = 0; k < nParticles; ++k)
        {
            coagulationParticle& p = *listParticles_[k];
            p.stepFraction() = 0;
            const label booked = threadTd.nBooked();
            const bool kept = p.move(*this, threadTd, dt);
            moveOutcome_[k] =
                kept ? keptByMove
              : threadTd.nBooked() > booked ? leftByOutflow
              : droppedByTracking;
            listCells_[k] = p.cell();
        }

        // Counts only: the same whatever the order the threads add them in
        #pragma omp critical(coagulationCloudMoveCounts)
        {
            for (label i = 0; i < threadTd.nStalled(); ++i)
            {
                td.bookStalled();
            }
            if (threadTd.nUnhandled())
            {
                td.bookUnhandled(threadTd.unhandledPatch());
            }
        }
    }

    for (label k = 0; k < nParticles; ++k)
    {
        if (moveOutcome_[k] != keptByMove)
        {
            coagulationParticle& p = *listParticles_[k];
            if (moveOutcome_[k] == leftByOutflow)
            {
                td.bookOutflow(p.patch(), p);
            }
            deleteParticle(p);
        }
    }
    compactList(moveOutcome_);
}


void Foam::coagulationCloud::injectInflow
(
    const volVectorField& U,
    const scalar dt
)
{
    if (inflowDensity_ <= 0)
    {
        return;
    }

    for (const label patchi : inflowPatches_)
    {
        const polyPatch& pp = mesh_.boundaryMesh()[patchi];
        const vectorField& Sf = mesh_.Sf().boundaryField()[patchi];
        const vectorField& Ub = U.boundaryField()[patchi];
        const pointField& points = mesh_.points();

        forAll(pp, facei)
        {
            const scalar inwardFlux = -(Ub[facei] & Sf[facei]);
            if (inwardFlux <= 0)
            {
                continue;
            }

            // Computational particles entering over dt: Poisson with mean
            // c_in * flux * dt / W
            reseed(pp.start() + facei, 1);
            std::poisson_distribution<label> count
            (
                inflowDensity_*inwardFlux*dt/particleWeight_
            );
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

                const point position = onFace + rng_.uniform()*dt*Uin;

                coagulationParticle* pPtr = new coagulationParticle
                (
                    mesh_, position, owner, inflowMass_, particleWeight_
                );
                this->addParticle(pPtr);
                if (listValid_)
                {
                    listParticles_.append(pPtr);
                    listCells_.append(pPtr->cell());
                }

                inflow_.particles += 1;
                inflow_.number += particleWeight_;
                inflow_.mass += particleWeight_*inflowMass_;
            }
        }
    }
}


Foam::coagulationCloud::balance Foam::coagulationCloud::incepted() const
{
    balance b;
    b.particles = label(events_.inceptions);
    b.number = events_.inceptions*particleWeight_;
    // Every incepted particle has the same type and weight: the product is
    // exact where a running sum over millions of events would drift
    b.mass = events_.inceptions*particleWeight_*inception_.type.mass;
    return b;
}


Foam::coagulationCloud::balance Foam::coagulationCloud::domainContent() const
{
    balance b;
    for (const coagulationParticle& p : *this)
    {
        b.particles += 1;
        b.number += p.weight();
        b.mass += p.weight()*p.mass();
    }
    reduce(b.particles, sumOp<label>());
    reduce(b.number, sumOp<scalar>());
    reduce(b.mass, sumOp<scalar>());
    return b;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coagulationCloud::coagulationCloud
(
    const fvMesh& mesh,
    const word& cloudName
)
:
    Cloud<coagulationParticle>(mesh, cloudName, false),
    mesh_(mesh),
    properties_
    (
        IOobject
        (
            "coagulationProperties",
            mesh.time().constant(),
            mesh,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    ),
    kernel_(coagulationKernel::New(properties_.subDict("kernel"))),
    n_(0),
    V1_(0),
    particleWeight_(0),
    inception_(),
    inceptionCell_(mesh.nCells(), false),
    algorithm_(),
    algorithmNoInception_(),
    seed_(0),
    inflowPatches_(),
    inflowDensity_(0),
    inflowMass_(1),
    moments_(4),
    removedInCells_(0),
    events_(),
    stalled_(0),
    memoryLimit_(0),
    pendingWrite_(),
    nThreads_(1),
    cellTets_(mesh.nCells()),
    cellTetVolumes_(mesh.nCells()),
    cellTetTotal_(mesh.nCells(), Zero),
    cellStart_(),
    cellNext_(),
    cellParticles_(),
    listParticles_(),
    listCells_(),
    listValid_(false),
    cellListIndex_(),
    listRemoved_(),
    moveOutcome_(),
    sorted_(false),
    workers_(),
    outcomes_(),
    rng_(0)
{
    // Every entry is checked: an unknown keyword is a typo, not a default
    caseChecks::keywords
    (
        properties_,
        {
            "algorithm", "kernel", "inception", "inflow", "statisticalWeight",
            "seed", "sampling", "numberControl"
        }
    );

    // Statistical scaling of the paper: W = Vref/(n V1).  V1 may be given
    // per algorithm (the paper uses different V1 for DSA and SWA), so that
    // the 'algorithm' keyword alone switches a case between them.
    {
        const dictionary& dict = properties_.subDict("statisticalWeight");
        caseChecks::keywords(dict, {"n", "V1"});
        n_ = getPositive(dict, "n");
        if (dict.isDict("V1"))
        {
            caseChecks::keywords(dict.subDict("V1"), {"SWA", "DSA1", "DSA2"});
            V1_ = getPositive
            (
                dict.subDict("V1"), properties_.get<word>("algorithm")
            );
        }
        else
        {
            V1_ = getPositive(dict, "V1");
        }
        const scalar meanCellVolume =
            gSum(mesh_.V())/returnReduce(mesh_.nCells(), sumOp<label>());
        particleWeight_ = meanCellVolume/(n_*V1_);
    }

    readInception(properties_.subDict("inception"));

    if (properties_.found("inflow"))
    {
        readInflow(properties_.subDict("inflow"));
    }

    {
        const label seed = properties_.get<label>("seed");
        if (seed < 0)
        {
            FatalIOErrorInFunction(properties_)
                << "Entry 'seed' = " << seed << " in " << properties_.name()
                << " must not be negative" << nl << exit(FatalIOError);
        }
        seed_ = uint64_t(seed);
    }

    coag::NumberControl control;
    if (properties_.found("numberControl"))
    {
        const dictionary& dict = properties_.subDict("numberControl");
        caseChecks::keywords(dict, {"maxParticlesPerCell"});
        const label maxParticles =
            dict.getOrDefault<label>("maxParticlesPerCell", 0);
        if (maxParticles < 0 || maxParticles == 1)
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'maxParticlesPerCell' = " << maxParticles << " in "
                << dict.name() << " must be 0 (off) or at least 2: halving"
                << " keeps about half of the particles of a cell" << nl
                << exit(FatalIOError);
        }
        control.maxParticles = std::size_t(maxParticles);
    }

    algorithm_ =
        cellAlgorithm::New(properties_, *kernel_, inception_, control);

    // DSA halving would halve a cell's sample volume, but a mesh cell's
    // volume is fixed: number control is for weighted particles only
    if (algorithm_->equalWeights() && control.maxParticles > 0)
    {
        FatalIOErrorInFunction(properties_)
            << "Entry 'numberControl/maxParticlesPerCell' in "
            << properties_.name() << " needs weighted particles (SWA); "
            << properties_.get<word>("algorithm")
            << " keeps all weights equal" << nl << exit(FatalIOError);
    }

    coag::InceptionModel noInception(inception_);
    noInception.rate = 0;
    algorithmNoInception_ =
        cellAlgorithm::New(properties_, *kernel_, noInception, control);

    // Threads of the cell step: OMP_NUM_THREADS, or all cores in a serial
    // run; MPI ranks already share the cores, so one thread per rank there
    // unless OMP_NUM_THREADS says otherwise
    #ifdef _OPENMP
    nThreads_ = omp_get_max_threads();
    if (Pstream::parRun() && !std::getenv("OMP_NUM_THREADS"))
    {
        nThreads_ = 1;
    }
    #endif
    workers_.resize(nThreads_);
    for (cellWorker& worker : workers_)
    {
        worker.algorithm = algorithm_->clone();
        worker.algorithmNoInception = algorithmNoInception_->clone();
    }

    // Tet decomposition of every cell, computed once and serially (the
    // mesh's demand-driven geometry is not built inside the threads)
    forAll(cellTets_, celli)
    {
        cellTets_[celli] =
            polyMeshTetDecomposition::cellTetIndices(mesh_, celli);
        const List<tetIndices>& tets = cellTets_[celli];
        scalarList& volumes = cellTetVolumes_[celli];
        volumes.setSize(tets.size());
        forAll(tets, i)
        {
            volumes[i] = tets[i].tet(mesh_).mag();
            cellTetTotal_[celli] += volumes[i];
        }
    }

    // Particles of the start time, if any: of a completely written time of
    // this mesh, each in a cell with a finite positive mass and weight
    checkStartTime();
    coagulationParticle::readFields(*this);
    checkParticles();

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
                    mesh_.time().timeName(),
                    mesh_,
                    IOobject::NO_READ,
                    IOobject::AUTO_WRITE
                ),
                mesh_,
                dimensionedScalar(dimless/dimVolume, Zero),
                zeroGradientFvPatchScalarField::typeName
            )
        );
    }

    initial_ = domainContent();
    updateMoments();

    // The cloud may grow into the memory free now, less a quarter for the
    // rest of the run (fields, samples, the cell step's work arrays)
    memoryLimit_ = 0.75*availableMemory() + initial_.particles*bytesPerParticle();

    Info<< "Coagulation cloud " << cloudName << ": "
        << initial_.particles << " particles, weight per new particle "
        << particleWeight_ << ", inception rate " << inception_.rate
        << " in " << returnReduce(std::count(inceptionCell_.begin(), inceptionCell_.end(), true), sumOp<label>())
        << " cells, " << nThreads_ << " thread(s) for the cell step"
        << " (OMP_WAIT_POLICY "
        << (std::getenv("OMP_WAIT_POLICY") ? std::getenv("OMP_WAIT_POLICY") : "unset")
        << ")" << nl << endl;

    if (nThreads_ > 1 && !std::getenv("OMP_WAIT_POLICY"))
    {
        WarningInFunction
            << "OMP_WAIT_POLICY is not set: threads waiting for each other"
            << " spin, which slows a run several times on a machine shared"
            << " with other jobs. etc/bashrc sets it to PASSIVE" << nl << endl;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::coagulationCloud::coagulateCell
(
    const label celli,
    const scalar dt,
    cellWorker& worker,
    cellOutcome& outcome
) const
{
    outcome.events = coag::StepStatistics();
    outcome.born.clear();
    outcome.died.clear();

    const label start = cellStart_[celli];
    const label np = cellStart_[celli + 1] - start;
    const bool incepts = inception_.rate > 0 && inceptionCell_[celli];

    // Without inception a cell needs a pair to change
    if (np < 2 && !incepts)
    {
        return;
    }

    coag::CellPopulation& population = worker.population;
    population.volume = mesh_.V()[celli];
    population.particles.clear();
    for (label i = 0; i < np; ++i)
    {
        const coagulationParticle& p = *cellParticles_[start + i];
        coag::Particle cp;
        cp.type.mass = p.mass();
        cp.weight = p.weight();
        cp.tag = i;
        population.particles.push_back(cp);
    }

    // Counted in the worker, not in outcome: the outcomes of the cells that
    // the other threads are stepping share its cache lines
    worker.events = coag::StepStatistics();
    worker.rng.engine().seed(streamSeed(celli, 0));
    {
        // The core reports overflow (gelation, a huge kernel) as a
        // non-finite rate: OpenFOAM's floating-point traps are held while it
        // runs, so that it can say so instead of dying of SIGFPE
        std::fenv_t trapping;
        std::feholdexcept(&trapping);
        try
        {
            (incepts ? worker.algorithm : worker.algorithmNoInception)
                ->advance(population, dt, worker.rng, worker.events);
        }
        catch (...)
        {
            std::feclearexcept(FE_ALL_EXCEPT);
            std::fesetenv(&trapping);
            throw;
        }
        std::feclearexcept(FE_ALL_EXCEPT);
        std::fesetenv(&trapping);
    }
    outcome.events = worker.events;

    // Write the cell's new state back: survivors in place, new particles
    // placed with the cell's stream (in population order, as they will be
    // constructed), the rest recorded as gone
    worker.survived.assign(np, 0);
    for (const coag::Particle& cp : population.particles)
    {
        if (cp.tag >= 0)
        {
            coagulationParticle& p = *cellParticles_[start + cp.tag];
            p.mass() = cp.type.mass;
            p.weight() = cp.weight;
            worker.survived[cp.tag] = 1;
        }
        else
        {
            bornParticle born;
            born.mass = cp.type.mass;
            born.weight = cp.weight;
            placeInCell(celli, worker.rng, born);
            outcome.born.push_back(born);
        }
    }
    for (label i = 0; i < np; ++i)
    {
        if (!worker.survived[i])
        {
            outcome.died.push_back(start + i);
        }
    }
}


void Foam::coagulationCloud::coagulate(const scalar dt)
{
    sortByCell();

    const label nCells = mesh_.nCells();
    outcomes_.resize(nCells);

    // The cells are independent jump processes: share them among the
    // threads (largest cells, downstream on a duct, are not known in
    // advance, so cells are handed out one at a time)
    std::string failure;
    #pragma omp parallel for schedule(dynamic, 1) num_threads(nThreads_)
    for (label celli = 0; celli < nCells; ++celli)
    {
        #ifdef _OPENMP
        cellWorker& worker = workers_[omp_get_thread_num()];
        #else
        cellWorker& worker = workers_[0];
        #endif
        try
        {
            coagulateCell(celli, dt, worker, outcomes_[celli]);
        }
        catch (const std::exception& e)
        {
            #pragma omp critical(coagulationCloudFailure)
            if (failure.empty())
            {
                failure =
                    "cell " + std::to_string(celli) + ": " + e.what();
            }
        }
    }
    if (!failure.empty())
    {
        FatalErrorInFunction
            << "Cell step failed in " << failure << nl
            << "    Check the kernel (K0), the inception rate and deltaT in "
            << properties_.objectPath() << " and "
            << mesh_.time().controlDict().name() << nl
            << exit(FatalError);
    }

    // Serially, in cell order: book the events, construct the new particles
    // (ids are handed out in order) and delete the ones that are gone. The
    // list is then the old one less the dead, then the new in this order
    listRemoved_.assign(listParticles_.size(), 0);
    for (label celli = 0; celli < nCells; ++celli)
    {
        for (const label i : outcomes_[celli].died)
        {
            listRemoved_[cellListIndex_[i]] = 1;
        }
    }
    compactList(listRemoved_);

    for (label celli = 0; celli < nCells; ++celli)
    {
        const cellOutcome& outcome = outcomes_[celli];
        events_ += outcome.events;

        // Particles removed in the cell: DSA merges (including any
        // incepted and merged away within this step) and halvings
        removedInCells_ +=
            label(outcome.events.inceptions) - label(outcome.born.size())
          + label(outcome.died.size());

        for (const bornParticle& born : outcome.born)
        {
            coagulationParticle* pPtr = new coagulationParticle
            (
                mesh_,
                born.coordinates,
                celli,
                born.tetFace,
                born.tetPt,
                born.mass,
                born.weight
            );
            this->addParticle(pPtr);
            listParticles_.append(pPtr);
            listCells_.append(celli);
        }
        for (const label i : outcome.died)
        {
            this->deleteParticle(*cellParticles_[i]);
        }
    }
    sorted_ = false;

    checkMemory();
}


void Foam::coagulationCloud::advect(const volVectorField& U, const scalar dt)
{
    const label nPatches = mesh_.boundaryMesh().size();
    List<label> outParticles(nPatches, Zero);
    List<scalar> outNumber(nPatches, Zero);
    List<scalar> outMass(nPatches, Zero);

    coagulationParticle::trackingData td
    (
        *this, U, outParticles, outNumber, outMass
    );
    sorted_ = false;
    if (!cloudMove && !Pstream::parRun())
    {
        moveOnThreads(U, td, dt);
    }
    else
    {
        // Decomposed runs hand particles to other processors: Cloud::move
        // (and the walk of the linked list it implies)
        listValid_ = false;
        Cloud<coagulationParticle>::move(*this, td, dt);
    }

    // A particle that reached a patch type it does not handle was stopped
    // (and is gone from the cloud): stop the run with the patch's name
    if (returnReduce(td.nUnhandled(), sumOp<label>()) > 0)
    {
        const label patchi = td.unhandledPatch();
        FatalErrorInFunction
            << "Particles reached patch '"
            << (patchi >= 0 ? mesh_.boundaryMesh()[patchi].name() : word("?"))
            << "' of type '"
            << (patchi >= 0 ? mesh_.boundaryMesh()[patchi].type() : word("?"))
            << "' in " << mesh_.boundaryMesh().objectPath() << nl
            << "    coagulationFoam handles patch (outflow), wall, symmetry,"
            << " symmetryPlane and empty (rebound), processor, cyclic,"
            << " cyclicAMI and wedge patches" << nl << exit(FatalError);
    }
    stalled_ += td.nStalled();

    for (label patchi = 0; patchi < nPatches; ++patchi)
    {
        outflow_.particles += outParticles[patchi];
        outflow_.number += outNumber[patchi];
        outflow_.mass += outMass[patchi];
    }

    injectInflow(U, dt);
}


void Foam::coagulationCloud::updateMoments()
{
    // The sort is kept for the next coagulate(): nothing changes the cloud
    // in between
    sortByCell();

    scalarField& M0 = moments_[0].primitiveFieldRef();
    scalarField& M1 = moments_[1].primitiveFieldRef();
    scalarField& M2 = moments_[2].primitiveFieldRef();
    scalarField& M3 = moments_[3].primitiveFieldRef();
    const scalarField& V = mesh_.V();
    const label nCells = mesh_.nCells();

    // Each cell sums its particles in list order, whatever the thread count
    #pragma omp parallel for schedule(static) num_threads(nThreads_)
    for (label celli = 0; celli < nCells; ++celli)
    {
        scalar s0 = 0, s1 = 0, s2 = 0, s3 = 0;
        for (label i = cellStart_[celli]; i < cellStart_[celli + 1]; ++i)
        {
            const coagulationParticle& p = *cellParticles_[i];
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


Foam::scalar Foam::coagulationCloud::massBalanceError() const
{
    balance in(initial_);
    balance inflow(inflow_), incepted(this->incepted()), outflow(outflow_);
    reduce(inflow.mass, sumOp<scalar>());
    reduce(incepted.mass, sumOp<scalar>());
    reduce(outflow.mass, sumOp<scalar>());

    const scalar control = returnReduce(events_.controlMass, sumOp<scalar>());

    const balance now = domainContent();
    const scalar expected =
        in.mass + inflow.mass + incepted.mass - outflow.mass + control;
    const scalar scale =
        max(max(now.mass, in.mass + inflow.mass + incepted.mass), VSMALL);

    return (now.mass - expected)/scale;
}


Foam::label Foam::coagulationCloud::particleBalanceError() const
{
    label change =
        inflow_.particles + incepted().particles - outflow_.particles
      - removedInCells_;
    reduce(change, sumOp<label>());

    return domainContent().particles - initial_.particles - change;
}


void Foam::coagulationCloud::report()
{
    balance inflow(inflow_), incepted(this->incepted()), outflow(outflow_);
    reduce(inflow.mass, sumOp<scalar>());
    reduce(incepted.mass, sumOp<scalar>());
    reduce(outflow.mass, sumOp<scalar>());
    reduce(inflow.particles, sumOp<label>());
    reduce(incepted.particles, sumOp<label>());
    reduce(outflow.particles, sumOp<label>());

    scalar coagulations = events_.coagulations;
    scalar fictitious = events_.fictitious;
    reduce(coagulations, sumOp<scalar>());
    reduce(fictitious, sumOp<scalar>());
    const scalar control = returnReduce(events_.controlMass, sumOp<scalar>());
    const label stalled = returnReduce(stalled_, sumOp<label>());

    const balance now = domainContent();

    Info<< "Coagulation cloud:" << nl
        << "    particles in domain        = " << now.particles << nl
        << "    physical particles         = " << now.number << nl
        << "    coagulation events         = " << coagulations
        << " (fictitious " << fictitious << ")" << nl
        << "    particles in/incepted/out  = " << inflow.particles << " / "
        << incepted.particles << " / " << outflow.particles << nl
        << "    mass initial + inflow + inception - outflow + control = "
        << initial_.mass << " + " << inflow.mass << " + " << incepted.mass
        << " - " << outflow.mass << " + " << control << nl
        << "    mass in domain             = " << now.mass << nl
        << "    mass balance error (rel.)  = " << massBalanceError() << nl
        << "    particle balance error     = " << particleBalanceError()
        << nl
        << "    particles held at a face   = " << stalled << endl;

    checkBalance();

    pendingWrite_ = mesh_.time().timeName();
}


void Foam::coagulationCloud::checkBalance() const
{
    // No run ends well having lost particles or mass: the balances close to
    // round-off, or the run stops here
    const scalar massError = massBalanceError();
    const label particleError = particleBalanceError();
    if (!(mag(massError) <= 1e-9) || particleError != 0)
    {
        FatalErrorInFunction
            << "The balances do not close at time "
            << mesh_.time().timeName() << ": relative mass error "
            << massError << ", particle count error " << particleError << nl
            << "    Particles or mass were lost: please report this case"
            << nl << exit(FatalError);
    }
}


// ************************************************************************* //
