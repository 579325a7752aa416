// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#include "TestHelpers.hpp"

#include <limits>
#include <numeric>
#include <tuple>

using namespace coagtest;

namespace {

//- Every leaf majorises its value within one scale unit (v <= Q < v + 2^e, Q = 2^e for any
//  0 < v <= 2^e), is the tree's quantisation of it, and the totals are the integer sums of the
//  leaves (the sums rebuild() makes from them)
void expectQuantisationOf(QuantizedSumTree& tree, const std::vector<std::vector<double>>& v,
                          const std::string& what)
{
    for (std::size_t c = 0; c < tree.columns(); ++c) {
        const double unit = std::ldexp(1.0, tree.exponent(c));
        std::uint64_t sum = 0;
        for (std::size_t j = 0; j < v[c].size(); ++j) {
            const double Q = tree.value(j, c);
            ASSERT_GE(Q, v[c][j]) << what << ": column " << c << " leaf " << j;
            ASSERT_LT(Q - unit, v[c][j]) << what << ": column " << c << " leaf " << j;  // exact
            ASSERT_EQ(Q, tree.quantised(c, v[c][j])) << what;
            if (v[c][j] > 0.0) {
                ASSERT_GT(tree.leaf(j, c), 0u) << what;
            }
            sum += tree.leaf(j, c);
        }
        for (std::size_t j = v[c].size(); j < tree.capacity(); ++j) ASSERT_EQ(tree.leaf(j, c), 0u);
        ASSERT_EQ(tree.totalInteger(c), sum) << what << ": column " << c;
    }
    std::vector<std::uint64_t> totals(tree.columns());
    for (std::size_t c = 0; c < tree.columns(); ++c) totals[c] = tree.totalInteger(c);
    tree.rebuild();
    for (std::size_t c = 0; c < tree.columns(); ++c) ASSERT_EQ(tree.totalInteger(c), totals[c]);
}

//- A 3-column tree over n leaves of Exp(1) values (every fifth zero, by leaf and column, when
//  withZeros), staged and built; v holds the values, leaf by leaf
void buildRandomTree(QuantizedSumTree& tree, std::size_t n, Rng& rng, std::vector<double>& v,
                     bool withZeros)
{
    tree.reset(3, n);
    v.assign(3 * n, 0.0);
    for (std::size_t j = 0; j < n; ++j) {
        for (std::size_t c = 0; c < 3; ++c) {
            v[3 * j + c] = withZeros && (j + c) % 5 == 1 ? 0.0 : rng.exponential(1.0);
            tree.stage(j, c, v[3 * j + c]);
        }
    }
    tree.finishBuild(n);
}

} // namespace

TEST(QuantizedSumTree, BuildQuantisesEachColumnBelowItsLargestValue)
{
    QuantizedSumTree tree;
    tree.reset(2, 5);
    EXPECT_GE(tree.capacity(), 5u);
    std::vector<std::vector<double>> v{{1.0, 0.25, 3.0, 0.0, 1e-30}, {1e12, 2e12, 0.5e12, 7e11, 0.0}};
    for (std::size_t j = 0; j < 5; ++j) {
        for (std::size_t c = 0; c < 2; ++c) tree.stage(j, c, v[c][j]);
    }
    tree.finishBuild(5);
    expectQuantisationOf(tree, v, "build");
    // the largest value headroomBits below the leaf limit: q = 3 * 2^-e < 2^(52 - 8)
    EXPECT_LE(tree.leaf(2, 0), std::uint64_t(1) << 44);
    EXPECT_GT(tree.leaf(2, 0), std::uint64_t(1) << 43);
    EXPECT_EQ(tree.leaf(4, 0), 1u);  // far below the scale: one unit
    // small integers and powers of two stay exact: the totals are the sums
    EXPECT_EQ(tree.total(0), 4.25 + tree.value(4, 0));
    EXPECT_EQ(tree.total(1), 4.2e12);

    // a positive value whose quotient underflows to zero (1e-300 at the scale of 1e300,
    // 2^953) is still one unit, so that it can be drawn
    QuantizedSumTree wide;
    wide.reset(1, 2);
    wide.stage(0, 0, 1e300);
    wide.stage(1, 0, 1e-300);
    wide.finishBuild(2);
    EXPECT_EQ(wide.leaf(1, 0), 1u);
    expectQuantisationOf(wide, {{1e300, 1e-300}}, "wide");
}

