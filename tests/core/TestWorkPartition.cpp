// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#include "TestHelpers.hpp"

#include "coagulation/WorkPartition.hpp"

#include <algorithm>
#include <functional>
#include <limits>

using namespace coagtest;

namespace {

//- The smallest largest-part sum over every way to cut w into k non-empty contiguous parts
double bruteForce(const std::vector<double>& w, std::size_t k)
{
    double best = std::numeric_limits<double>::infinity();
    std::vector<std::size_t> b(1, 0);
    std::function<void()> recurse = [&] {
        if (b.size() == k) {
            b.push_back(w.size());
            best = std::min(best, largestPart(w, b));
            b.pop_back();
            return;
        }
        const std::size_t partsAfter = k - b.size();
        for (std::size_t c = b.back() + 1; c + partsAfter <= w.size(); ++c) {
            b.push_back(c);
            recurse();
            b.pop_back();
        }
    };
    recurse();
    return best;
}

void expectValid(const std::vector<std::size_t>& b, std::size_t n, std::size_t k)
{
    ASSERT_EQ(b.size(), k + 1);
    EXPECT_EQ(b.front(), 0u);
    EXPECT_EQ(b.back(), n);
    for (std::size_t p = 0; p < k; ++p) EXPECT_LT(b[p], b[p + 1]) << "part " << p << " empty";
}

} // namespace

//- The bottleneck equals the brute-force optimum on 600 random cases (n <= 11, k <= 5, some
//  weights zero, some heavy), and every part is non-empty.
TEST(WorkPartition, OptimalAgainstBruteForce)
{
    Rng rng(4242);
    for (int c = 0; c < 600; ++c) {
        const std::size_t n = 1 + rng.uniformIndex(11);
        const std::size_t k = 1 + rng.uniformIndex(std::min<std::size_t>(n, 5));
        std::vector<double> w(n);
        for (double& x : w) {
            const double u = rng.uniform();
            x = u < 0.2 ? 0.0 : (u > 0.9 ? 50.0 * rng.uniform() : rng.exponential(1.0));
        }
        const std::vector<std::size_t> b = partitionContiguous(w, k);
        expectValid(b, n, k);
        const double opt = bruteForce(w, k);
        EXPECT_LE(largestPart(w, b), opt * (1 + 1e-12) + 1e-300) << "case " << c;
    }
}

//- The duct of issue 19 (the work per cell of the additive duct at n = 8192, last 8 of 50
//  cells as measured with events counted at half a particle, the rest small): the cumulative
//  split leaves 59 % on one rank, the optimal one 52 %.
TEST(WorkPartition, HeavyCellsOfTheDuct)
{
    std::vector<double> w(42, 4000.0);
    for (double x : {16569., 21154., 27703., 37299., 51433., 72311., 103498., 150485.}) {
        w.push_back(x);
    }
    double total = 0.0;
    for (double x : w) total += x;
    // OpenFOAM's weighted simple/hierarchical: item i to part floor(2 * before / total)
    std::vector<std::size_t> cumulative(1, 0);
    double before = 0.0;
    for (std::size_t i = 0; i < w.size(); ++i) {
        if (cumulative.size() < 2 && 2.0 * before / total >= 1.0) cumulative.push_back(i);
        before += w[i];
    }
    cumulative.push_back(w.size());
    const std::vector<std::size_t> b = partitionContiguous(w, 2);
    expectValid(b, w.size(), 2);
    EXPECT_EQ(b[1], 47u);  // cells 47-49 on the second rank
    EXPECT_GT(largestPart(w, cumulative) / total, 0.55);
    EXPECT_LT(largestPart(w, b) / total, 0.53);
    EXPECT_NEAR(largestPart(w, b), bruteForce(w, 2), 1e-9 * total);
}

TEST(WorkPartition, EdgeCasesAndBadInput)
{
    expectValid(partitionContiguous({0.0, 0.0, 0.0}, 3), 3, 3);  // all zero: one each
    const auto one = partitionContiguous({1.0, 2.0}, 1);
    EXPECT_EQ(one, (std::vector<std::size_t>{0, 2}));
    const auto many = partitionContiguous(std::vector<double>(1000, 1.0), 7);
    expectValid(many, 1000, 7);
    EXPECT_LE(largestPart(std::vector<double>(1000, 1.0), many), 143.0);
    EXPECT_THROW(partitionContiguous({1.0}, 2), std::invalid_argument);
    EXPECT_THROW(partitionContiguous({1.0}, 0), std::invalid_argument);
    EXPECT_THROW(partitionContiguous({1.0, -1.0}, 1), std::invalid_argument);
    EXPECT_THROW(partitionContiguous({1.0, std::nan("")}, 1), std::invalid_argument);
    EXPECT_THROW(partitionContiguous({1e308, 1e308}, 1), std::invalid_argument);
}
