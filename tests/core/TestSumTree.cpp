// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#include "TestHelpers.hpp"

using namespace coagtest;

TEST(SumTree, TotalsAndUpdates)
{
    SumTree tree;
    tree.reset(2, 5);
    EXPECT_GE(tree.capacity(), 5u);
    for (std::size_t j = 0; j < 5; ++j) {
        tree.set(j, 0, 1.0);
        tree.set(j, 1, double(j));
    }
    tree.rebuild();
    EXPECT_DOUBLE_EQ(tree.total(0), 5.0);
    EXPECT_DOUBLE_EQ(tree.total(1), 10.0);
    tree.set(3, 1, 0.5);
    tree.update(3);
    EXPECT_DOUBLE_EQ(tree.total(1), 7.5);
    tree.resizeCapacity(2000);
    EXPECT_GE(tree.capacity(), 2000u);
    EXPECT_EQ(tree.levels(), 4u);  // 2000 leaves: 250, 32, 4, 1 nodes
    EXPECT_DOUBLE_EQ(tree.total(1), 7.5);
    EXPECT_DOUBLE_EQ(tree.value(4, 1), 4.0);
    tree.set(1999, 0, 2.0);
    tree.update(1999);
    EXPECT_DOUBLE_EQ(tree.total(0), 7.0);
    EXPECT_EQ(tree.sample(0, 6.5), 1999u);
}

TEST(SumTree, ManyLeavesStayExactlyConsistent)
{
    // After many random updates the totals equal a fresh rebuild bit for bit.
    SumTree tree;
    const std::size_t n = 5000;
    tree.reset(3, n);
    Rng rng(2);
    for (std::size_t j = 0; j < n; ++j)
        for (std::size_t c = 0; c < 3; ++c) tree.set(j, c, rng.uniform());
    tree.rebuild();
    for (int i = 0; i < 20000; ++i) {
        const std::size_t j = rng.uniformIndex(n);
        tree.set(j, i % 3, i % 7 == 0 ? 0.0 : rng.exponential(1.0));
        tree.update(j);
    }
    const double t0 = tree.total(0), t1 = tree.total(1), t2 = tree.total(2);
    tree.rebuild();
    EXPECT_EQ(tree.total(0), t0);
    EXPECT_EQ(tree.total(1), t1);
    EXPECT_EQ(tree.total(2), t2);
}

//- assign() (one pass, the new sums carried up in registers; update() is assign() of the
//  leaf's own values) leaves the tree that rebuild() makes from the same leaves, bit for bit,
//  for every column count (1-4 have their own code, 5 and 16 the generic path) and depth:
//  the totals after every change, and the leaf every u samples.
TEST(SumTree, AssignIsSetThenRebuild)
{
    for (const std::size_t ncol : {1, 2, 3, 4, 5, 16}) {
        for (const std::size_t n : {std::size_t(5), std::size_t(700), std::size_t(40000)}) {
            SumTree a, b;
            a.reset(ncol, n);
            b.reset(ncol, n);
            Rng rng(7 + ncol);
            for (std::size_t j = 0; j < n; ++j) {
                for (std::size_t c = 0; c < ncol; ++c) {
                    const double v = rng.uniform();
                    a.set(j, c, v);
                    b.set(j, c, v);
                }
            }
            a.rebuild();
            b.rebuild();
            std::vector<double> values(ncol);
            const int every = n > 1000 ? 97 : 1;  // a rebuild is O(n)
            for (int i = 0; i < 3000; ++i) {
                const std::size_t j = rng.uniformIndex(n);
                for (std::size_t c = 0; c < ncol; ++c) {
                    values[c] = i % 5 == 0 ? 0.0 : rng.exponential(1.0);
                    b.set(j, c, values[c]);
                }
                if (i % 2 == 0) {
                    a.assign(j, values.data());
                } else {
                    for (std::size_t c = 0; c < ncol; ++c) a.set(j, c, values[c]);
                    a.update(j);
                }
                if (i % every != 0) continue;
                b.rebuild();
                for (std::size_t c = 0; c < ncol; ++c) {
                    ASSERT_EQ(a.total(c), b.total(c)) << ncol << " columns, " << n << " leaves";
                    for (int k = 0; k < 20; ++k) {
                        const double u = (k + 0.5) / 20.0 * a.total(c);
                        ASSERT_EQ(a.sample(c, u), b.sample(c, u));
                    }
                }
            }
        }
    }
    SumTree t;
    EXPECT_THROW(t.reset(SumTree::maxColumns + 1, 8), std::invalid_argument);
}

TEST(SumTree, SamplesProportionallyAndNeverPicksEmptyLeaves)
{
    for (const std::size_t n : {6u, 70u, 700u}) {
        SumTree tree;
        tree.reset(2, n);
        std::vector<double> w(n);
        double total = 0;
        for (std::size_t j = 0; j < n; ++j) {
            w[j] = (j % 3 == 1) ? 0.0 : double(1 + j % 5);
            total += w[j];
            tree.set(j, 1, w[j]);
            tree.set(j, 0, 1.0);
        }
        tree.rebuild();
        Rng rng(8 + n);
        std::vector<int> counts(tree.capacity(), 0);
        const int draws = 200000;
        for (int i = 0; i < draws; ++i) ++counts[tree.sample(1, rng.uniform() * tree.total(1))];
        double chi2 = 0;
        int dof = -1;
        for (std::size_t j = 0; j < tree.capacity(); ++j) {
            if (j >= n || w[j] == 0.0) {
                EXPECT_EQ(counts[j], 0) << "empty leaf " << j << " chosen (n = " << n << ")";
                continue;
            }
            const double e = draws * w[j] / total;
            chi2 += (counts[j] - e) * (counts[j] - e) / e;
            ++dof;
        }
        // chi-square with dof degrees of freedom: mean dof, sd sqrt(2 dof)
        EXPECT_LT(chi2, dof + 5 * std::sqrt(2.0 * dof)) << "n = " << n;
        // u at (or past, by round-off) the total still lands on a non-empty leaf
        const std::size_t last = tree.sample(1, tree.total(1));
        EXPECT_LT(last, n);
        EXPECT_GT(w[last], 0.0);
        const std::size_t beyond = tree.sample(1, 2 * tree.total(1));
        EXPECT_GT(w[beyond], 0.0);
        EXPECT_EQ(tree.sample(1, 0.0), 0u);
    }
}

//- samplePair walks two columns at once: the leaves of two sample() calls, bit for bit, in a
//  cache-resident tree and in one big enough for the prefetching walk (> 512 kB)
TEST(SumTree, SamplePairGivesTheLeavesOfTwoSamples)
{
    for (std::size_t n : {std::size_t(300), std::size_t(40000)}) {
        SumTree tree;
        tree.reset(3, n);
        Rng rng(7);
        for (std::size_t j = 0; j < n; ++j) {
            for (std::size_t c = 0; c < 3; ++c) tree.set(j, c, j % 5 == c ? 0.0 : rng.uniform());
        }
        tree.rebuild();
        std::vector<double> leafData(n);
        for (int d = 0; d < 20000; ++d) {
            const std::size_t c1 = d % 3, c2 = (d / 3) % 3;
            const double u1 = rng.uniform() * tree.total(c1);
            const double u2 = rng.uniform() * tree.total(c2);
            std::size_t j1 = 0, j2 = 0;
            tree.samplePair(c1, u1, c2, u2, leafData.data(), sizeof(double), j1, j2);
            ASSERT_EQ(j1, tree.sample(c1, u1)) << n;
            ASSERT_EQ(j2, tree.sample(c2, u2)) << n;
        }
    }
}
