// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_NUMBERCONTROL_HPP
#define COAGULATION_NUMBERCONTROL_HPP

#include "coagulation/population/CellPopulation.hpp"
#include "coagulation/random/Rng.hpp"
#include "coagulation/algorithms/StepStatistics.hpp"

#include <cstddef>

namespace coag {

//- Control of the number of computational particles in one cell.
//
//  maxParticles (0 = off): whenever the number N of computational particles exceeds it
//  (checked at the start of CellAlgorithm::advance and after every inception), the cell is
//  thinned by unbiased random halving: a uniformly random subset of exactly N/2 particles is
//  kept (N odd: (N-1)/2 or (N+1)/2 with probability 1/2 each, so every particle survives with
//  probability exactly 1/2), and
//    - SWA: the weights of the survivors are doubled;
//    - DSA1/DSA2 (weights must stay equal): the sample volume pop.volume is halved instead.
//  Either way E[sum_j w_j phi(z_j) / V] is unchanged for every phi, so all moment estimators
//  stay unbiased; the price is extra variance: a halving adds, for the estimator
//  M_phi = sum_j w_j phi(z_j)/V, a conditional variance of sum_j (w_j phi(z_j)/V)^2 (roughly,
//  the variance of a cell with half the particles), i.e. the statistical error after a
//  halving is that of N/2 particles, never that of N.
//
//  minParticles (0 = off): in a closed DSA cell (inception rate 0) with 0 < N < minParticles
//  (checked at the start of advance and after every coagulation) every particle is
//  duplicated (the copies get tag -1; the caller places them) and the sample volume is
//  doubled. This is exact for the empirical measure (no bias, no added variance at that
//  moment), but the copies are correlated, so the variance keeps that of the population
//  before doubling; it only stops the DSA cell from dying out. Ignored for SWA, whose
//  coagulation never removes particles, and in cells with inception.
//
//  When both are on, maxParticles >= 2*minParticles is required (no ping-pong).
struct NumberControl {
    std::size_t maxParticles = 0;
    std::size_t minParticles = 0;
};

//- The halving above: keep a uniformly random half; equalWeights (DSA) halves pop.volume,
//  otherwise (SWA) the survivors' weights are doubled. Books the change of sum(w*m) in
//  stats.controlMass and counts the halving.
void halvePopulation(CellPopulation& pop, bool equalWeights, Rng& rng, StepStatistics& stats);

//- The doubling above: every particle copied (tag -1), pop.volume doubled; booked likewise.
void duplicatePopulation(CellPopulation& pop, StepStatistics& stats);

} // namespace coag

#endif