//- assign() and moveLeaf() add exact deltas: after many random changes, with values over
//  30 decades, zeros, growth that coarsens a column and capacity changes, every leaf is the
//  quantisation of its value and the totals are the sums of the leaves
TEST(QuantizedSumTree, ChangesKeepTheLeavesAndSumsExact)
{
    for (const std::size_t ncol : {1, 2, 3, 4, 5, 16}) {
        for (const std::size_t n : {std::size_t(7), std::size_t(600), std::size_t(5000)}) {
            const std::string what = std::to_string(ncol) + " columns, " + std::to_string(n);
            QuantizedSumTree tree;
            tree.reset(ncol, n);
            Rng rng(3 + n + ncol);
            std::vector<std::vector<double>> v(ncol, std::vector<double>(n));
            for (std::size_t j = 0; j < n; ++j) {
                for (std::size_t c = 0; c < ncol; ++c) {
                    v[c][j] = j % 11 == c ? 0.0 : std::pow(10.0, 10.0 * rng.uniform());
                    tree.stage(j, c, v[c][j]);
                }
            }
            tree.finishBuild(n);
            expectQuantisationOf(tree, v, what + " build");
            std::vector<double> x(ncol);
            std::size_t size = n;
            for (int i = 0; i < 4000; ++i) {
                const std::size_t j = rng.uniformIndex(size);
                if (i % 97 == 5 && size > 1) {  // removal by swap
                    tree.moveLeaf(size - 1, j);
                    for (std::size_t c = 0; c < ncol; ++c) {
                        v[c][j] = v[c][size - 1];
                        v[c].pop_back();
                    }
                    --size;
                    continue;
                }
                for (std::size_t c = 0; c < ncol; ++c) {
                    // mostly moderate changes, sometimes zero, rarely 20 decades of growth
                    const double r = rng.uniform();
                    x[c] = r < 0.1 ? 0.0 : r > 0.998 ? 1e20 * v[c][j] + 1.0
                                         : v[c][j] * (0.5 + rng.uniform()) + 1e-20;
                    v[c][j] = x[c];
                }
                tree.assign(j, x.data());
                if (i % 500 == 0) expectQuantisationOf(tree, v, what + " step");
            }
            expectQuantisationOf(tree, v, what + " end");
            tree.resizeCapacity(4 * n + 100);
            expectQuantisationOf(tree, v, what + " resized");
        }
    }
    QuantizedSumTree t;
    EXPECT_THROW(t.reset(QuantizedSumTree::maxColumns + 1, 8), std::invalid_argument);
}

//- The descent is exact: leaf j is chosen for exactly the q_j draws u in
//  [prefix_j, prefix_j + q_j), so the law is q_j / total and a leaf with q = 0 is never chosen.
//  Checked at both ends of every leaf's range, for trees of 1 to 4 levels, with and without
//  the prefetching walk (> 512 kB); samplePair gives the leaves of two sample() calls.
TEST(QuantizedSumTree, EachLeafOwnsExactlyItsRangeOfDraws)
{
    for (const std::size_t n : {std::size_t(6), std::size_t(70), std::size_t(700),
                                std::size_t(30000)}) {
        QuantizedSumTree tree;
        tree.reset(3, n);
        Rng rng(8 + n);
        for (std::size_t j = 0; j < n; ++j) {
            for (std::size_t c = 0; c < 3; ++c) {
                tree.stage(j, c, (j + c) % 3 == 1 ? 0.0 : rng.exponential(1.0));
            }
        }
        tree.finishBuild(n);
        std::vector<double> leafData(tree.capacity());
        for (std::size_t c = 0; c < 3; ++c) {
            std::uint64_t prefix = 0;
            for (std::size_t j = 0; j < tree.capacity(); ++j) {
                const std::uint64_t q = tree.leaf(j, c);
                if (q > 0) {
                    ASSERT_EQ(tree.sample(c, prefix), j) << n;
                    ASSERT_EQ(tree.sample(c, prefix + q - 1, leafData.data(), sizeof(double)), j);
                    std::size_t j1 = 0, j2 = 0;
                    const std::uint64_t u2 = rng.uniformIndex(tree.totalInteger(2 - c));
                    tree.samplePair(c, prefix + q - 1, 2 - c, u2, leafData.data(),
                                    sizeof(double), j1, j2);
                    ASSERT_EQ(j1, j);
                    ASSERT_EQ(j2, tree.sample(2 - c, u2));
                }
                prefix += q;
            }
            ASSERT_EQ(prefix, tree.totalInteger(c));
        }
    }
}

