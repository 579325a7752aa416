/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "cellStepper.H"
#include "coagulationCloud.H"
#include "caseChecks.H"

#include <chrono>
#include <cmath>
#include <new>
#include <sstream>
#include <stdexcept>
#include <string>

#ifdef _OPENMP
#include <omp.h>
#endif

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coagulation::cellStepper::cellStepper
(
    coagulationCloud& cloud,
    const cellAlgorithm& algorithm,
    const cellAlgorithm& algorithmNoInception
)
:
    cloud_(cloud),
    tets_(cloud.pMesh()),
    workers_(cloud.nThreads()),
    outcomes_(),
    listRemoved_()
{
    for (worker& w : workers_)
    {
        w.algorithm = algorithm.clone();
        w.algorithmNoInception = algorithmNoInception.clone();
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::coagulation::cellStepper::advanceCell
(
    const label celli,
    const scalar dt,
    const streamSeeds::purpose stream,
    worker& w,
    cellOutcome& outcome
) const
{
    outcome.events = coag::StepStatistics();
    outcome.born.clear();
    outcome.died.clear();

    const cellParticleIndex& index = cloud_.index();
    const label start = index.cellStart()[celli];
    const label np = index.cellStart()[celli + 1] - start;
    const scalar inceptionRate = cloud_.inception().cellRate(celli);
    const bool incepts = inceptionRate > 0;
    const growthModelList& growth = cloud_.growth();
    outcome.particles = np;

    // Without inception a cell needs a pair to change, or a particle to grow
    outcome.stepped = np >= 2 || incepts || (np == 1 && growth.active());
    if (!outcome.stepped)
    {
        return;
    }

    coag::CellPopulation& population = w.population;
    population.volume = cloud_.pMesh().cellVolumes()[celli];
    population.particles.clear();
    for (label i = 0; i < np; ++i)
    {
        const coagulationParticle& p = *index.cellParticles()[start + i];
        coag::Particle cp;
        cp.type.mass = p.mass();
        cp.weight = p.weight();
        cp.tag = i;
        population.particles.push_back(cp);
    }

    // Counted in the worker, not in outcome: the outcomes of the cells that
    // the other threads are stepping share its cache lines
    w.events = coag::StepStatistics();
    w.rng.engine().seed(cloud_.seeds()(celli, stream));
    const cellAlgorithm& algorithm =
        incepts ? *w.algorithm : *w.algorithmNoInception;
    if (!growth.active())
    {
        algorithm.advance
        (
            celli, population, inceptionRate, dt, w.rng, w.events
        );
    }
    else
    {
        growth.law(celli, w.law);
        if (np == 1 && !incepts)
        {
            // A lone particle only grows: no jump process (whose number
            // control would act on it where a run without growth passes the
            // cell over)
            coag::growPopulation
            (
                population, w.law, dt, growth.minimumMass(), w.events
            );
        }
        else
        {
            algorithm.advance
            (
                celli, population, inceptionRate, w.law,
                growth.minimumMass(), dt, w.rng, w.events
            );
        }
    }
    outcome.events = w.events;

    // Write the cell's new state back: survivors in place, new particles
    // placed with the cell's stream (in population order, as they will be
    // constructed), the rest recorded as gone
    // (Growth far too fast for the mass unit can take a particle's mass, or
    // its moment w m^3, past the largest number, Inf with the traps held
    // here: named as the cell step's failure, not SIGFPE in a later sum)
    w.survived.assign(np, 0);
    for (const coag::Particle& cp : population.particles)
    {
        const double m = cp.type.mass;
        if (growth.active() && !std::isfinite(cp.weight*m*m*m))
        {
            std::ostringstream os;
            os  << "a particle of mass " << m << " (mass units) has a third"
                << " moment past the largest number";
            throw std::overflow_error(os.str());
        }
        if (cp.tag >= 0)
        {
            coagulationParticle& p = *index.cellParticles()[start + cp.tag];
            p.mass() = cp.type.mass;
            p.weight() = cp.weight;
            w.survived[cp.tag] = 1;
        }
        else
        {
            bornParticle born;
            born.mass = cp.type.mass;
            born.weight = cp.weight;
            born.place = tets_.sample(celli, w.rng);
            outcome.born.push_back(born);
        }
    }
    for (label i = 0; i < np; ++i)
    {
        if (!w.survived[i])
        {
            outcome.died.push_back(start + i);
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::coagulation::cellStepper::advance
(
    const scalar dt,
    coag::StepStatistics& events,
    label& removed,
    const streamSeeds::purpose stream
)
{
    cellParticleIndex& index = cloud_.index();
    const label nCells = cloud_.pMesh().nCells();
    index.sort(cloud_, nCells);
    outcomes_.resize(nCells);

    // The cells are independent jump processes: share them among the
    // threads (the largest cells, downstream on a duct, are not known in
    // advance, so cells are handed out one at a time)
    std::string failure;
    bool outOfMemory = false;
    #pragma omp parallel num_threads(cloud_.nThreads())
    {
        // OpenFOAM's floating-point traps held over the thread's share of
        // the cells (an overflow in a jump process gives Inf, which the
        // algorithm's checks name), set once per thread rather than per
        // cell (setting the floating-point environment is not cheap). The
        // write-back and the placing of new particles (finite arithmetic on
        // checked values) run with them held too
        const caseChecks::trapsHeld traps;
        #pragma omp for schedule(dynamic, 1)
        for (label celli = 0; celli < nCells; ++celli)
        {
            #ifdef _OPENMP
            worker& w = workers_[omp_get_thread_num()];
            #else
            worker& w = workers_[0];
            #endif
            try
            {
                if (timed_)
                {
                    using clock = std::chrono::steady_clock;
                    const clock::time_point t0 = clock::now();
                    advanceCell(celli, dt, stream, w, outcomes_[celli]);
                    outcomes_[celli].seconds =
                        std::chrono::duration<double>
                        (
                            clock::now() - t0
                        ).count();
                }
                else
                {
                    advanceCell(celli, dt, stream, w, outcomes_[celli]);
                }
            }
            catch (const std::bad_alloc&)
            {
                #pragma omp atomic write
                outOfMemory = true;
            }
            catch (const std::exception& e)
            {
                #pragma omp critical(cellStepFailure)
                if (failure.empty())
                {
                    failure =
                        "cell " + std::to_string(celli) + ": " + e.what();
                }
            }
        }
    }
    if (outOfMemory)
    {
        // Out of the threads: the solver names the particle count
        throw std::bad_alloc();
    }
    if (!failure.empty())
    {
        FatalErrorInFunction
            << "Cell step failed at time "
            << cloud_.pMesh().time().timeName() << " in " << failure << nl
            << "    Check the kernel (K0), the inception rate, the growth"
            << " models and deltaT in "
            << cloud_.properties().objectPath() << " and "
            << cloud_.pMesh().time().controlDict().name() << nl
            << exit(FatalError);
    }

    // Serially, in cell order: book the events, construct the new particles
    // (ids are handed out in order) and delete the ones that are gone
    listRemoved_.assign(index.particles().size(), 0);
    for (label celli = 0; celli < nCells; ++celli)
    {
        for (const label i : outcomes_[celli].died)
        {
            listRemoved_[index.cellListIndex()[i]] = 1;
        }
    }
    index.compact(listRemoved_);

    for (label celli = 0; celli < nCells; ++celli)
    {
        const cellOutcome& outcome = outcomes_[celli];
        events += outcome.events;
        grownSum_.add(outcome.events.grownMass);
        lostNumberSum_.add(outcome.events.lostNumber);
        lostMassSum_.add(outcome.events.lostMass);
        workSum_ += work(celli);

        // Particles removed in the cell: DSA merges (including any
        // incepted and merged away within this step), halvings, and those
        // gone by shrinking
        removed +=
            label(outcome.events.inceptions) - label(outcome.born.size())
          + label(outcome.died.size());

        for (const bornParticle& born : outcome.born)
        {
            coagulationParticle* pPtr = new coagulationParticle
            (
                cloud_.pMesh(),
                born.place.coordinates,
                celli,
                born.place.tetFace,
                born.place.tetPt,
                born.mass,
                born.weight
            );
            cloud_.addParticle(pPtr);
            index.append(pPtr, celli);
        }
        for (const label i : outcome.died)
        {
            cloud_.deleteParticle(*index.cellParticles()[i]);
        }
    }
    // The growth's run totals, compensated: a uniform case adds near-equal
    // terms cells times steps over
    events.grownMass = grownSum_.value();
    events.lostNumber = lostNumberSum_.value();
    events.lostMass = lostMassSum_.value();
    index.invalidateSort();
}


// ************************************************************************* //
