// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
// CostFit: the least-squares cost of a cell step that cellWork prints
#include "TestHelpers.hpp"

#include "coagulation/decomposition/CostFit.hpp"

#include <cmath>

using namespace coagtest;

namespace {

//- Cells of a duct-like step: events and particles varying independently, some cells not
//  stepped; seconds from known costs plus uniform noise of half-width `noise`
CostFit synthetic(std::uint64_t seed, int n, double noise)
{
    Rng rng(seed);
    CostFit fit;
    for (int i = 0; i < n; ++i) {
        const double events = std::floor(1e5 * rng.uniform());
        const double particles = std::floor(3e3 * rng.uniform());
        const double stepped = rng.uniform() < 0.8 ? 1.0 : 0.0;
        const double t = 150e-9 * events + 60e-9 * particles + 2e-6 * stepped
                         + noise * (2.0 * rng.uniform() - 1.0);
        fit.add(events, particles, stepped, t);
    }
    return fit;
}

} // namespace

//- Exact data give the costs to round-off; noisy data give them within 4 of the fit's own
//  standard errors (fixed seeds, 20 data sets of 500 cells: the errors mean what they say
//  when the residuals are independent, as here), and the errors shrink as 1/sqrt(n)
TEST(CostFit, RecoversTheCostsWithinItsStandardErrors)
{
    const double truth[3] = {150e-9, 60e-9, 2e-6};
    const CostFit::Result exact = synthetic(1, 200, 0.0).solve();
    ASSERT_TRUE(exact.determined);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(exact.coef[i], truth[i], 1e-9 * truth[i] + 1e-15);

    int outside2 = 0;
    for (std::uint64_t s = 0; s < 20; ++s) {
        const CostFit::Result r = synthetic(100 + s, 500, 1e-4).solve();
        ASSERT_TRUE(r.determined);
        for (int i = 0; i < 3; ++i) {
            ASSERT_GT(r.stdErr[i], 0.0);
            const double z = (r.coef[i] - truth[i]) / r.stdErr[i];
            EXPECT_LT(std::abs(z), 4.0) << "data set " << s << " coefficient " << i;
            outside2 += std::abs(z) > 2.0;
        }
    }
    EXPECT_LE(outside2, 9);  // 60 coefficients, about 3 expected outside 2 standard errors
    const CostFit::Result small = synthetic(7, 400, 1e-4).solve();
    const CostFit::Result large = synthetic(8, 6400, 1e-4).solve();
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(large.stdErr[i] / small.stdErr[i], 0.25, 0.06) << "coefficient " << i;
    }
}

//- Regressors that move together, a column of zeros, too few observations: undetermined,
//  and never a NaN (the case that stopped a decomposed run: three cells whose events and
//  particles kept their ratio over the steps)
TEST(CostFit, UndeterminedWhereTheDataHoldNoFit)
{
    CostFit collinear;  // events = 40 particles in every cell, every cell stepped
    CostFit nearly;     // the same with the ratio wandering by 1e-6
    CostFit unstepped;  // no cell stepped: the visit's column is zero
    Rng rng(3);
    for (int i = 0; i < 750; ++i) {
        const double p = 3000.0 + 10.0 * rng.uniform();
        collinear.add(40.0 * p, p, 1.0, 2e-3 * rng.uniform());
        nearly.add(40.0 * p * (1.0 + 1e-6 * rng.uniform()), p, 1.0, 2e-3 * rng.uniform());
        unstepped.add(40.0 * rng.uniform(), p, 0.0, 1e-3 * rng.uniform());
    }
    EXPECT_FALSE(collinear.solve().determined);
    EXPECT_FALSE(unstepped.solve().determined);
    const CostFit::Result r = nearly.solve();
    EXPECT_FALSE(r.determined);
    for (int i = 0; i < 3; ++i) {
        EXPECT_FALSE(std::isnan(r.coef[i]));
        EXPECT_FALSE(std::isnan(r.stdErr[i]));
    }
    CostFit few;
    few.add(1, 2, 1, 1e-6);
    few.add(3, 1, 0, 2e-6);
    few.add(2, 5, 1, 3e-6);
    EXPECT_FALSE(few.solve().determined);  // 3 observations for 3 coefficients
    few.add(7, 1, 1, 4e-6);
    EXPECT_TRUE(few.solve().determined);
    few.add(std::nan(""), 1, 1, 1e-6);
    EXPECT_EQ(few.count(), 4u);
    EXPECT_EQ(few.skipped(), 1u);
    few.clear();
    EXPECT_EQ(few.count(), 0u);
    EXPECT_FALSE(few.solve().determined);
}

//- cellWork's ratios: eventCost = c0 / p and visit = c2 / p, p = move + c1, with the delta
//  method's errors (J cov J^T, J = (1/p, -e/p, 0) and (0, -v/p, 1/p)); undetermined where the
//  fit is, nothing moved, or p is not above a tenth of a move (the fit of a 3-cell
//  processor put p at or below zero, and the errors overflowed), never infinite or NaN
TEST(CostFit, RelativeCostsOnlyWhereAParticleCostsSomething)
{
    CostFit::Result r;
    r.determined = true;
    r.coef = {90e-9, 25e-9, -6e-6};
    r.cov = {{{4e-19, 1e-19, 2e-17}, {1e-19, 9e-18, -3e-17}, {2e-17, -3e-17, 1e-10}}};
    const double m = 250e-9;
    const CostFit::Relative q = CostFit::relative(r, m);
    ASSERT_TRUE(q.determined);
    const double p = m + r.coef[1];
    EXPECT_DOUBLE_EQ(q.eventCost, r.coef[0] / p);
    EXPECT_DOUBLE_EQ(q.visit, r.coef[2] / p);
    const double Je[3] = {1.0 / p, -q.eventCost / p, 0.0};
    const double Jv[3] = {0.0, -q.visit / p, 1.0 / p};
    double ve = 0.0, vv = 0.0;
    for (int i = 0; i < 3; ++i) {
        for (int k = 0; k < 3; ++k) {
            ve += Je[i] * r.cov[i][k] * Je[k];
            vv += Jv[i] * r.cov[i][k] * Jv[k];
        }
    }
    EXPECT_NEAR(q.eventCostErr, std::sqrt(ve), 1e-12 * std::sqrt(ve));
    EXPECT_NEAR(q.visitErr, std::sqrt(vv), 1e-12 * std::sqrt(vv));

    for (const double c1 : {-m, -0.95 * m, -m + 1e-300, -1e300, std::nan("")}) {
        CostFit::Result bad = r;
        bad.coef[1] = c1;
        const CostFit::Relative b = CostFit::relative(bad, m);
        EXPECT_FALSE(b.determined) << c1;
        EXPECT_TRUE(std::isfinite(b.eventCost) && std::isfinite(b.eventCostErr)) << c1;
    }
    EXPECT_TRUE(CostFit::relative(r, m).determined);
    EXPECT_FALSE(CostFit::relative(r, 0.0).determined);  // nothing moved
    EXPECT_FALSE(CostFit::relative(r, std::nan("")).determined);
    r.determined = false;
    EXPECT_FALSE(CostFit::relative(r, m).determined);
}