//- A draw made ahead (walk, walkPair) and taken later by drawNear() is the walk's draw for
//  the later integer, after no change or one assign() (of a leaf before, at or after the
//  drawn one, to a larger, smaller or zero value): drawNear either declines or gives
//  sample(c, u) exactly, for integers near and far from the predicted one (in the Draw's
//  block of 8 leaves and outside it, on both sides); it takes most of the near ones; and it
//  declines after two changes, a removal by swap and a coarsening. The Draw is the walk's
//  block: its first leaf, and where that leaf's interval begins (the sum of the leaves before).
TEST(QuantizedSumTree, DrawsMadeAheadAreTheWalksDrawsOrDeclined)
{
    for (const std::size_t n : {std::size_t(5), std::size_t(300), std::size_t(20000)}) {
        QuantizedSumTree tree;
        Rng rng(31 + n);
        std::vector<double> v;
        buildRandomTree(tree, n, rng, v, true);
        std::vector<double> leafData(tree.capacity());
        std::size_t tried = 0, taken = 0, nearTried = 0, nearTaken = 0;
        std::size_t takenLeft = 0, takenRight = 0;  // outside the Draw's block
        for (int round = 0; round < 400; ++round) {
            for (std::size_t c = 0; c < 3; ++c) {
                if (tree.totalInteger(c) == 0) {  // zeroed below: refill one leaf
                    double values[3] = {v[0], v[1], v[2]};
                    values[c] = 1.0;
                    tree.assign(0, values);
                    v[c] = 1.0;
                }
            }
            const std::size_t c1 = rng.uniformIndex(3), c2 = rng.uniformIndex(3);
            const std::uint64_t p1 = rng.uniformIndex(tree.totalInteger(c1));
            const std::uint64_t p2 = rng.uniformIndex(tree.totalInteger(c2));
            QuantizedSumTree::Draw d1, d2, d3;
            tree.walkPair(c1, p1, c2, p2, leafData.data(), sizeof(double), d1, d2);
            tree.walk(c1, p1, leafData.data(), sizeof(double), d3);
            ASSERT_EQ(d1.leaf, tree.sample(c1, p1) / 8 * 8);
            ASSERT_EQ(d2.leaf, tree.sample(c2, p2) / 8 * 8);
            ASSERT_EQ(d3.leaf, d1.leaf);
            ASSERT_EQ(d3.start, d1.start);
            for (const auto& [c, d] : {std::pair{c1, d1}, std::pair{c2, d2}}) {
                std::uint64_t below = 0, block = 0;
                for (std::size_t k = 0; k < d.leaf; ++k) below += tree.leaf(k, c);
                for (std::size_t k = d.leaf; k < d.leaf + 8; ++k) block += tree.leaf(k, c);
                ASSERT_EQ(d.start, below);
                // the integers at the block's ends, inside and out
                for (const std::uint64_t u : {below - 1, below, below + block - 1, below + block}) {
                    if (u >= tree.totalInteger(c)) continue;  // also below - 1 for below = 0
                    std::size_t j = n + 7;
                    ASSERT_TRUE(tree.drawNear(c, d, u, j));
                    ASSERT_EQ(j, tree.sample(c, u)) << n << " round " << round << " u " << u;
                }
            }
            // no change, or one change of a leaf near the drawn one or anywhere
            const int kind = round % 4;
            if (kind > 0) {
                std::size_t j = kind == 1 ? rng.uniformIndex(n)
                                          : std::min(n - 1, d1.leaf + rng.uniformIndex(3) - 1
                                                                + (d1.leaf == 0 ? 1 : 0));
                const double factor = kind == 3 ? 0.0 : 0.25 + 3.0 * rng.uniform();
                double values[3];
                for (std::size_t c = 0; c < 3; ++c) values[c] = v[3 * j + c] * factor;
                tree.assign(j, values);
                for (std::size_t c = 0; c < 3; ++c) v[3 * j + c] = values[c];
            }
            for (const auto& [c, d, p] : {std::tuple{c1, d1, p1}, std::tuple{c2, d2, p2}}) {
                if (tree.totalInteger(c) == 0) continue;
                for (int k = 0; k < 12; ++k) {
                    const std::uint64_t total = tree.totalInteger(c);
                    // a quarter of a mean interval, three intervals, anywhere
                    const std::uint64_t spread = k < 6   ? total / (4 * n) + 2
                                                 : k < 9 ? 3 * (total / n) + 2
                                                         : total;
                    const std::uint64_t offset = rng.uniformIndex(2 * spread);
                    std::uint64_t u = p + offset >= spread ? p + offset - spread : 0;
                    if (u >= total) u = total - 1;
                    std::size_t j = n + 7;
                    const bool ok = tree.drawNear(c, d, u, j);
                    ++tried;
                    if (k < 6) ++nearTried;
                    if (ok) {
                        ASSERT_EQ(j, tree.sample(c, u)) << n << " round " << round;
                        if (j < d.leaf) ++takenLeft;
                        if (j >= d.leaf + 8) ++takenRight;
                        ++taken;
                        if (k < 6) ++nearTaken;
                    } else {
                        ASSERT_EQ(j, n + 7);
                    }
                }
            }
        }
        EXPECT_GT(nearTaken, nearTried * 9 / 10) << n;
        EXPECT_GT(taken, 0u);
        if (n > 8) {
            EXPECT_GT(takenLeft, 0u) << n;
            EXPECT_GT(takenRight, 0u) << n;
        }
        // after two changes, a removal by swap or a coarsening: declined
        const std::uint64_t p = rng.uniformIndex(tree.totalInteger(0));
        QuantizedSumTree::Draw d;
        tree.walk(0, p, leafData.data(), sizeof(double), d);
        std::size_t j = 0;
        ASSERT_TRUE(tree.drawNear(0, d, p, j));
        double values[3] = {1.0, 1.0, 1.0};
        tree.assign(0, values);
        tree.assign(n - 1, values);
        EXPECT_FALSE(tree.drawNear(0, d, p, j));
        tree.walk(0, p, leafData.data(), sizeof(double), d);
        if (n > 1) {
            tree.moveLeaf(n - 1, 0);
            EXPECT_FALSE(tree.drawNear(0, d, p, j));
        }
        tree.walk(0, rng.uniformIndex(tree.totalInteger(0)), leafData.data(), sizeof(double), d);
        const double huge[3] = {1e30, 1.0, 1.0};  // past the column's headroom: coarsened
        tree.assign(n / 2, huge);
        EXPECT_FALSE(tree.drawNear(0, d, p, j));
        // coarsenings by a few bits: integers near the drawn block's old start then lie
        // elsewhere (B133: a Draw that survived the rebuild would be taken there)
        for (int k = 0; k < 20; ++k) {
            const std::uint64_t q = rng.uniformIndex(tree.totalInteger(1));
            tree.walk(1, q, leafData.data(), sizeof(double), d);
            const int before = tree.exponent(1);
            // 2^53 units of the scale: past any leaf's limit (2^52 at most), a few bits over
            const double big[3] = {1.0, std::ldexp(1.0, before + 53), 1.0};
            tree.assign(rng.uniformIndex(n), big);
            ASSERT_GT(tree.exponent(1), before) << "coarsened";
            for (const std::uint64_t u : {d.start / 2, d.start, d.start + 1, q}) {
                if (u >= tree.totalInteger(1)) continue;
                std::size_t jj = n + 7;
                if (tree.drawNear(1, d, u, jj)) {
                    ASSERT_EQ(jj, tree.sample(1, u)) << n << " u " << u;
                }
            }
        }
    }
}

