// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#include "coagulation/algorithms/NumberControl.hpp"

#include <utility>

namespace coag {

namespace {

//- sum_j w_j m_j: the physical mass a population stands for (per unit sample volume V)
double physicalMass(const ParticleVector& P)
{
    double s = 0.0;
    for (const Particle& p : P) s += p.weight * p.type.mass;
    return s;
}

} // namespace

void halvePopulation(CellPopulation& pop, bool equalWeights, Rng& rng, StepStatistics& stats)
{
    ParticleVector& P = pop.particles;
    const std::size_t n = P.size();
    const double massBefore = physicalMass(P);
    std::size_t keep = n / 2;
    if ((n % 2) == 1 && rng.uniform() < 0.5) ++keep;
    // Partial Fisher-Yates: the first `keep` entries become a uniform random subset.
    for (std::size_t i = 0; i < keep; ++i) {
        const std::size_t j = i + static_cast<std::size_t>(rng.uniformIndex(n - i));
        if (j != i) std::swap(P[i], P[j]);
    }
    P.erase(P.begin() + static_cast<std::ptrdiff_t>(keep), P.end());
    if (equalWeights) {
        pop.volume *= 0.5;
    } else {
        for (Particle& p : P) p.weight *= 2.0;
    }
    // Unbiased, but not conservative: the change is booked for mass balances
    stats.controlMass += physicalMass(P) - massBefore;
    ++stats.halvings;
}

void duplicatePopulation(CellPopulation& pop, StepStatistics& stats)
{
    ParticleVector& P = pop.particles;
    const std::size_t n = P.size();
    const double massBefore = physicalMass(P);
    P.reserve(2 * n);
    for (std::size_t i = 0; i < n; ++i) {
        Particle c = P[i];
        c.tag = -1;
        P.push_back(c);
    }
    pop.volume *= 2.0;
    stats.controlMass += physicalMass(P) - massBefore;
    ++stats.doublings;
}

} // namespace coag
