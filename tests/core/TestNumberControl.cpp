// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
// Number control (halving with weight doubling / volume halving, DSA doubling) must not bias
// the moments: controlled and uncontrolled ensemble means agree within their uncertainties.
#include "TestHelpers.hpp"

using namespace coagtest;

namespace {

void expectSameMeans(const EnsembleResult& a, const EnsembleResult& b,
                     const std::vector<double>& times, int nMoments, const std::string& what)
{
    for (std::size_t i = 0; i < times.size(); ++i) {
        for (int k = 0; k < nMoments; ++k) {
            const RunningStatistics& x = a.moments[i][k];
            const RunningStatistics& y = b.moments[i][k];
            const double se = std::hypot(x.standardError(), y.standardError());
            EXPECT_NEAR(x.mean(), y.mean(), 4 * se + 1e-9 * std::abs(y.mean()))
                << what << ": M" << k << " at t = " << times[i];
        }
    }
}

} // namespace

TEST(NumberControl, SwaHalvingWithSourceIsUnbiased)
{
    const double K0 = 1.0, I = 1.0, V = 500.0;
    ConstantKernel kernel(K0);
    InceptionModel inception{I, {}, 1.0};
    const std::vector<double> times{1.0, 2.0};
    auto init = [&] {
        CellPopulation pop;
        pop.volume = V;
        return pop;
    };
    auto exact = [&](double t) { return exact::constantKernelSourceMoments(K0, I, t); };
    NumberControl ctl;
    ctl.maxParticles = 256;  // uncontrolled SWA reaches ~1000 particles by t = 2
    const auto controlled = runEnsemble("SWA", kernel, inception, ctl, init, times, 400, 41);
    const auto free = runEnsemble("SWA", kernel, inception, {}, init, times, 400, 42);
    EXPECT_GT(controlled.steps.halvings, 400u);
    EXPECT_EQ(free.steps.halvings, 0u);
    expectSameMeans(controlled, free, times, 4, "SWA halving");
    expectMomentsMatch(controlled, times, exact, 4, "SWA halving vs exact");
}

TEST(NumberControl, SwaHalvingOnEntryDoublesWeights)
{
    ConstantKernel kernel(1.0);
    NumberControl ctl;
    ctl.maxParticles = 100;
    auto alg = makeCellAlgorithm("SWA", kernel, InceptionModel{}, ctl);
    Rng rng(3);
    CellPopulation pop = monodisperse(301, 301.0);
    StepStatistics stats;
    alg->advance(pop, 0.0, rng, stats);
    EXPECT_EQ(stats.halvings, 2u);
    EXPECT_GE(pop.particles.size(), 75u);
    EXPECT_LE(pop.particles.size(), 76u);
    for (const Particle& p : pop.particles) EXPECT_EQ(p.weight, 4.0);
    EXPECT_EQ(pop.volume, 301.0);
}

TEST(NumberControl, HalvingKeepsEachParticleWithProbabilityOneHalf)
{
    // Odd N: (N-1)/2 or (N+1)/2 survivors with probability 1/2 each, so E[sum w] is unchanged.
    ConstantKernel kernel(1.0);
    NumberControl ctl;
    ctl.maxParticles = 100;
    const std::size_t N = 101;
    auto alg = makeCellAlgorithm("SWA", kernel, InceptionModel{}, ctl);
    Rng rng(17);
    RunningStatistics totalWeight;
    std::vector<int> kept(N, 0);
    const int trials = 20000;
    for (int i = 0; i < trials; ++i) {
        CellPopulation pop = monodisperse(N, 1.0);
        StepStatistics stats;
        alg->advance(pop, 0.0, rng, stats);
        ASSERT_EQ(stats.halvings, 1u);
        double w = 0;
        for (const Particle& p : pop.particles) {
            w += p.weight;
            ++kept[static_cast<std::size_t>(p.tag)];
        }
        totalWeight.add(w);
    }
    EXPECT_NEAR(totalWeight.mean(), double(N), 4 * totalWeight.standardError());
    const double sd = std::sqrt(trials * 0.25);
    for (std::size_t j = 0; j < N; ++j) EXPECT_NEAR(kept[j], trials / 2.0, 4.5 * sd) << "particle " << j;
}

TEST(NumberControl, DsaVolumeHalvingWithSourceIsUnbiased)
{
    const double K0 = 1.0, I = 1.0, V = 500.0;
    ConstantKernel kernel(K0);
    InceptionModel inception{I, {}, 1.0};
    const std::vector<double> times{1.0, 2.0};
    auto init = [&] {
        CellPopulation pop;
        pop.volume = V;
        return pop;
    };
    auto exact = [&](double t) { return exact::constantKernelSourceMoments(K0, I, t); };
    NumberControl ctl;
    ctl.maxParticles = 200;  // uncontrolled DSA reaches ~600 particles
    for (const std::string alg : {"DSA1", "DSA2"}) {
        const auto controlled = runEnsemble(alg, kernel, inception, ctl, init, times, 400, 43);
        const auto free = runEnsemble(alg, kernel, inception, {}, init, times, 400, 44);
        EXPECT_GT(controlled.steps.halvings, 400u) << alg;
        expectSameMeans(controlled, free, times, 4, alg + " volume halving");
        expectMomentsMatch(controlled, times, exact, 4, alg + " volume halving vs exact");
    }
}

TEST(NumberControl, ClosedDsaDoublingIsUnbiased)
{
    const double K0 = 1.0, N0 = 1.0;
    ConstantKernel kernel(K0);
    const std::vector<double> times{2.0, 6.0, 14.0};  // N(t) ~ 400/(1 + t/2): 50 at t = 14
    auto init = [&] { return monodisperse(400, 400.0); };
    auto exact = [&](double t) { return exact::constantKernelMoments(K0, N0, t); };
    NumberControl ctl;
    ctl.minParticles = 120;
    for (const std::string alg : {"DSA1", "DSA2"}) {
        const auto controlled = runEnsemble(alg, kernel, {}, ctl, init, times, 400, 45);
        const auto free = runEnsemble(alg, kernel, {}, {}, init, times, 400, 46);
        EXPECT_GE(controlled.steps.doublings, 400u) << alg;
        EXPECT_EQ(free.steps.doublings, 0u);
        expectSameMeans(controlled, free, times, 3, alg + " doubling");
        expectMomentsMatch(controlled, times, exact, 3, alg + " doubling vs exact");
    }
}

TEST(NumberControl, DoublingCopiesParticlesAndVolume)
{
    ConstantKernel kernel(1.0);
    NumberControl ctl;
    ctl.minParticles = 10;
    auto alg = makeCellAlgorithm("DSA1", kernel, InceptionModel{}, ctl);
    Rng rng(1);
    CellPopulation pop = monodisperse(3, 3.0);
    StepStatistics stats;
    alg->advance(pop, 0.0, rng, stats);
    EXPECT_EQ(stats.doublings, 2u);
    EXPECT_EQ(pop.particles.size(), 12u);
    EXPECT_EQ(pop.volume, 12.0);
    int created = 0;
    for (const Particle& p : pop.particles) created += p.tag == -1;
    EXPECT_EQ(created, 9);
    EXPECT_DOUBLE_EQ(moments(pop)[0], 1.0);
}