//- Draws made in two halves (walkToNode, walkPairToNode, then finishToBlock after no change
//  or one assign()) are Draws as walk() makes them: the block's first leaf, inside the tree,
//  and where its interval begins now; drawNear() with them gives sample(c, u) exactly; and
//  finishToBlock declines after two changes. Integers drawn at the end of the column, whose
//  last level-1 node has fewer than 8 blocks, are then moved past the column's total by the
//  change (the node's missing blocks must not be named).
TEST(QuantizedSumTree, DrawsMadeInTwoHalvesAreWalksDraws)
{
    for (const std::size_t n : {std::size_t(9), std::size_t(300), std::size_t(5000),
                                std::size_t(20000)}) {
        QuantizedSumTree tree;
        Rng rng(77 + n);
        std::vector<double> v;
        buildRandomTree(tree, n, rng, v, false);
        ASSERT_GE(tree.levels(), 2u) << "level 1 exists";
        std::vector<double> leafData(tree.capacity());
        std::size_t finished = 0, declined = 0, pastTotal = 0;
        for (int round = 0; round < 3000; ++round) {
            const std::size_t c1 = rng.uniformIndex(3), c2 = rng.uniformIndex(3);
            // every fourth integer from the column's last few intervals
            const std::uint64_t t1 = tree.totalInteger(c1);
            const std::uint64_t p1 = round % 4 == 0 ? t1 - 1 - rng.uniformIndex(t1 / n + 1)
                                                    : rng.uniformIndex(t1);
            const std::uint64_t p2 = rng.uniformIndex(tree.totalInteger(c2));
            QuantizedSumTree::Partial h1, h2, h3;
            tree.walkPairToNode(c1, p1, c2, p2, h1, h2);
            tree.walkToNode(c1, p1, h3);
            ASSERT_EQ(h3.node, h1.node);
            ASSERT_EQ(h3.start, h1.start);
            const int kind = round % 3;  // no change, one, or two
            for (int k = 0; k < kind; ++k) {
                // the last leaves shrink as often as any: integers past the total follow
                const std::size_t last = std::min<std::size_t>(n, 8);
                const std::size_t j =
                    round % 2 ? n - 1 - rng.uniformIndex(last) : rng.uniformIndex(n);
                const double grow = round % 2 ? 0.0 : 0.5 + rng.uniform();
                const double factor = 0.25 * rng.uniform() + grow;
                double values[3];
                for (std::size_t c = 0; c < 3; ++c) values[c] = v[3 * j + c] * factor;
                tree.assign(j, values);
                for (std::size_t c = 0; c < 3; ++c) v[3 * j + c] = values[c];
            }
            for (const auto& [c, h, p] : {std::tuple{c1, h1, p1}, std::tuple{c2, h2, p2}}) {
                QuantizedSumTree::Draw d;
                const bool ok = tree.finishToBlock(c, h, leafData.data(), sizeof(double), d);
                if (kind == 2) {
                    EXPECT_FALSE(ok);
                    continue;
                }
                if (p >= tree.totalInteger(c)) ++pastTotal;
                if (!ok) {
                    ++declined;
                    continue;
                }
                ++finished;
                ASSERT_EQ(d.leaf % 8, 0u);
                ASSERT_LT(d.leaf, tree.capacity()) << n << " round " << round;
                std::uint64_t below = 0;
                for (std::size_t k = 0; k < d.leaf; ++k) below += tree.leaf(k, c);
                ASSERT_EQ(d.start, below) << n << " round " << round;
                const std::uint64_t total = tree.totalInteger(c);
                for (int k = 0; k < 4; ++k) {
                    const std::uint64_t spread = total / n + 2;
                    const std::uint64_t offset = rng.uniformIndex(2 * spread);
                    std::uint64_t u = p + offset >= spread ? p + offset - spread : 0;
                    if (u >= total) u = total - 1;
                    std::size_t j = n + 7;
                    if (tree.drawNear(c, d, u, j)) {
                        ASSERT_EQ(j, tree.sample(c, u)) << n << " round " << round;
                    }
                }
            }
        }
        EXPECT_GT(finished, 1000u) << n;
        EXPECT_GT(pastTotal, 10u) << n << ": integers moved past the total";
        EXPECT_LT(declined, finished / 10) << n;
    }
}

