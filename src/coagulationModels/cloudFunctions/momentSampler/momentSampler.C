/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "momentSampler.H"
#include "coagulationCloud.H"
#include "particleMaterial.H"
#include "fvMesh.H"
#include "OSspecific.H"
#include "caseChecks.H"

namespace Foam
{
namespace coagulation
{
namespace cloudFunctions
{
    defineTypeNameAndDebug(momentSampler, 0);
}
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coagulation::cloudFunctions::momentSampler::momentSampler
(
    coagulationCloud& cloud
)
:
    cloudFunction(cloud),
    tRelax_(0),
    stepsPerSample_(1),
    writer_(),
    file_(),
    lastFlushed_(-GREAT),
    values_()
{
    const dictionary& dict = cloud.properties().subDict("sampling");
    const Time& runTime = cloud.pMesh().time();
    const fvMesh& mesh = cloud.mesh();

    caseChecks::keywords(dict, {"tRelax", "sampleInterval"});
    tRelax_ = caseChecks::nonNegative(dict, "tRelax");
    const scalar interval = dict.get<scalar>("sampleInterval");
    const scalar dt = runTime.deltaTValue();
    // Samples of whole split steps (stepInterval time steps each)
    stepsPerSample_ =
        cloud.stepInterval()
       *caseChecks::stepsPer
        (
            dict, "sampleInterval", interval, cloud.splitDeltaT()
        );

    // A run that would take no sample is a mistake in the input: the first
    // sample is at the first step index past the start that is a multiple
    // of the interval (counted in scalars: stopAt nextWrite, writeNow and
    // noWriteNow leave endTime at GREAT)
    {
        const label startIndex = runTime.startTimeIndex();
        const scalar nSteps =
            std::round((runTime.endTime().value() - runTime.value())/dt);
        const label firstSample =
            (startIndex/stepsPerSample_ + 1)*stepsPerSample_;
        if (nSteps > 0 && scalar(firstSample - startIndex) > nSteps)
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'sampleInterval' = " << interval << " in "
                << dict.name() << " is longer than the run (" << nSteps
                << " steps of " << dt << " from time " << runTime.timeName()
                << " to endTime " << runTime.endTime().value() << "):"
                << " no sample would be written." << nl
                << "    Set sampleInterval <= "
                << nSteps*dt
                << " or a later endTime" << nl << exit(FatalIOError);
        }
    }

    // A run that ends before tRelax takes no sample into a time average:
    // said now, not found out by the tools afterwards
    if
    (
        runTime.endTime().value() < 0.5*GREAT
     && !(tRelax_ < runTime.endTime().value())
    )
    {
        WarningInFunction
            << "The run ends at endTime " << runTime.endTime().value()
            << ", not after tRelax = " << tRelax_ << " (" << dict.name()
            << "): the samples are written, but no time average will be"
            << " taken from them (coagulationReport.py needs samples at"
            << " t >= tRelax). Set a later endTime or an earlier tRelax"
            << nl << endl;
    }

    const fileName dir
    (
        runTime.globalPath()/"postProcessing"/"coagulationSamples"
    );
    // Every processor writes its own file: each makes sure the folder exists
    mkDir(dir);

    fileName file("samples_" + runTime.timeName());
    if (Pstream::parRun())
    {
        file += "_processor" + Foam::name(Pstream::myProcNo());
    }
    file = dir/(file + ".h5");
    file_ = file;

    const vectorField& C = mesh.C().primitiveField();
    std::vector<std::array<double, 3>> centres(C.size());
    forAll(C, celli)
    {
        centres[celli] = {C[celli].x(), C[celli].y(), C[celli].z()};
    }

    try
    {
        writer_.reset(new coag::MomentSeriesWriter(file, centres, 4));
        setAttributes(dt, interval);
    }
    catch (const std::exception& e)
    {
        FatalErrorInFunction
            << "Cannot create the sample file " << file << ": " << e.what()
            << nl << exit(FatalError);
    }

    values_.resize(4*C.size());

    Info<< "Sampling moments every " << stepsPerSample_ << " steps into "
        << dir << nl << endl;
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::coagulation::cloudFunctions::momentSampler::setAttributes
(
    const scalar dt,
    const scalar interval
)
{
    const coagulationCloud& cloud = cloud_;
    writer_->setAttribute("n", cloud.scaling().n());
    writer_->setAttribute("V1", cloud.scaling().V1());
    writer_->setAttribute("K0", cloud.kernel().K0());
    writer_->setAttribute("inceptionRate", cloud.inception().core().rate);
    writer_->setAttribute("seed", double(cloud.seeds().seed()));
    writer_->setAttribute("splitDeltaT", cloud.splitDeltaT());
    writer_->setAttribute("sampleInterval", interval);
    writer_->setAttribute("tRelax", tRelax_);
    writer_->setAttribute("particleWeight", cloud.scaling().particleWeight());
    writer_->setAttribute
    (
        "algorithm", cloud.algorithmName()
    );
    writer_->setAttribute
    (
        "kernel", cloud.properties().subDict("kernel").get<word>("type")
    );
    // The particles' material, when the case gives one: the report's diameters
    if (cloud.properties().found("particles"))
    {
        const coag::ParticleMaterial material =
            readParticleMaterial(cloud.properties(), "moment samples");
        writer_->setAttribute("density", material.density);
        writer_->setAttribute("massUnit", material.massUnit);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::coagulation::cloudFunctions::momentSampler::sample()
{
    const Time& runTime = cloud_.pMesh().time();
    if (runTime.timeIndex() % stepsPerSample_ != 0)
    {
        return;
    }

    const PtrList<volScalarField>& M = cloud_.moments();
    const label nCells = M[0].size();
    for (label celli = 0; celli < nCells; ++celli)
    {
        for (label k = 0; k < 4; ++k)
        {
            values_[4*celli + k] = M[k][celli];
        }
    }
    writer_->append(runTime.value(), values_);

    if (runTime.writeTime())
    {
        flush();
    }
}


void Foam::coagulation::cloudFunctions::momentSampler::flush()
{
    try
    {
        // This processor's jumps since the run started, real and fictitious
        // (the majorant's efficiency), with the samples they led to
        const coag::StepStatistics& events = cloud_.events();
        writer_->stageAttribute("coagulations", double(events.coagulations));
        writer_->stageAttribute("fictitious", double(events.fictitious));
        // and what growth added (negative: took) and the shrinking removed
        writer_->stageAttribute("grownMass", events.grownMass);
        writer_->stageAttribute("lostParticles", double(events.lostParticles));
        writer_->stageAttribute("lostNumber", events.lostNumber);
        writer_->stageAttribute("lostMass", events.lostMass);
        writer_->flush();
        lastFlushed_ = cloud_.pMesh().time().value();
    }
    catch (const std::exception& e)
    {
        OStringStream upTo;
        if (lastFlushed_ > -GREAT)
        {
            upTo << " (time " << Time::timeName(lastFlushed_) << ")";
        }
        FatalErrorInFunction
            << "Cannot write the samples to " << file_.c_str()
            << " (disk full?): " << e.what() << nl
            << "    The file is intact and holds the samples up to the last"
            << " write" << upTo.str().c_str() << "; restart from the latest"
            << " complete time" << nl
            << exit(FatalError);
    }
}


// ************************************************************************* //
