// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
// Nanbu-type method (Kolodko-Sabelfeld-Wagner §2.1) and its finite-difference limit.
#include "TestHelpers.hpp"

using namespace coagtest;

namespace {

struct NanbuError {
    double density = 0.0;  //!< max_l |N_l/c_k - nhat_l(t_k)| / sum_l nhat_l(t_k), run average
    double time = 0.0;     //!< |t_k^(N) - t_k| / t_k, run average
};

//- Nanbu (constant kernel, monomers) against the FD scheme after `steps` steps, R runs.
NanbuError nanbuVersusFd(std::int64_t N, int R, int steps, double alpha, std::uint64_t seed)
{
    ConstantKernel kernel(1.0);
    NanbuParameters params;
    params.alpha = alpha;
    params.maxSize = 256;
    FiniteDifferenceSmoluchowski fd(kernel, {1.0}, alpha, params.maxSize);
    for (int k = 0; k < steps; ++k) fd.step();
    const double fdTotal = fd.densities().sum();

    NanbuError e;
    for (int r = 0; r < R; ++r) {
        Rng rng(seedFor(seed, static_cast<std::uint64_t>(r)));
        auto nanbu = NanbuSmoluchowski::fromDensity(kernel, {1.0}, N, params);
        for (int k = 0; k < steps; ++k) nanbu.step(rng);
        EXPECT_EQ(nanbu.stepIndex(), fd.stepIndex());
        double err = 0.0;
        for (std::size_t l = 1; l <= params.maxSize; ++l) {
            err = std::max(err, std::abs(nanbu.density(l) - fd.density(l)));
        }
        e.density += err / fdTotal / R;
        // the random times t_k^(N) approach the deterministic t_k as well
        e.time += std::abs(nanbu.time() - fd.time()) / fd.time() / R;
    }
    return e;
}

} // namespace

TEST(Nanbu, ConvergesToTheFiniteDifferenceScheme)
{
    const NanbuError small = nanbuVersusFd(1000, 20, 10, 0.5, 1);
    const NanbuError large = nanbuVersusFd(100000, 20, 10, 0.5, 2);
    // statistical error ~ N^{-1/2}: expected ratio 10; demand 4
    EXPECT_LT(large.density, small.density / 4)
        << "N = 1e3: " << small.density << ", N = 1e5: " << large.density;
    EXPECT_LT(large.time, small.time / 4) << "N = 1e3: " << small.time << ", N = 1e5: " << large.time;
    EXPECT_LT(large.density, 0.01);
    EXPECT_LT(large.time, 0.01);
}

TEST(Nanbu, DoublingAndTruncationHappen)
{
    // Few particles and a large alpha: partners of rare sizes are over-drawn (truncation).
    ConstantKernel kernel(1.0);
    NanbuParameters params;
    params.alpha = 1.0;
    NanbuStatistics total;
    for (int r = 0; r < 20; ++r) {
        Rng rng(seedFor(3, static_cast<std::uint64_t>(r)));
        auto nanbu = NanbuSmoluchowski::fromDensity(kernel, {1.0}, 60, params);
        for (int k = 0; k < 8; ++k) {
            nanbu.step(rng);
            for (std::size_t l = 1; l <= nanbu.largestSize(); ++l) ASSERT_GE(nanbu.count(l), 0);
        }
        total.doublings += nanbu.statistics().doublings;
        total.truncatedComponents += nanbu.statistics().truncatedComponents;
        total.reactions += nanbu.statistics().reactions;
    }
    EXPECT_GT(total.doublings, 20u);
    EXPECT_GT(total.truncatedComponents, 0u);
    EXPECT_GT(total.reactions, 0u);
}

TEST(Nanbu, DoublingDoublesCountsAndNormalization)
{
    ConstantKernel kernel(1.0);
    NanbuParameters params;
    params.alpha = 0.5;
    auto nanbu = NanbuSmoluchowski::fromDensity(kernel, {2.0}, 1000, params);
    EXPECT_DOUBLE_EQ(nanbu.normalization(), 500.0);  // c0 = N / sum n0 (2.23)
    Rng rng(9);
    std::uint64_t doublings = 0;
    for (int k = 0; k < 20; ++k) {
        const double c = nanbu.normalization();
        nanbu.step(rng);
        if (nanbu.statistics().doublings > doublings) {
            ++doublings;
            EXPECT_EQ(nanbu.normalization(), 2 * c);
            EXPECT_EQ(nanbu.totalCount() % 2, 0);
            EXPECT_LE(nanbu.totalCount(), 1000);  // doubled from <= N/2 (2.20)
        } else {
            EXPECT_EQ(nanbu.normalization(), c);
            EXPECT_GT(2 * nanbu.totalCount(), 1000);
        }
    }
    EXPECT_GT(doublings, 3u);
    EXPECT_EQ(nanbu.normalization(), 500.0 * std::pow(2.0, double(doublings)));
}

TEST(Nanbu, MassIsConservedUpToTruncationAndDoubling)
{
    // Without truncation, sum_l l N_l/c_k is conserved exactly (doubling rescales both).
    AdditiveKernel kernel(1.0);
    NanbuParameters params;
    params.alpha = 0.05;  // truncation practically impossible with 1e5 particles
    auto nanbu = NanbuSmoluchowski::fromDensity(kernel, {1.0, 0.5}, 100000, params);
    auto mass = [&] {
        double m = 0;
        const auto d = nanbu.densities();
        for (std::size_t l = 0; l < d.size(); ++l) m += double(l + 1) * d[l];
        return m;
    };
    const double m0 = mass();
    Rng rng(10);
    for (int k = 0; k < 30; ++k) nanbu.step(rng);
    EXPECT_EQ(nanbu.statistics().truncatedComponents, 0u);
    EXPECT_EQ(nanbu.statistics().overflowParticles, 0u);
    EXPECT_NEAR(mass(), m0, 1e-12 * m0);
    EXPECT_GT(nanbu.time(), 0.0);
}

TEST(FiniteDifference, ConvergesToTheExactSolutionAsAlphaShrinks)
{
    ConstantKernel kernel(1.0);
    const double T = 2.0;
    double errors[3];
    const double alphas[3] = {0.2, 0.05, 0.0125};
    for (int a = 0; a < 3; ++a) {
        FiniteDifferenceSmoluchowski fd(kernel, {1.0}, alphas[a], 128);
        double err = 0.0;
        while (fd.time() < T) {
            fd.step();
            for (std::size_t l = 1; l <= 40; ++l) {
                err = std::max(err, std::abs(fd.density(l)
                                             - exact::constantKernelDensity(1.0, 1.0, fd.time(), l)));
            }
        }
        errors[a] = err;
    }
    // first order in alpha (2.35): each factor 4 in alpha should cut the error about 4 times
    EXPECT_LT(errors[1], errors[0] / 2.5) << errors[0] << " " << errors[1];
    EXPECT_LT(errors[2], errors[1] / 2.5) << errors[1] << " " << errors[2];
    EXPECT_LT(errors[2], 5e-3);
}

TEST(FiniteDifference, TimeStepFollowsTheDefinition)
{
    // constant kernel: Delta_k = alpha / (K0 sum_j nhat_j)
    ConstantKernel kernel(2.0);
    FiniteDifferenceSmoluchowski fd(kernel, {3.0}, 0.5, 64);
    EXPECT_DOUBLE_EQ(fd.step(), 0.5 / (2.0 * 3.0));
    const double m0 = fd.densities().sum();
    EXPECT_DOUBLE_EQ(fd.step(), 0.5 / (2.0 * m0));
    EXPECT_EQ(fd.stepIndex(), 2u);
}