//- A column whose leaves are all zero takes its scale from the next value, whatever the
//  scale before; values beyond the scales' range are refused
TEST(QuantizedSumTree, EmptyColumnTakesItsScaleAfresh)
{
    QuantizedSumTree tree;
    tree.reset(1, 16);
    tree.finishBuild(0);
    const double tiny = 3e-200, large = 5e200;
    tree.assign(3, &tiny);
    EXPECT_GT(tree.leaf(3, 0), std::uint64_t(1) << 40);
    EXPECT_GE(tree.value(3, 0), tiny);
    const double zero = 0.0;
    tree.assign(3, &zero);
    EXPECT_EQ(tree.totalInteger(0), 0u);
    tree.assign(5, &large);
    EXPECT_GT(tree.leaf(5, 0), std::uint64_t(1) << 40);
    EXPECT_GE(tree.value(5, 0), large);
    EXPECT_LT(tree.value(5, 0), large * (1 + 1e-12));
    const double unreachable = 1e-300;
    tree.assign(5, &zero);
    EXPECT_THROW(tree.assign(2, &unreachable), std::domain_error);
}

//- Values that are NaN, infinite or negative (a bad particle weight) are refused, at build and
//  at a change, and a refused change leaves the leaf as it was; an SWA step with such a weight
//  stops with the error instead of running on garbage integers
TEST(QuantizedSumTree, RefusesValuesThatAreNotFiniteAndNonNegative)
{
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    for (const double bad : {nan, inf, -1.0, -inf}) {
        QuantizedSumTree tree;
        tree.reset(2, 8);
        tree.stage(0, 0, 1.0);
        tree.stage(0, 1, bad);
        EXPECT_THROW(tree.finishBuild(1), std::domain_error) << bad;
        tree.reset(2, 8);
        tree.stage(0, 0, 1.0);
        tree.stage(0, 1, 2.0);
        tree.finishBuild(1);
        const std::uint64_t before = tree.totalInteger(1);
        const double values[2] = {1.0, bad};
        EXPECT_THROW(tree.assign(0, values), std::domain_error) << bad;
        EXPECT_EQ(tree.totalInteger(1), before) << bad;
        EXPECT_EQ(tree.leaf(0, 1), before) << bad;

        auto kernel = makeKernel("additive", 1.0);
        auto swa = makeCellAlgorithm("SWA", *kernel, InceptionModel{});
        CellPopulation pop;
        pop.volume = 10.0;
        for (int j = 0; j < 10; ++j) pop.particles.push_back(Particle{ParticleType{1.0}, 1.0, j});
        pop.particles[3].weight = bad;
        Rng rng(1);
        StepStatistics stats;
        EXPECT_THROW(swa->advance(pop, 0.1, rng, stats), std::domain_error) << bad;
    }
}

