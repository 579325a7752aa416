// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#include "TestHelpers.hpp"

using namespace coagtest;

TEST(RunningStatistics, MatchesTwoPassComputation)
{
    Rng rng(12);
    std::vector<double> x;
    for (int i = 0; i < 1001; ++i) x.push_back(1e6 + 3.0 * rng.exponential(1.0));
    RunningStatistics s;
    for (double v : x) s.add(v);
    double mean = 0;
    for (double v : x) mean += v;
    mean /= double(x.size());
    double ss = 0;
    for (double v : x) ss += (v - mean) * (v - mean);
    const double var = ss / double(x.size() - 1);
    EXPECT_EQ(s.count(), x.size());
    EXPECT_NEAR(s.mean(), mean, 1e-12 * mean);
    EXPECT_NEAR(s.variance(), var, 1e-9 * var);
    EXPECT_NEAR(s.m2(), ss, 1e-9 * ss);
    EXPECT_NEAR(s.standardDeviation(), std::sqrt(var), 1e-9);
    EXPECT_NEAR(s.standardError(), std::sqrt(var / double(x.size())), 1e-9);
    EXPECT_NEAR(s.confidenceHalfWidth95(), 1.96 * std::sqrt(var / double(x.size())), 1e-9);
}

TEST(RunningStatistics, MergeEqualsTheWholeSample)
{
    Rng rng(13);
    RunningStatistics all, a, b, empty;
    for (int i = 0; i < 500; ++i) {
        const double v = rng.uniform() * 10 - 3;
        all.add(v);
        (i < 137 ? a : b).add(v);
    }
    RunningStatistics m = a;
    m.merge(b);
    EXPECT_EQ(m.count(), all.count());
    EXPECT_NEAR(m.mean(), all.mean(), 1e-12);
    EXPECT_NEAR(m.variance(), all.variance(), 1e-10);
    m.merge(empty);
    EXPECT_EQ(m.count(), all.count());
    empty.merge(a);
    EXPECT_EQ(empty.count(), a.count());
    EXPECT_EQ(empty.mean(), a.mean());

    RunningStatistics restored;
    restored.set(all.count(), all.mean(), all.m2());
    EXPECT_EQ(restored.variance(), all.variance());
    EXPECT_THROW(restored.set(3, 1.0, -1.0), std::invalid_argument);
}

TEST(RunningStatistics, DegenerateCases)
{
    RunningStatistics s;
    EXPECT_EQ(s.count(), 0u);
    EXPECT_EQ(s.variance(), 0.0);
    s.add(2.0);
    EXPECT_EQ(s.mean(), 2.0);
    EXPECT_EQ(s.variance(), 0.0);
    EXPECT_EQ(s.standardError(), 0.0);
}

TEST(Moments, WeightedMassMomentsPerVolume)
{
    CellPopulation pop;
    pop.volume = 2.0;
    pop.particles.push_back(Particle{ParticleType{1.0}, 3.0, 0});
    pop.particles.push_back(Particle{ParticleType{2.0}, 0.5, 1});
    const auto m = moments(pop);
    EXPECT_DOUBLE_EQ(m[0], (3.0 + 0.5) / 2);
    EXPECT_DOUBLE_EQ(m[1], (3.0 + 1.0) / 2);
    EXPECT_DOUBLE_EQ(m[2], (3.0 + 2.0) / 2);
    EXPECT_DOUBLE_EQ(m[3], (3.0 + 4.0) / 2);
}
