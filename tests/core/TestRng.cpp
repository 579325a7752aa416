// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#include "TestHelpers.hpp"

using namespace coagtest;

TEST(Rng, UniformIsInOpenUnitIntervalWithMeanHalf)
{
    Rng rng(1);
    RunningStatistics s;
    for (int i = 0; i < 200000; ++i) {
        const double u = rng.uniform();
        ASSERT_GT(u, 0.0);
        ASSERT_LT(u, 1.0);
        s.add(u);
    }
    EXPECT_NEAR(s.mean(), 0.5, 4 * s.standardError());
    EXPECT_NEAR(s.variance(), 1.0 / 12.0, 2e-3);
}

TEST(Rng, ExponentialHasTheRequestedMean)
{
    Rng rng(2);
    RunningStatistics s;
    for (int i = 0; i < 200000; ++i) s.add(rng.exponential(4.0));
    EXPECT_NEAR(s.mean(), 0.25, 4 * s.standardError());
}

//- The ziggurat's exponential is Exp(1): its tables make 256 regions of equal area v with the
//  right parts accepted at once, and 2 million draws (fixed seed) pass the Kolmogorov-Smirnov test and a chi-square over 100
//  equiprobable bins at 0.1 %, put e^-r of themselves beyond r (the tail, 5 sd), and have
//  mean and variance 1 (5 standard errors)
TEST(Rng, ExponentialByTheZigguratIsExp1)
{
    const Rng::Ziggurat& z = Rng::ziggurat();
    const double two53 = 9007199254740992.0;
    for (int i = 1; i < 256; ++i) {
        const double x = z.w[i] * two53;  // the region's right end
        EXPECT_NEAR(x * (z.f[i - 1] - z.f[i]), Rng::Ziggurat::v, 1e-12) << i;
        EXPECT_NEAR(z.f[i], std::exp(-x), 1e-15) << i;
    }
    EXPECT_NEAR((z.w[0] * two53) * std::exp(-Rng::Ziggurat::r), Rng::Ziggurat::v, 1e-12);
    // accepted at once: the part of region i's width under the curve at every height, x_{i-1}
    // of x_i (region 1: none; the base strip: r of its width q = v e^r)
    EXPECT_EQ(z.k[1], 0u);
    for (int i = 2; i < 256; ++i) {
        EXPECT_NEAR(double(z.k[i]) / two53, z.w[i - 1] / z.w[i], 1e-12) << i;
    }
    EXPECT_NEAR(double(z.k[0]) / two53, Rng::Ziggurat::r / (z.w[0] * two53), 1e-12);

    Rng rng(2718);
    const std::size_t n = 2000000;
    std::vector<double> x(n);
    RunningStatistics s;
    std::vector<double> bins(100, 0.0);
    std::size_t tail = 0;
    for (std::size_t j = 0; j < n; ++j) {
        x[j] = rng.standardExponential();
        ASSERT_GE(x[j], 0.0);
        s.add(x[j]);
        bins[std::min<std::size_t>(99, static_cast<std::size_t>(100.0 * -std::expm1(-x[j])))] += 1;
        tail += x[j] > Rng::Ziggurat::r;
    }
    std::sort(x.begin(), x.end());
    double D = 0.0;
    for (std::size_t j = 0; j < n; ++j) {
        const double F = -std::expm1(-x[j]);
        D = std::max({D, std::abs(F - double(j) / n), std::abs(double(j + 1) / n - F)});
    }
    EXPECT_LT(D, 1.949 / std::sqrt(double(n)));  // 0.1 %
    double chi2 = 0.0;
    for (double c : bins) chi2 += (c - n / 100.0) * (c - n / 100.0) / (n / 100.0);
    EXPECT_LT(chi2, 148.2);  // 99 degrees of freedom, 0.1 %
    const double pTail = std::exp(-Rng::Ziggurat::r);
    EXPECT_NEAR(double(tail), n * pTail, 5.0 * std::sqrt(n * pTail));
    EXPECT_GT(tail, 0u);
    EXPECT_NEAR(s.mean(), 1.0, 5.0 * s.standardError());
    EXPECT_NEAR(s.variance(), 1.0, 5.0 * std::sqrt(8.0 / n));  // mu4 - sigma^4 = 9 - 1
}

TEST(Rng, UniformIndexCoversTheRangeEvenly)
{
    Rng rng(3);
    const std::uint64_t n = 7;
    std::vector<int> counts(n, 0);
    const int draws = 70000;
    for (int i = 0; i < draws; ++i) {
        const std::uint64_t j = rng.uniformIndex(n);
        ASSERT_LT(j, n);
        ++counts[j];
    }
    const double p = 1.0 / 7.0, sd = std::sqrt(draws * p * (1 - p));
    for (int c : counts) EXPECT_NEAR(c, draws * p, 4.5 * sd);
    EXPECT_EQ(rng.uniformIndex(1), 0u);
    EXPECT_THROW(rng.uniformIndex(0), std::invalid_argument);
}

