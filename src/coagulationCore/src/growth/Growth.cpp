// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#include "coagulation/growth/Growth.hpp"
#include "coagulation/statistics/CompensatedSum.hpp"

namespace coag {

void growPopulation(CellPopulation& pop, const GrowthLaw& law, double dt, double minMass,
                    StepStatistics& stats)
{
    // Without a law nothing changes but the removal of particles at or below the minimum
    if (law.empty() && !(minMass > 0.0)) return;
    ParticleVector& P = pop.particles;
    // Compensated: the particles of a cell are often of one size, their terms equal
    CompensatedSum grown, lostNumber, lostMass;
    std::size_t kept = 0;
    for (std::size_t i = 0; i < P.size(); ++i) {
        Particle p = P[i];
        const GrowthLaw::Step step = law.advance(p.type.mass, dt, minMass);
        grown.add(p.weight * (step.mass - p.type.mass));
        if (step.gone) {
            ++stats.lostParticles;
            lostNumber.add(p.weight);
            lostMass.add(p.weight * step.mass);
            continue;
        }
        p.type.mass = step.mass;
        P[kept++] = p;
    }
    P.resize(kept);
    stats.grownMass += grown.value();
    stats.lostNumber += lostNumber.value();
    stats.lostMass += lostMass.value();
}

void advanceWithGrowth(CellAlgorithm& algorithm, CellPopulation& pop,
                       const CoagulationKernel& kernel, double inceptionRate,
                       const GrowthLaw& law, double minMass, double dt, Rng& rng,
                       StepStatistics& stats)
{
    // No law and no minimum: the jump process alone (a law may be empty in some cells only,
    // where the minimum still removes what is at or below it)
    if (law.empty() && !(minMass > 0.0)) {
        algorithm.advance(pop, kernel, inceptionRate, dt, rng, stats);
        return;
    }
    growPopulation(pop, law, 0.5 * dt, minMass, stats);
    algorithm.advance(pop, kernel, inceptionRate, dt, rng, stats);
    growPopulation(pop, law, 0.5 * dt, minMass, stats);
}

} // namespace coag