TEST(QuantizedSumTree, BuildInFewerPassesIsTheStagedBuild)
{
    // build() against reset() + stage() + finishBuild(): the same leaves (also those from n to
    // the capacity, which build() does not zero first: the fused tree is reused from a bigger
    // build each time), scales, totals and draws; the same first bad value refused
    Rng rng(2024);
    QuantizedSumTree fused;
    for (std::size_t ncol : {1u, 3u, 5u}) {
        for (std::size_t n : {1000u, 65u, 64u, 9u, 8u, 7u, 1u, 0u}) {
            for (std::size_t capacity : {n, n + 5, 3 * n + 20}) {
                std::vector<std::vector<double>> v(ncol, std::vector<double>(n));
                for (auto& column : v) {
                    for (double& x : column) {
                        x = rng.uniform() < 0.2 ? 0.0 : std::exp(40.0 * rng.uniform() - 20.0);
                    }
                }
                QuantizedSumTree staged;
                staged.reset(ncol, capacity);
                for (std::size_t j = 0; j < n; ++j) {
                    for (std::size_t c = 0; c < ncol; ++c) staged.stage(j, c, v[c][j]);
                }
                staged.finishBuild(n);
                fused.build(ncol, capacity, n, [&](std::size_t j, double* out) {
                    for (std::size_t c = 0; c < ncol; ++c) out[c] = v[c][j];
                });
                const std::string what = std::to_string(ncol) + " columns, n " + std::to_string(n)
                                         + ", capacity " + std::to_string(capacity);
                ASSERT_EQ(fused.capacity(), staged.capacity()) << what;
                ASSERT_EQ(fused.levels(), staged.levels()) << what;
                for (std::size_t c = 0; c < ncol; ++c) {
                    ASSERT_EQ(fused.exponent(c), staged.exponent(c)) << what;
                    ASSERT_EQ(fused.totalInteger(c), staged.totalInteger(c)) << what;
                    for (std::size_t j = 0; j < staged.capacity(); ++j) {
                        ASSERT_EQ(fused.leaf(j, c), staged.leaf(j, c)) << what << " leaf " << j;
                    }
                    const std::uint64_t total = staged.totalInteger(c);
                    for (int k = 0; total > 0 && k < 200; ++k) {
                        const std::uint64_t u = k == 0 ? total - 1 : rng.uniformIndex(total);
                        ASSERT_EQ(fused.sample(c, u), staged.sample(c, u)) << what << " u " << u;
                    }
                }
            }
        }
    }
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (const double bad : {nan, std::numeric_limits<double>::infinity(), -1.0}) {
        // bad values in columns 2 (leaf 3) and 1 (leaf 6): the scan reports column 1's first
        auto value = [&](std::size_t j, std::size_t c) {
            return (j == 3 && c == 2) || (j == 6 && c == 1) ? bad : 1.0 + double(j + c);
        };
        QuantizedSumTree staged;
        staged.reset(3, 16);
        for (std::size_t j = 0; j < 10; ++j) {
            for (std::size_t c = 0; c < 3; ++c) staged.stage(j, c, value(j, c));
        }
        std::string stagedMessage, fusedMessage;
        try {
            staged.finishBuild(10);
        } catch (const std::domain_error& e) {
            stagedMessage = e.what();
        }
        try {
            fused.build(3, 16, 10, [&](std::size_t j, double* out) {
                for (std::size_t c = 0; c < 3; ++c) out[c] = value(j, c);
            });
        } catch (const std::domain_error& e) {
            fusedMessage = e.what();
        }
        EXPECT_NE(stagedMessage.find("column 1"), std::string::npos) << stagedMessage;
        EXPECT_EQ(fusedMessage, stagedMessage) << bad;
    }
}