TEST(Rng, StateSaveRestoreReproducesTheSequence)
{
    Rng rng(42);
    for (int i = 0; i < 1000; ++i) rng.uniform();
    const std::string saved = rng.state();
    std::vector<double> a;
    for (int i = 0; i < 100; ++i) a.push_back(rng.uniform());
    std::vector<std::uint64_t> ai;
    for (int i = 0; i < 10; ++i) ai.push_back(rng.uniformIndex(1000));

    Rng other(7);
    other.setState(saved);
    for (int i = 0; i < 100; ++i) EXPECT_EQ(other.uniform(), a[i]);
    for (int i = 0; i < 10; ++i) EXPECT_EQ(other.uniformIndex(1000), ai[i]);
    EXPECT_EQ(other.state(), rng.state());
    EXPECT_THROW(other.setState("not a state"), std::invalid_argument);
}

//- Known answers: xoshiro256++ from the state {1, 2, 3, 4} (the first is rotl(1 + 4, 23) + 1 =
//  5 * 2^23 + 1, the rest from an independent Python transcription of Blackman & Vigna's
//  reference code), and the seeding's splitmix64 words for seed 0 (its published first value
//  is 0xe220a8397b1dcdaf).
TEST(Rng, EngineGivesTheReferenceSequence)
{
    Rng::Engine e(0);
    ASSERT_TRUE(e.setWords({1, 2, 3, 4}));
    EXPECT_EQ(e(), 41943041u);
    EXPECT_EQ(e(), 58720359u);
    EXPECT_EQ(e(), 3588806011781223u);
    EXPECT_EQ(e(), 3591011842654386u);

    const Rng::Engine seeded(0);
    EXPECT_EQ(seeded.words()[0], 0xe220a8397b1dcdafULL);
    EXPECT_EQ(seeded.words()[1], 7960286522194355700u);
    EXPECT_EQ(seeded.words()[2], 487617019471545679u);
    EXPECT_EQ(seeded.words()[3], 17909611376780542444u);
    Rng::Engine copy = seeded;
    EXPECT_EQ(copy(), 5987356902031041503u);
    EXPECT_EQ(copy(), 7051070477665621255u);

    EXPECT_FALSE(e.setWords({0, 0, 0, 0}));
    Rng rng(3);
    EXPECT_THROW(rng.setState("xoshiro256++ 0 0 0 0"), std::invalid_argument);
    EXPECT_THROW(rng.setState("xoshiro256++ 1 2 3"), std::invalid_argument);
    EXPECT_THROW(rng.setState("xoshiro256++ 1 2 3 4 5"), std::invalid_argument);
}

TEST(Rng, DifferentSeedsDiffer)
{
    Rng a(1), b(2);
    EXPECT_NE(a.uniform(), b.uniform());
}

namespace {

CellPopulation runOnce(const std::string& alg, std::uint64_t seed, std::string* endState = nullptr)
{
    AdditiveKernel kernel(1.0);
    InceptionModel inception;
    inception.rate = 2.0;
    auto a = makeCellAlgorithm(alg, kernel, inception);
    Rng rng(seed);
    CellPopulation pop = monodisperse(500, 500.0);
    StepStatistics stats;
    for (int i = 0; i < 5; ++i) a->advance(pop, 0.1, rng, stats);
    if (endState) *endState = rng.state();
    return pop;
}

void expectIdentical(const CellPopulation& a, const CellPopulation& b)
{
    ASSERT_EQ(a.particles.size(), b.particles.size());
    EXPECT_EQ(a.volume, b.volume);
    for (std::size_t j = 0; j < a.particles.size(); ++j) {
        EXPECT_EQ(a.particles[j].type.mass, b.particles[j].type.mass);
        EXPECT_EQ(a.particles[j].weight, b.particles[j].weight);
        EXPECT_EQ(a.particles[j].tag, b.particles[j].tag);
    }
}

} // namespace

TEST(Rng, SameSeedGivesIdenticalResults)
{
    for (const std::string alg : {"SWA", "DSA1", "DSA2"}) {
        std::string s1, s2;
        const CellPopulation a = runOnce(alg, 99, &s1);
        const CellPopulation b = runOnce(alg, 99, &s2);
        expectIdentical(a, b);
        EXPECT_EQ(s1, s2);
        const CellPopulation c = runOnce(alg, 100);
        EXPECT_NE(moments(a)[2], moments(c)[2]) << alg;
    }
}

TEST(Rng, RestoredStateContinuesARunIdentically)
{
    ConstantKernel kernel(1.0);
    auto alg = makeCellAlgorithm("SWA", kernel, InceptionModel{1.0, {}, 1.0});
    Rng rng(5);
    CellPopulation pop = monodisperse(300, 300.0);
    StepStatistics stats;
    alg->advance(pop, 0.3, rng, stats);
    const std::string state = rng.state();
    CellPopulation copy = pop;
    alg->advance(pop, 0.3, rng, stats);

    Rng restored(0);
    restored.setState(state);
    alg->advance(copy, 0.3, restored, stats);
    expectIdentical(pop, copy);
}
