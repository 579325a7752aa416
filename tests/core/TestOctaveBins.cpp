// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
// OctaveBins (issue 19): the half-octave binned store of MajorantSampler. Its draws must be
// exactly proportional to the values after any sequence of changes, appends and removals,
// and its totals a function of the current values alone (no drift).
#include "coagulation/OctaveBins.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace coag;

namespace {

//- Values over many octaves, some in the same half-octave, a few exactly at a bin's bottom
//  (powers of two: the lowest acceptance), some zero.
double someValue(Rng& rng, std::size_t j)
{
    if (j % 11 == 3) return 0.0;
    if (j % 7 == 0) return std::ldexp(1.0, static_cast<int>(j % 13) - 6);
    return std::ldexp(0.5 + rng.uniform(), static_cast<int>(rng.uniformIndex(24)) - 12);
}

struct Mirror {
    std::vector<std::vector<double>> v;  // [column][leaf]
};

//- A random sequence of set / append / removeBySwap on the bins and a plain mirror
void churn(OctaveBins& bins, Mirror& m, Rng& rng, int steps)
{
    const std::size_t nc = bins.columns();
    for (int s = 0; s < steps; ++s) {
        const double r = rng.uniform();
        const std::size_t n = bins.size();
        if (r < 0.6 && n > 0) {
            const std::size_t j = rng.uniformIndex(n);
            const std::size_t c = rng.uniformIndex(nc);
            const double v = someValue(rng, j + s);
            bins.set(j, c, v);
            m.v[c][j] = v;
        } else if (r < 0.8 || n < 4) {
            std::vector<double> v(nc);
            for (std::size_t c = 0; c < nc; ++c) {
                v[c] = someValue(rng, n + c + s);
                m.v[c].push_back(v[c]);
            }
            bins.append(v.data());
        } else {
            const std::size_t j = rng.uniformIndex(n);
            bins.removeBySwap(j, n - 1);
            for (std::size_t c = 0; c < nc; ++c) {
                m.v[c][j] = m.v[c][n - 1];
                m.v[c].pop_back();
            }
        }
    }
}

TEST(OctaveBins, TotalsEqualAFreshBuildBitForBit)
{
    OctaveBins bins;
    Mirror m;
    const std::size_t nc = 3, n0 = 200;
    bins.reset(nc, 64);  // grows past its capacity by append
    m.v.assign(nc, {});
    Rng rng(11);
    for (std::size_t j = 0; j < n0; ++j) {
        std::vector<double> v(nc);
        for (std::size_t c = 0; c < nc; ++c) {
            v[c] = someValue(rng, j + c);
            m.v[c].push_back(v[c]);
        }
        bins.append(v.data());
    }
    churn(bins, m, rng, 5000);
    ASSERT_EQ(bins.size(), m.v[0].size());
    OctaveBins fresh;
    fresh.reset(nc, bins.size());
    for (std::size_t c = 0; c < nc; ++c) {
        double direct = 0.0;
        for (std::size_t j = 0; j < bins.size(); ++j) {
            ASSERT_EQ(bins.value(j, c), m.v[c][j]) << j;
            fresh.stage(j, c, m.v[c][j]);
            direct += m.v[c][j];
        }
        fresh.finishBuild(bins.size());
        EXPECT_EQ(bins.total(c), fresh.total(c)) << c;  // bit for bit: no drift
        EXPECT_NEAR(bins.total(c), direct, 1e-12 * direct) << c;
    }
}

//- After churn, each column's draws against value / total by chi-square over the leaves
//  (fixed seed; the 0.1 % critical value for the degrees of freedom)
TEST(OctaveBins, DrawsAreProportionalToTheValues)
{
    OctaveBins bins;
    Mirror m;
    const std::size_t nc = 2;
    bins.reset(nc, 8);
    m.v.assign(nc, {});
    Rng rng(5);
    for (std::size_t j = 0; j < 40; ++j) {
        std::vector<double> v(nc);
        for (std::size_t c = 0; c < nc; ++c) {
            v[c] = someValue(rng, j + 5 * c);
            m.v[c].push_back(v[c]);
        }
        bins.append(v.data());
    }
    churn(bins, m, rng, 3000);
    const std::size_t n = bins.size();
    ASSERT_GE(n, 10u);
    const int draws = 300000;
    for (std::size_t c = 0; c < nc; ++c) {
        const double total = bins.total(c);
        std::vector<double> count(n, 0.0), count2(n, 0.0);
        for (int d = 0; d < draws; ++d) {
            const std::size_t j = bins.sample(c, rng.uniform() * total, rng);
            ASSERT_LT(j, n);
            ASSERT_GT(m.v[c][j], 0.0) << "a zero value drawn";
            count[j] += 1.0;
            std::size_t a = 0, b = 0;  // the pair draw, both factors from column c
            bins.samplePair(c, rng.uniform() * total, c, rng.uniform() * total, rng, a, b);
            count2[a] += 0.5;
            count2[b] += 0.5;
        }
        double chi2 = 0.0, chi2pair = 0.0;
        int dof = -1;
        for (std::size_t j = 0; j < n; ++j) {
            const double e = draws * m.v[c][j] / total;
            if (e == 0.0) continue;
            chi2 += (count[j] - e) * (count[j] - e) / e;
            chi2pair += (count2[j] - e) * (count2[j] - e) / (0.5 * e);  // 2 draws of half weight
            ++dof;
        }
        // 0.1 % critical value of chi-square (Wilson-Hilferty)
        const double z = 3.09, k = dof;
        const double crit = k * std::pow(1.0 - 2.0 / (9.0 * k) + z * std::sqrt(2.0 / (9.0 * k)), 3);
        EXPECT_LT(chi2, crit) << "column " << c << ", " << dof << " degrees of freedom";
        EXPECT_LT(chi2pair, crit) << "pairs, column " << c << ", " << dof << " degrees of freedom";
    }
}

} // namespace