TEST(QuantizedSumTree, QuantisesToTheCeilingOfTheScaledValue)
{
    // At a known scale 2^e, v = t 2^e for t integer, with a quarter or a half (ties of the
    // rounding inside quantise()), up to 2^52; and values far below the scale
    QuantizedSumTree tree;
    tree.reset(1, 8);
    tree.stage(0, 0, 1.0);
    tree.finishBuild(1);
    const double unit = std::ldexp(1.0, tree.exponent(0));
    const double two52 = std::ldexp(1.0, 52);
    int checked = 0;
    for (const double k : {0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 1048577.0, std::ldexp(1.0, 51) - 1.0,
                           std::ldexp(1.0, 51), two52 - 2.0, two52 - 1.0}) {
        for (const double f : {0.0, 0.25, 0.5, 0.75}) {
            const double t = k + f;
            if (t - k != f || t > two52) continue;  // not a double
            const double v = t * unit;
            ASSERT_EQ(tree.quantised(0, v), std::ceil(t) * unit) << "t = " << t;
            ++checked;
        }
    }
    EXPECT_GE(checked, 30);
    EXPECT_EQ(tree.quantised(0, two52 * unit), two52 * unit);
    for (const double tiny : {1e-300, std::numeric_limits<double>::denorm_min(), unit / 3.0}) {
        EXPECT_EQ(tree.quantised(0, tiny), unit) << tiny;
    }
    EXPECT_EQ(tree.quantised(0, 0.0), 0.0);
}
