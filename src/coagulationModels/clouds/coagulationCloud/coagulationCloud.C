/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "coagulationCloud.H"
#include "caseChecks.H"
#include "flowFields.H"
#include "particleMaterial.H"
#include "restartPrecision.H"

#include <cstdlib>

#ifdef _OPENMP
#include <omp.h>
#endif

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * //

const Foam::Enum<Foam::coagulation::coagulationCloud::splittingScheme>
Foam::coagulation::coagulationCloud::splittingSchemeNames
({
    { splittingScheme::Lie, "Lie" },
    { splittingScheme::Strang, "Strang" },
    { splittingScheme::StrangSAS, "StrangSAS" }
});


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

coag::NumberControl
Foam::coagulation::coagulationCloud::readNumberControl() const
{
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
    return control;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coagulation::coagulationCloud::coagulationCloud
(
    volVectorField& U,
    const word& cloudName,
    const bool liveFlow,
    const label stepInterval,
    const bool checkFlowNow
)
:
    Cloud<coagulationParticle>(U.mesh(), cloudName, false),
    mesh_(U.mesh()),
    U_(U),
    liveFlow_(liveFlow),
    stepInterval_(stepInterval),
    deltaT_(U.mesh().time().deltaTValue()),
    flowChecked_(checkFlowNow),
    properties_
    (
        IOobject
        (
            "coagulationProperties",
            mesh_.time().constant(),
            mesh_,
            IOobject::MUST_READ,
            IOobject::NO_WRITE
        )
    ),
    algorithmName_(readAlgorithmName(properties_)),
    splitting_(splittingScheme::Strang),
    scaling_
    (
        properties_.subDict("statisticalWeight"), algorithmName_, mesh_
    ),
    seeds_(properties_, mesh_.time(), stepInterval),
    ownFields_(),
    fields_(nullptr),
    kernel_(),
    inception_(),
    growth_(),
    algorithm_(),
    algorithmNoInception_(),
    nThreads_(1),
    index_(),
    cellStepper_(),
    transport_(),
    injection_(),
    patchInteraction_(),
    events_(),
    removedInCells_(0),
    momentFields_(),
    momentSampler_(),
    massBalance_(),
    functions_(),
    memoryLimit_(0),
    memoryLimitedBy_(),
    timer_(),
    pendingWrite_(),
    inputFields_()
{
    // Every entry is checked: an entry given twice is refused (OpenFOAM
    // would keep the last one), an unknown keyword is a typo, not a default
    caseChecks::noDuplicates(properties_);
    caseChecks::keywords
    (
        properties_,
        {
            "algorithm", "kernel", "inception", "inflow", "transport",
            "statisticalWeight", "seed", "sampling", "numberControl",
            "splitting", "patchInteraction", "dispersion",
            "initialPopulation", "cloudFunctions", "particles", "growth"
        }
    );
    caseChecks::cellVolumes(mesh_);

    // The particles' material, checked whether or not a model reads it
    if (properties_.found("particles"))
    {
        readParticleMaterial(properties_, "cloud " + cloudName);
    }

    const word scheme =
        properties_.getOrDefault<word>
        (
            "splitting", splittingSchemeNames[splittingScheme::Strang]
        );
    if (!splittingSchemeNames.found(scheme))
    {
        FatalIOErrorInFunction(properties_)
            << "Entry 'splitting' in " << properties_.name() << " is '"
            << scheme << "'; valid schemes are " << splittingSchemeNames
            << nl << exit(FatalIOError);
    }
    splitting_ = splittingSchemeNames[scheme];
    Info<< "Splitting " << scheme << endl;

    // The fields the submodels read: frozen, of a flow series, or the flow
    // solver's (the mesh's object, found by the submodels)
    if (!mesh_.foundObject<flowFields>(flowFields::typeName))
    {
        ownFields_.reset
        (
            new flowFields
            (
                mesh_, properties_.subOrEmptyDict("transport"), liveFlow_
            )
        );
    }
    fields_ = &flowFields::of(mesh_);

    kernel_ = coagulationKernel::New(properties_.subDict("kernel"), mesh_);
    inception_ = inceptionModel::New
    (
        properties_.subDict("inception"), mesh_, scaling_.particleWeight()
    );

    growth_.reset(new growthModelList(properties_, mesh_));
    if
    (
        growth_->active()
     && !(inception_->core().type.mass > growth_->minimumMass())
    )
    {
        FatalIOErrorInFunction(properties_)
            << "The incepted particles' mass " << inception_->core().type.mass
            << " is not above the minimum mass " << growth_->minimumMass()
            << " of 'growth' in " << properties_.name() << ": every new"
            << " particle would be gone at once" << nl << exit(FatalIOError);
    }

    const coag::NumberControl control = readNumberControl();
    Info<< "Selecting cell algorithm " << algorithmName_ << endl;
    algorithm_ = cellAlgorithm::New
    (
        algorithmName_, properties_, *kernel_, inception_->core(), control
    );

    // DSA halving would halve a cell's sample volume, but a mesh cell's
    // volume is fixed: number control is for weighted particles only
    if (algorithm_->equalWeights() && control.maxParticles > 0)
    {
        FatalIOErrorInFunction(properties_)
            << "Entry 'numberControl/maxParticlesPerCell' in "
            << properties_.name() << " needs weighted particles (SWA); "
            << algorithmName_ << " keeps all weights equal" << nl
            << exit(FatalIOError);
    }

    coag::InceptionModel noInception(inception_->core());
    noInception.rate = 0;
    algorithmNoInception_ = cellAlgorithm::New
    (
        algorithmName_, properties_, *kernel_, noInception, control
    );

    // Threads: OMP_NUM_THREADS, or all cores in a serial run; MPI ranks
    // already share the cores, so one thread per rank there unless
    // OMP_NUM_THREADS says otherwise
    #ifdef _OPENMP
    nThreads_ = omp_get_max_threads();
    if (Pstream::parRun() && !std::getenv("OMP_NUM_THREADS"))
    {
        nThreads_ = 1;
    }
    #endif

    cellStepper_.reset
    (
        new cellStepper(*this, *algorithm_, *algorithmNoInception_)
    );
    transport_ = transportModel::New
    (
        properties_.subOrEmptyDict("transport"), *this
    );
    // The flow of the start time (a flow series': its velocity there)
    transport_->setFlow(U_, mesh_.time().value());
    // The dispersion dictionary itself, not a copy: a Brownian walk reads
    // the particles' material beside it
    const dictionary noDispersion(properties_, dictionary());
    dispersion_ = dispersionModel::New
    (
        properties_.isDict("dispersion")
      ? properties_.subDict("dispersion")
      : noDispersion,
        mesh_
    );
    if (properties_.found("inflow"))
    {
        injection_ = injectionModel::New(properties_.subDict("inflow"), *this);
    }
    patchInteraction_ =
        properties_.found("patchInteraction")
      ? patchInteractionModel::New
        (
            properties_.subDict("patchInteraction"), mesh_
        )
      : autoPtr<patchInteractionModel>(new patchInteractionModel(mesh_));
    dispersion_->setStickWalls(patchInteraction_->stick());

    // Particles of the start time, if any: of a completely written time of
    // this mesh, each in a cell with a finite positive mass and weight
    checkStartTime();
    checkParticleFiles();
    coagulationParticle::readFields(*this);
    checkParticles();
    createInitialPopulation();

    // The cloud may grow into the memory free now, less a quarter for the
    // rest of the run (fields, samples, the cell step's work arrays)
    memoryLimit_ =
        0.75*availableMemory(memoryLimitedBy_)
      + returnReduce(this->size(), sumOp<label>())*bytesPerParticle();

    // Checked before anything is written
    checkFlow(U);

    // The functions of every run, on the particles of the start (the
    // balances count these as the initial population)
    momentFields_.reset(new cloudFunctions::momentFields(*this));
    momentSampler_.reset(new cloudFunctions::momentSampler(*this));
    massBalance_.reset(new cloudFunctions::massBalance(*this));

    // The user's functions (sizeDistribution, cellWork), after the moment
    // fields: their postStep finds the particles sorted by cell
    if (properties_.found("cloudFunctions"))
    {
        const dictionary& dict = properties_.subDict("cloudFunctions");
        for (const entry& e : dict)
        {
            if (!e.isDict())
            {
                FatalIOErrorInFunction(dict)
                    << "Entry '" << e.keyword() << "' of " << dict.name()
                    << " is not a dictionary: every cloud function is"
                    << " name { type <type>; ... }" << nl
                    << exit(FatalIOError);
            }
            functions_.append(cloudFunction::New(e.keyword(), e.dict(), *this));
        }
    }

    // The fields read (U, the submodels'): the cloud writes them, with all
    // their digits, so that a restart reads the flow and the sources exactly
    // (in a flow solver, the solver writes its own fields)
    if (!liveFlow_)
    {
        takeInputFields<volScalarField>();
        takeInputFields<volVectorField>();
    }

    Info<< "Coagulation cloud " << cloudName << ": "
        << returnReduce(this->size(), sumOp<label>())
        << " particles, weight per new particle "
        << scaling_.particleWeight() << ", inception rate "
        << inception_->core().rate << " in "
        << returnReduce(inception_->nCells(mesh_.nCells()), sumOp<label>())
        << " cells, " << nThreads_ << " thread(s) for the cell step"
        << " (OMP_WAIT_POLICY "
        << (std::getenv("OMP_WAIT_POLICY") ? std::getenv("OMP_WAIT_POLICY") : "unset")
        << ")" << nl << endl;

    #ifdef _OPENMP
    if (nThreads_ > omp_get_num_procs())
    {
        WarningInFunction
            << "OMP_NUM_THREADS = " << nThreads_ << " asks for more threads than"
            << " the " << omp_get_num_procs() << " cores this process may"
            << " use: the threads take turns, and the cell step is several"
            << " times slower. Set OMP_NUM_THREADS to at most "
            << omp_get_num_procs() << nl << endl;
    }
    #endif
    if (nThreads_ > 1 && !std::getenv("OMP_WAIT_POLICY"))
    {
        WarningInFunction
            << "OMP_WAIT_POLICY is not set: threads waiting for each other"
            << " spin, which slows a run several times on a machine shared"
            << " with other jobs. etc/bashrc sets it to PASSIVE" << nl << endl;
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::coagulation::coagulationCloud::createInitialPopulation()
{
    if (!properties_.found("initialPopulation"))
    {
        return;
    }

    // Used on a fresh start only: a start time that holds particle files of
    // this cloud (a restart) continues from them
    const fileName dir(mesh_.time().timePath()/cloud::prefix/name());
    bool written = isFile(dir/"coordinates") || isFile(dir/"positions");
    reduce(written, orOp<bool>());
    if (written)
    {
        Info<< "Initial population: not used, the start time "
            << mesh_.time().timeName() << " has the cloud's particles" << endl;
        return;
    }
    const initialPopulation initial
    (
        properties_.subDict("initialPopulation"), *this
    );

    const label created = returnReduce(initial.create(*this), sumOp<label>());
    Info<< "Initial population: " << created << " particles" << endl;
}


template<class FieldType>
void Foam::coagulation::coagulationCloud::takeInputFields()
{
    for (const word& name : mesh_.sortedNames<FieldType>())
    {
        FieldType& f = mesh_.lookupObjectRef<FieldType>(name);
        if
        (
            f.readOpt() == IOobject::MUST_READ
         && f.writeOpt() == IOobject::AUTO_WRITE
        )
        {
            f.writeOpt() = IOobject::NO_WRITE;
            inputFields_.append(&f);
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::coagulation::coagulationCloud::cellStep
(
    const scalar dt,
    const scalar tEnd,
    const streamSeeds::purpose stream
)
{
    // The kernel's and the inception's fields at the middle of the step
    fields_->update(tEnd - 0.5*dt, mesh_.time().value() - splitDeltaT());
    kernel_->correct();
    inception_->correct();

    cellStepper_->advance(dt, events_, removedInCells_, stream);
    checkMemory();

    forAllFunctions([](cloudFunction& f) { f.postCellStep(); });
}


void Foam::coagulation::coagulationCloud::transport
(
    const scalar dt,
    const scalar tEnd,
    const streamSeeds::purpose inflowStream
)
{
    // The flow over the move (a frozen flow: unchanged), and the walk's
    // diffusivity
    transport_->setFlow(U_, tEnd - 0.5*dt);
    fields_->update(tEnd - 0.5*dt, mesh_.time().value() - splitDeltaT());
    dispersion_->correct();

    transportModel::outflow out(mesh_.boundaryMesh().size());
    transport_->move
    (
        U_,
        dt,
        inflowStream == streamSeeds::inflowFirstHalf
      ? streamSeeds::walkFirstHalf
      : streamSeeds::walk,
        out
    );

    forAllFunctions([&out](cloudFunction& f) { f.postMove(out); });

    if (injection_)
    {
        injection_->inject
        (
            U_,
            dt,
            inflowStream,
            massBalance_->inflow()
        );
    }
}


void Foam::coagulation::coagulationCloud::postStep()
{
    forAllFunctions([](cloudFunction& f) { f.postStep(); });
}


void Foam::coagulation::coagulationCloud::evolve()
{
    checkStep();
    const scalar dt = splitDeltaT();
    const scalar t = mesh_.time().value();

    // Operator splitting over dt (Patterson & Wagner 2011, section 2) of
    //   S: the source terms, each cell on its own: inception (eqs 10, 20)
    //      and coagulation (SWA jumps 21-22, DSA jumps 11-15)
    //   A: transport, every particle with the flow U and its random walk
    //      dX = grad(D) dt + sqrt(2D) dW (coagulation-diffusion paper,
    //      eq. 8) in one displacement; outflow leaves, walls rebound or
    //      take the particle (deposition); then inflow enters
    timer_.start();
    if (splitting_ == splittingScheme::Lie)
    {
        // Lie, the paper's scheme: S(dt) then A(dt); first order in dt
        cellStep(dt, t);
        timer_.coagulationDone();
        transport(dt, t);
        timer_.transportDone(this->size());
    }
    else if (splitting_ == splittingScheme::Strang)
    {
        // Strang: A(dt/2), S(dt), A(dt/2); second order in dt
        transport(0.5*dt, t - 0.5*dt, streamSeeds::inflowFirstHalf);
        timer_.transportDone(this->size());
        cellStep(dt, t);
        timer_.coagulationDone();
        transport(0.5*dt, t);
        timer_.transportDone(this->size());
    }
    else
    {
        // Strang the other way round: S(dt/2), A(dt), S(dt/2); second
        // order in dt, one tracking pass
        cellStep(0.5*dt, t - 0.5*dt, streamSeeds::cellStepFirstHalf);
        timer_.coagulationDone();
        transport(dt, t);
        timer_.transportDone(this->size());
        cellStep(0.5*dt, t);
        timer_.coagulationDone();
    }

    // The cloud functions on the new state: M0..M3 (eq. 37), samples
    postStep();
}


void Foam::coagulation::coagulationCloud::onWrite()
{
    // The flow written is that of the time (a flow series set it at the
    // middle of the last move)
    transport_->setFlow(U_, mesh_.time().value());
    {
        const restartPrecision allDigits;
        for (regIOobject* f : inputFields_)
        {
            f->write();
        }
    }

    forAllFunctions([](cloudFunction& f) { f.write(); });
    pendingWrite_ = mesh_.time().timeName();
}


void Foam::coagulation::coagulationCloud::reportTimes() const
{
    timer_.report
    (
        events_, transport_->transfers(), cellStepper_->workSinceStart()
    );

    // Strang tracks every particle twice a step: where the transport takes
    // most of the time, the other second-order splitting tracks it once
    const scalar transport =
        returnReduce(timer_.transportSeconds(), sumOp<scalar>());
    const scalar cells =
        returnReduce(timer_.coagulationSeconds(), sumOp<scalar>());
    if (splitting_ == splittingScheme::Strang && transport > 2*cells)
    {
        const label percent = label(100*transport/(transport + cells));
        Info<< "The transport takes " << percent
            << " % of the split step's wall time: 'splitting StrangSAS;'"
            << " (second order too) tracks each particle once a step,"
            << " Strang twice" << nl << endl;
    }
}


void Foam::coagulation::coagulationCloud::endRun()
{
    forAllFunctions([](cloudFunction& f) { f.end(); });
    completeWrite();
}


// ************************************************************************* //
