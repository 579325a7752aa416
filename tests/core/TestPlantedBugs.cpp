// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
// Paths that planted bugs went through unnoticed: each test below fails on one
// such one-line bug and is deterministic (fixed seeds, or an exactly constructed state).
#include "TestHelpers.hpp"

#include <sstream>

using namespace coagtest;

namespace {

class PlantedBugCellTest : public ::testing::TestWithParam<std::string> {};

//- With number control on, the cell never holds more than maxParticles particles after
//  advance, however strong the inception (the halving after every inception keeps it there,
//  not only the halving on entry). During the step the work memory (the sum tree, sized for
//  at most maxParticles + 1 particles) must not grow either: it stays at most that of a cell
//  that simply starts with maxParticles particles.
TEST_P(PlantedBugCellTest, ParticleBoundHoldsAfterInception)
{
    const std::size_t maxParticles = 64;
    const double w = 1.0;
    AdditiveKernel kernel(1e-3);                        // tree columns for every algorithm
    InceptionModel inception;
    inception.rate = 2e4;  // V = 1, dt = 0.5: ~1e4 inceptions in the first step
    inception.weight = w;
    NumberControl ctl;
    ctl.maxParticles = maxParticles;

    // Reference work memory: a cell that starts at the bound, one short step.
    std::size_t boundBytes = 0;
    {
        auto ref = makeCellAlgorithm(GetParam(), kernel, inception, ctl);
        CellPopulation pop = monodisperse(maxParticles, 1.0, w);
        Rng rng(1);
        StepStatistics stats;
        ref->advance(pop, 1e-9, rng, stats);
        boundBytes = ref->workspaceBytes();
        ASSERT_GT(boundBytes, 0u);
    }

    auto alg = makeCellAlgorithm(GetParam(), kernel, inception, ctl);
    Rng rng(seedFor(2101, 0));
    CellPopulation pop;
    pop.volume = 1.0;
    StepStatistics stats;
    for (int step = 0; step < 4; ++step) {
        alg->advance(pop, 0.5, rng, stats);
        ASSERT_LE(pop.particles.size(), maxParticles) << GetParam() << " after step " << step;
        ASSERT_GT(pop.particles.size(), 0u) << GetParam() << " after step " << step;
        EXPECT_LE(alg->workspaceBytes(), boundBytes)
            << GetParam() << ": the work memory grew past the bound during step " << step;
    }
    // DSA halves the volume, and with it the inception rate, so it inceps far less than SWA
    EXPECT_GT(stats.inceptions, 4 * maxParticles) << GetParam();
    EXPECT_GE(stats.halvings, 5u) << GetParam();
}

//- maxParticles is the largest count a cell may hold: the halving comes when an inception
//  takes the cell past it, to maxParticles + 1, never at maxParticles itself. A cell growing by
//  inception alone (a negligible kernel), in steps short enough for at most one inception each
//  (0.01 expected per step), holds exactly maxParticles after some step before its first
//  halving; halving at >= maxParticles would stop it at maxParticles - 1. The first halving
//  then leaves (maxParticles + 1)/2 rounded down or up.
TEST_P(PlantedBugCellTest, CellReachesTheBoundExactlyBeforeItsFirstHalving)
{
    const std::size_t maxParticles = 16;
    ConstantKernel kernel(1e-12);
    InceptionModel inception;
    inception.rate = 1.0;  // V = 1, dt = 0.01: 0.01 inceptions expected per step
    NumberControl ctl;
    ctl.maxParticles = maxParticles;
    auto alg = makeCellAlgorithm(GetParam(), kernel, inception, ctl);
    Rng rng(seedFor(2105, 0));
    CellPopulation pop;
    pop.volume = 1.0;
    StepStatistics stats;
    std::size_t largest = 0;
    int steps = 0;
    for (; steps < 100000 && stats.halvings == 0; ++steps) {
        alg->advance(pop, 0.01, rng, stats);
        if (stats.halvings == 0) largest = std::max(largest, pop.particles.size());
    }
    ASSERT_EQ(stats.halvings, 1u) << GetParam() << " after " << steps << " steps";
    EXPECT_EQ(stats.coagulations, 0u) << GetParam();
    EXPECT_EQ(largest, maxParticles) << GetParam() << ": the largest count before the first halving";
    EXPECT_GE(pop.particles.size(), maxParticles / 2) << GetParam();
    EXPECT_LE(pop.particles.size(), maxParticles / 2 + 1) << GetParam();
}

//- The incepted mass is sum(weight * mass) of the incepted particles, also for an inception
//  weight other than 1, and it is exactly the growth of the represented mass (no number
//  control). weight 2.5, mass 0.75: every product and partial sum is exact in binary.
TEST_P(PlantedBugCellTest, InceptedMassCountsTheInceptionWeight)
{
    const double w = 2.5, m = 0.75;
    ConstantKernel kernel(1.0);
    InceptionModel inception;
    inception.rate = 40.0;
    inception.weight = w;
    inception.type.mass = m;
    auto alg = makeCellAlgorithm(GetParam(), kernel, inception);
    Rng rng(seedFor(2103, 0));
    CellPopulation pop = monodisperse(100, 250.0, w);  // DSA: weights = inception weight
    const double m0 = totalMass(pop);
    StepStatistics stats;
    for (int step = 0; step < 5; ++step) alg->advance(pop, 0.2, rng, stats);
    ASSERT_GT(stats.inceptions, 100u) << GetParam();
    ASSERT_GT(stats.coagulations, 10u) << GetParam();
    EXPECT_EQ(stats.inceptedMass, static_cast<double>(stats.inceptions) * w * m) << GetParam();
    const double added = totalMass(pop) - m0;
    EXPECT_NEAR(stats.inceptedMass, added, 1e-12 * totalMass(pop)) << GetParam();
}

INSTANTIATE_TEST_SUITE_P(Algorithms, PlantedBugCellTest, ::testing::Values("SWA", "DSA1", "DSA2"),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

} // namespace

//- The solver sums the cells' tallies with operator+=: every field must be added.
TEST(StepStatistics, PlusEqualsAddsEveryField)
{
    StepStatistics a;
    a.coagulations = 1;
    a.fictitious = 2;
    a.inceptions = 3;
    a.halvings = 4;
    a.doublings = 5;
    a.inceptedMass = 0.5;
    a.controlMass = -0.25;
    StepStatistics b;
    b.coagulations = 10;
    b.fictitious = 200;
    b.inceptions = 3000;
    b.halvings = 40000;
    b.doublings = 500000;
    b.inceptedMass = 6.25;
    b.controlMass = 1.5;

    StepStatistics& r = (a += b);
    EXPECT_EQ(&r, &a);
    EXPECT_EQ(a.coagulations, 11u);
    EXPECT_EQ(a.fictitious, 202u);
    EXPECT_EQ(a.inceptions, 3003u);
    EXPECT_EQ(a.halvings, 40004u);
    EXPECT_EQ(a.doublings, 500005u);
    EXPECT_EQ(a.inceptedMass, 6.75);
    EXPECT_EQ(a.controlMass, 1.25);
    // the right-hand side is unchanged
    EXPECT_EQ(b.coagulations, 10u);
    EXPECT_EQ(b.inceptedMass, 6.25);

    // Summing real per-cell tallies gives the tally of all events.
    ConstantKernel kernel(1.0);
    InceptionModel inception{1.0, {}, 1.0};
    NumberControl ctl;
    ctl.maxParticles = 40;
    ctl.minParticles = 20;
    StepStatistics total, together;
    for (const std::string name : {"SWA", "DSA1"}) {
        auto alg = makeCellAlgorithm(name, kernel, name == "SWA" ? inception : InceptionModel{},
                                     ctl);
        Rng rng(seedFor(2102, name == "SWA" ? 0 : 1));
        CellPopulation pop = monodisperse(100, 100.0);
        StepStatistics cell;
        alg->advance(pop, 30.0, rng, cell);
        total += cell;
        Rng again(seedFor(2102, name == "SWA" ? 0 : 1));
        CellPopulation pop2 = monodisperse(100, 100.0);
        alg->advance(pop2, 30.0, again, together);  // advance accumulates into its argument
    }
    EXPECT_GT(total.coagulations, 0u);
    EXPECT_GT(total.inceptions, 0u);
    EXPECT_GT(total.halvings, 0u);
    EXPECT_GT(total.doublings, 0u);
    EXPECT_GT(total.inceptedMass, 0.0);
    EXPECT_EQ(total.coagulations, together.coagulations);
    EXPECT_EQ(total.fictitious, together.fictitious);
    EXPECT_EQ(total.inceptions, together.inceptions);
    EXPECT_EQ(total.halvings, together.halvings);
    EXPECT_EQ(total.doublings, together.doublings);
    EXPECT_EQ(total.inceptedMass, together.inceptedMass);
    EXPECT_NE(total.controlMass, 0.0);
    EXPECT_EQ(total.controlMass, together.controlMass);
}

//- Doubling (2.20) happens when sum N_l <= N/2, equality included. Two monomers, constant
//  kernel, alpha = 1: each reacts with probability 1/2; when exactly one reaction happens
//  (the two monomers merge) one particle of size 2 is left, exactly N/2, so the step must
//  double it (2 particles of size 2, c doubled). The seeds below give that case several
//  times (each with probability 1/2); the test checks that it was hit at all.
TEST(NanbuPlantedBugs, DoublingThresholdIsInclusive)
{
    ConstantKernel kernel(1.0);
    NanbuParameters params;
    params.alpha = 1.0;
    int hits = 0;
    for (std::uint64_t s = 0; s < 32; ++s) {
        NanbuSmoluchowski nanbu(kernel, {2}, 1.0, params);
        Rng rng(seedFor(2104, s));
        nanbu.step(rng);
        const NanbuStatistics& st = nanbu.statistics();
        if (st.reactions != 1) continue;  // 0: nothing happens; 2: truncation, 2 left
        ++hits;
        EXPECT_EQ(st.truncatedComponents, 0u) << "seed " << s;
        EXPECT_EQ(st.doublings, 1u) << "seed " << s << ": sum N_l = N/2 must double";
        EXPECT_EQ(nanbu.count(1), 0) << "seed " << s;
        EXPECT_EQ(nanbu.count(2), 2) << "seed " << s;
        EXPECT_EQ(nanbu.totalCount(), 2) << "seed " << s;
        EXPECT_EQ(nanbu.normalization(), 2.0) << "seed " << s;
    }
    ASSERT_GT(hits, 3) << "the threshold case sum N_l = N/2 was never reached";
}

//- Delta_k (2.12) takes the maximum over all sizes i <= min(2^k L0, maxSize), not only the
//  occupied ones. With the additive kernel sum_j N_j K_ij grows with i, so the maximum sits at
//  the end of the range, which after a few steps lies well beyond the largest occupied size.
TEST(NanbuPlantedBugs, TimeStepUsesTheWholeSizeRange)
{
    AdditiveKernel kernel(1.0);
    NanbuParameters params;
    params.alpha = 0.02;
    params.maxSize = 1000;  // the range reaches the cap: 1, 2, 4, ..., 512, 1000
    NanbuSmoluchowski nanbu(kernel, {20000}, 20000.0, params);
    const std::size_t L0 = 1;
    Rng rng(seedFor(2105, 0));
    int beyond = 0;
    for (int k = 0; k < 12; ++k) {
        const std::size_t range = cappedDoublingRange(L0, nanbu.stepIndex(), params.maxSize);
        const std::size_t largest = nanbu.largestSize();
        ASSERT_LE(largest, range);
        if (range > largest) ++beyond;
        double maxRate = 0.0;
        for (std::size_t i = 1; i <= range; ++i) {
            double s = 0.0;
            for (std::size_t m = 1; m <= largest; ++m) {
                if (nanbu.count(m) > 0) {
                    s += static_cast<double>(nanbu.count(m))
                         * kernel(ParticleType{double(i)}, ParticleType{double(m)});
                }
            }
            maxRate = std::max(maxRate, s);
        }
        const double expected = params.alpha * nanbu.normalization() / maxRate;
        const double delta = nanbu.step(rng);
        EXPECT_NEAR(delta, expected, 1e-12 * expected)
            << "step " << k << ": range " << range << ", largest occupied size " << largest;
    }
    EXPECT_GE(beyond, 8);
}

namespace {

//- An Rng whose next raw 64-bit output is `raw`. xoshiro256++ outputs rotl(s0 + s3, 23) + s0:
//  with s0 = 0 and s3 = rotr(raw, 23) that is raw (s1 = s2 = 1 keep the state non-zero).
//  Asserts on a copy of the engine that the crafted state does give `raw`.
Rng rngWithNextRawOutput(std::uint64_t raw)
{
    Rng rng(1);
    const std::uint64_t s3 = (raw >> 23) | (raw << 41);
    std::ostringstream out;
    out << "xoshiro256++ 0 1 1 " << s3;
    rng.setState(out.str());
    Rng::Engine copy = rng.engine();
    EXPECT_EQ(copy(), raw) << "crafted state does not give the raw output";
    return rng;
}

} // namespace

TEST(RngPlantedBugs, CraftedStateGivesTheChosenOutput)
{
    // an output of the engine itself, and the extremes
    Rng::Engine e(7);
    const std::uint64_t out = e();
    for (const std::uint64_t raw : {out, std::uint64_t(0), ~std::uint64_t(0)}) {
        Rng rng = rngWithNextRawOutput(raw);
        Rng::Engine crafted = rng.engine();
        EXPECT_EQ(crafted(), raw);
    }
}

//- A raw output of 0 must not give uniform() == 0 (an infinite exponential waiting time).
TEST(RngPlantedBugs, UniformIsPositiveAtRawZero)
{
    Rng rng = rngWithNextRawOutput(0);
    const double u = rng.uniform();
    EXPECT_GT(u, 0.0);
    EXPECT_LT(u, 1.0);
    EXPECT_EQ(u, std::ldexp(1.0, -54));  // 53 bits, centred in their bin: (0 + 1/2) 2^-53

    // the waiting time from the same word: the ziggurat takes region 0 and abscissa 0 (a zero
    // waiting time, finite; with -log(u) it was 54 ln 2)
    Rng rng2 = rngWithNextRawOutput(0);
    const double t = rng2.exponential(1.0);
    EXPECT_TRUE(std::isfinite(t)) << t;
    EXPECT_EQ(t, 0.0);

    // the smallest raw value that does not share uniform()'s lowest bin
    Rng rng3 = rngWithNextRawOutput(std::uint64_t(1) << 11);
    EXPECT_EQ(rng3.uniform(), 3.0 * std::ldexp(1.0, -54));
}

//- The top bin: (2^53 - 1 + 1/2) 2^-53 rounds to 1 in double precision; uniform() must stay
//  below 1 (a zero waiting time, a point at the very end of a tree's total), and every other
//  bin keeps its value (so that seeded results do not change).
TEST(RngPlantedBugs, UniformIsBelowOneAtRawMaximum)
{
    for (const std::uint64_t raw : {~std::uint64_t(0), ~std::uint64_t(0) << 11}) {
        Rng rng = rngWithNextRawOutput(raw);
        const double u = rng.uniform();
        EXPECT_LT(u, 1.0) << std::hex << raw;
        EXPECT_EQ(u, 1.0 - std::ldexp(1.0, -53));  // the largest double below 1
        Rng rng2 = rngWithNextRawOutput(raw);
        EXPECT_GT(rng2.exponential(1.0), 0.0);
    }
    // the bin below the top one is unchanged: (2^53 - 2 + 1/2) 2^-53
    Rng rng = rngWithNextRawOutput((~std::uint64_t(0) << 11) - (std::uint64_t(1) << 11));
    EXPECT_EQ(rng.uniform(), (9007199254740990.0 + 0.5) * std::ldexp(1.0, -53));
}
