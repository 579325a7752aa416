// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
// The stochastic Lagrangian model of Sabelfeld-Kolodko: the table of the normalised
// homogeneous problem (18), the trajectories (8)/(16), the direct (15) and adjoint (16)-(17)
// estimators against the exact Gaussian integral (19)/(23), the effective source (20) against
// its closed form for uniform data and the bound F_R (22)-(23), and the §7 study (29)-(30).
// Fixed seeds; every interval comes from the run (95 %, iid samples).
#include "TestHelpers.hpp"

#include "coagulationReferences/coagulationDiffusion/CoagulationDiffusionLagrangian.hpp"
#include "coagulationReferences/coagulationDiffusion/CoagulationDiffusionReference.hpp"
#include "coagulationReferences/smoluchowski/ExactSolutions.hpp"

#include <cmath>
#include <iostream>

using namespace coagtest;

namespace {

//- "No coagulation": K = 1e-12, so u_1 = 1 to 1e-11 on the times used here.
const ConstantKernel& noCoagulation()
{
    static const ConstantKernel k(1e-12);
    return k;
}

Box box2(double x0, double x1, double y0, double y1)
{
    Box b;
    b.dim = 2;
    b.lo = {{x0, y0, 0}};
    b.hi = {{x1, y1, 0}};
    return b;
}

//- Gauss-Legendre (5 points) on n panels of [a, b].
template <class F> double quad(F f, double a, double b, int n = 200)
{
    static const double xg[5] = {-0.9061798459386640, -0.5384693101056831, 0.0,
                                 0.5384693101056831, 0.9061798459386640};
    static const double wg[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                                 0.4786286704993665, 0.2369268850561891};
    double s = 0.0;
    const double h = (b - a) / n;
    for (int k = 0; k < n; ++k) {
        const double c = a + (k + 0.5) * h;
        for (int g = 0; g < 5; ++g) s += wg[g] * f(c + 0.5 * h * xg[g]);
    }
    return 0.5 * h * s;
}

//- 95 % checks of independent estimates: under the null each misses with probability 0.05, so
//  the number outside is binomial(n, 0.05); the test allows the largest k with
//  P(Bin(n, 0.05) > k) >= 0.005 and every |z| < 4 (z = error / (half-width / quantile)). Sizes
//  of one estimate share their paths: only counted ones enter n (the others enter max |z|).
struct Tally {
    int n = 0, outside = 0;
    double maxZ = 0.0;
    void check(double mean, double hw, double quantile, double exact, bool count)
    {
        const double z = hw > 0.0 ? (mean - exact) / (hw / quantile) : (mean == exact ? 0.0 : 1e300);
        maxZ = std::max(maxZ, std::abs(z));
        if (!count) return;
        ++n;
        outside += !(std::abs(mean - exact) <= hw);  // NaN counts as outside
    }
    void check(const Estimate& e, std::size_t l, double exact, bool count = true)
    {
        check(e.mean[l - 1], e.halfWidth[l - 1], 1.959963984540054, exact, count);
    }
    void check(const EffectiveSource& F, double exact)
    {
        check(F.F, F.halfWidth, 2.063898561628021, exact, true);
    }
    int allowed() const
    {
        double pk = std::pow(0.95, n), cdf = pk;  // P(X = 0)
        int k = 0;
        while (1.0 - cdf >= 0.005 && k < n) {
            pk *= (n - k) / (k + 1.0) * 0.05 / 0.95;
            cdf += pk;
            ++k;
        }
        return k;
    }
    void expect(const char* what) const
    {
        std::cout << "[" << what << "] " << outside << " of " << n
                  << " estimates outside their 95 % interval (allowed " << allowed()
                  << "), largest |z| " << maxZ << "\n";
        EXPECT_LE(outside, allowed()) << what;
        EXPECT_LT(maxZ, 4.0) << what;
    }
};

} // namespace

TEST(LagrangianDiffusion, HomogeneousTableMatchesExactConstantKernel)
{
    ConstantKernel K(1.0);
    const HomogeneousTable table = table18(K, 300, 20.0, 20, 400);
    double worstRel = 0.0, worstAbs = 0.0;  // relative where u_l > 1e-4; absolute everywhere
    for (double tau : {0.013, 0.77, 3.3333, 9.99, 19.7})
        for (std::size_t l : {1, 2, 5, 10}) {
            const double ex = exact::constantKernelDensity(1.0, 1.0, tau, l);
            const double err = std::abs(table.density(l, tau) - ex);
            worstAbs = std::max(worstAbs, err);
            if (ex > 1e-4) worstRel = std::max(worstRel, err / ex);
        }
    std::cout << "[table] u_l(tau), l <= 10: largest relative error (u_l > 1e-4) " << worstRel
              << ", largest absolute error " << worstAbs << "\n";
    EXPECT_LT(worstRel, 1e-7);
    EXPECT_LT(worstAbs, 2e-9);
    // rho(t; delta_1l f) = f u(f t): the exact solution from n0 = f
    std::vector<double> r(table.sizes());
    for (double f : {0.5, 2.0}) {
        table.solution(f, 4.0, r.data());
        for (std::size_t l : {1, 3, 7})
            EXPECT_NEAR(r[l - 1] / exact::constantKernelDensity(1.0, f, 4.0, l), 1.0, 1e-7)
                << "f " << f << " l " << l;
    }
    EXPECT_THROW(table.density(1, 20.5), std::out_of_range);
}

//- Pure diffusion (no coagulation) and K = 1 with uniform data: I_l = u_l(n0 t) times the
//  Gaussian integral, exactly (rho is the same everywhere in the support). Direct and adjoint,
//  2-D at three (t, Omega) each, and one 3-D case; every estimate within its 95 % interval.
TEST(LagrangianDiffusion, DirectAndAdjointMatchTheGaussianIntegral)
{
    ConstantKernel K1(1.0);
    const double n0 = 1.5;
    const HomogeneousTable diffusionOnly = table18(noCoagulation(), 10, 10.0, 1, 10);
    const HomogeneousTable coag = table18(K1, 300, 10.0 * n0, 5, 400);
    DiffusionProcess p;
    p.dim = 2;
    p.D = 0.0888;
    MonodisperseData data;
    data.support = Box::centred(2, 1.0);
    data.n0 = n0;
    Tally tally;
    std::uint64_t seed = 1600;
    for (const HomogeneousTable* table : {&diffusionOnly, &coag}) {
        LagrangianEstimator est(*table, p, data);
        for (double t : {0.5, 2.0, 5.0})
            for (const Box& omega : {box2(-0.25, 0.25, -0.25, 0.25), box2(0.6, 1.1, 0.1, 0.5),
                                     box2(1.2, 1.8, -0.3, 0.3)}) {
                const double G = exact::diffusedBoxIntegral(n0, data.support, omega, p.D, t);
                const Estimate d = est.direct(t, omega, 40000, ++seed);
                const Estimate a = est.adjoint(t, omega, 20000, ++seed);
                for (std::size_t l = 1; l <= table->sizes(); ++l) {
                    const double u = table == &diffusionOnly
                                         ? 1.0
                                         : exact::constantKernelDensity(1.0, 1.0, n0 * t, l);
                    const double ex = G * u;
                    tally.check(d, l, ex, l == 1);
                    tally.check(a, l, ex, l == 1);
                    if (l == 1)
                        std::cout << "  t " << t << " Omega x [" << omega.lo[0] << ", "
                                  << omega.hi[0] << "] exact " << ex << " direct " << d.mean[0]
                                  << " +- " << d.halfWidth[0] << " adjoint " << a.mean[0]
                                  << " +- " << a.halfWidth[0] << "\n";
                }
            }
    }
    // 3-D: the cube [-1, 1]^3, Omega a box across its face
    DiffusionProcess p3 = p;
    p3.dim = 3;
    p3.D = 0.2;
    MonodisperseData d3;
    d3.support = Box::centred(3, 1.0);
    LagrangianEstimator est3(diffusionOnly, p3, d3);
    Box omega3 = Box::centred(3, 0.3);
    omega3.lo[0] += 0.9;
    omega3.hi[0] += 0.9;
    const double G3 = exact::diffusedBoxIntegral(1.0, d3.support, omega3, p3.D, 1.0);
    const Estimate d = est3.direct(1.0, omega3, 100000, 1690);
    const Estimate a = est3.adjoint(1.0, omega3, 20000, 1691);
    std::cout << "[pure diffusion 3-D] exact " << G3 << " direct " << d.mean[0] << " +- "
              << d.halfWidth[0] << " adjoint " << a.mean[0] << " +- " << a.halfWidth[0] << "\n";
    tally.check(d, 1, G3);
    tally.check(a, 1, G3);
    tally.expect("Gaussian integral");
}

//- v != 0: a constant drift (both estimators; the backward path runs against the drift) and a
//  rigid rotation (adjoint at points: n(t, x) is the Gaussian integral at R(-omega t) x).
TEST(LagrangianDiffusion, DriftAndRotation)
{
    const HomogeneousTable table = table18(noCoagulation(), 10, 10.0, 1, 10);
    MonodisperseData data;
    data.support = Box::centred(2, 1.0);
    const double v[2] = {0.6, -0.4};
    DiffusionProcess p;
    p.dim = 2;
    p.D = 0.05;
    p.dt = 0.1;
    p.velocity = [v](double, const double*, double* out) {
        out[0] = v[0];
        out[1] = v[1];
    };
    LagrangianEstimator est(table, p, data);
    const double t = 1.5;
    const Box omega = box2(0.5, 1.5, -1.0, 0.0);
    const double ex = exact::diffusedBoxIntegral(1.0, data.support, omega, p.D, t, v);
    const Estimate d = est.direct(t, omega, 40000, 1700);
    const Estimate a = est.adjoint(t, omega, 40000, 1701);
    std::cout << "[constant drift] exact " << ex << " direct " << d.mean[0] << " +- "
              << d.halfWidth[0] << " adjoint " << a.mean[0] << " +- " << a.halfWidth[0] << "\n";
    Tally tally;
    tally.check(d, 1, ex);
    tally.check(a, 1, ex);

    const double w = 1.0;
    DiffusionProcess rot = p;
    rot.dt = 0.02;
    rot.velocity = [w](double, const double* x, double* out) {
        out[0] = -w * x[1];
        out[1] = w * x[0];
    };
    std::uint64_t seed = 1702;
    // Euler-Maruyama is weakly first order: at dt = 0.02 its rotation spirals out (radius
    // (1 + w^2 dt^2)^(t/2dt)), a 3 % bias here; dt = 0.005 and N = 10000 for it, 0.02 and 40000 for Heun.
    for (auto scheme : {DiffusionProcess::Scheme::Heun, DiffusionProcess::Scheme::EulerMaruyama}) {
        rot.scheme = scheme;
        const bool heun = scheme == DiffusionProcess::Scheme::Heun;
        rot.dt = heun ? 0.02 : 0.005;
        LagrangianEstimator er(table, rot, data);
        for (const std::array<double, 2>& x : {std::array<double, 2>{{1.0, 0.5}},
                                               std::array<double, 2>{{-0.3, 1.1}}}) {
            const double c = std::cos(w * t), s = std::sin(w * t);
            const double back[2] = {c * x[0] + s * x[1], -s * x[0] + c * x[1]};
            const double exr = exact::diffusedBoxDensity(1.0, data.support, rot.D, t, back);
            const Estimate e = er.adjointPoint(t, x.data(), heun ? 40000 : 10000, ++seed);
            std::cout << "[rotation] x (" << x[0] << ", " << x[1] << ") exact " << exr
                      << " adjoint " << e.mean[0] << " +- " << e.halfWidth[0] << "\n";
            tally.check(e, 1, exr);
        }
    }
    tally.expect("drift and rotation");
}

//- With coagulation and non-uniform data f = 1 + 0.5 x, the Saffman-Turner kernel, r not
//  uniform (r ~ f): the direct and the adjoint estimator agree, sizes 1..5. One fixed-seed
//  comparison: at the 95 % interval of the difference it would fail one stream in twenty
//  (seeds 1800/1801 gave z = 2.5 after the engine change; 15 other pairs gave
//  |z| <= 1.7), so the bound is twice that half-width, 3.9 standard deviations.
TEST(LagrangianDiffusion, DirectAndAdjointAgreeWithCoagulation)
{
    SaffmanTurnerKernel K(1.0 / 8.0);
    const double t = 1.0;
    const HomogeneousTable table = table18(K, 200, 1.5 * t, 5, 200);
    MonodisperseData data;
    data.support = Box::centred(2, 1.0);
    data.f = [](const double* x) { return 1.0 + 0.5 * x[0]; };
    DiffusionProcess p;
    p.dim = 2;
    p.D = 0.1;
    LagrangianEstimator est(table, p, data);
    Density r;  // r(x) = f(x)/4 on [-1, 1]^2 (int f = 4), drawn by rejection
    r.pdf = [](const double* x) { return (1.0 + 0.5 * x[0]) / 4.0; };
    r.draw = [](Rng& g, double* x) {
        do {
            x[0] = -1.0 + 2.0 * g.uniform();
        } while (1.5 * g.uniform() > 1.0 + 0.5 * x[0]);
        x[1] = -1.0 + 2.0 * g.uniform();
    };
    const Box omega = box2(-0.5, 0.5, 0.0, 1.0);
    auto h = [](const double* x) { return 1.0 + x[1]; };
    const Estimate d = est.direct(t, omega, 100000, 1800, h, r);
    const Estimate a = est.adjoint(t, omega, 40000, 1801, h);
    for (std::size_t l = 1; l <= 5; ++l) {
        const double diff = d.mean[l - 1] - a.mean[l - 1];
        const double hw = std::hypot(d.halfWidth[l - 1], a.halfWidth[l - 1]);
        std::cout << "[coagulation] l " << l << " direct " << d.mean[l - 1] << " +- "
                  << d.halfWidth[l - 1] << " adjoint " << a.mean[l - 1] << " +- "
                  << a.halfWidth[l - 1] << "\n";
        EXPECT_LT(std::abs(diff), 2.0 * hw) << "l " << l;
    }
}

//- D = 0: the estimators reduce to the homogeneous solution of the earlier paper (the
//  Saffman-Turner system integrated by DiscreteSmoluchowski, not by the table).
TEST(LagrangianDiffusion, NoDiffusionIsTheHomogeneousSolution)
{
    SaffmanTurnerKernel K(1.0 / 8.0);
    const double t = 2.0;
    const HomogeneousTable table = table18(K, 200, 2.0 * t, 10, 200);
    MonodisperseData data;
    data.support = Box::centred(2, 1.0);
    data.f = [](const double* x) { return 1.5 + 0.5 * x[0]; };
    DiffusionProcess p;
    p.dim = 2;
    p.D = 0.0;
    LagrangianEstimator est(table, p, data);
    DiscreteSmoluchowski ode(K, 200);
    for (double x0 : {-0.7, 0.4}) {
        const double x[2] = {x0, 0.2};
        const double f = 1.5 + 0.5 * x0;
        Eigen::VectorXd n = Eigen::VectorXd::Zero(200);
        n(0) = f;
        const Eigen::VectorXd ref = ode.integrate(n, 0.0, t);
        const Estimate e = est.adjointPoint(t, x, 10, 1900);
        for (std::size_t l = 1; l <= 10; ++l) {
            EXPECT_NEAR(e.mean[l - 1] / ref(l - 1), 1.0, 1e-6) << "x " << x0 << " l " << l;
            EXPECT_LT(e.halfWidth[l - 1], 1e-6 * e.mean[l - 1]);  // the same score (rounding only)
        }
    }
    // direct, uniform n0 = 2 inside: exactly n0 u(n0 t) |Omega| (every path stays)
    MonodisperseData uni;
    uni.support = Box::centred(2, 1.0);
    uni.n0 = 2.0;
    LagrangianEstimator eu(table, p, uni);
    const Box omega = box2(-0.5, 0.5, -0.5, 0.0);
    const Estimate e = eu.direct(t, omega, 20000, 1901);
    Eigen::VectorXd n = Eigen::VectorXd::Zero(200);
    n(0) = 2.0;
    const Eigen::VectorXd ref = ode.integrate(n, 0.0, t);
    // the fraction of xi in Omega is binomial: compare within the interval
    for (std::size_t l = 1; l <= 3; ++l) EXPECT_TRUE(e.covers(l, ref(l - 1) * 0.5)) << l;
}

//- Coverage: 200 independent pure-diffusion point estimates (N = 400 each); the number of 95 %
//  intervals that contain the exact value is binomial(200, 0.95): 190 +- 3.1; accept 178..198.
TEST(LagrangianDiffusion, IntervalsCoverAtTheirLevel)
{
    const HomogeneousTable table = table18(noCoagulation(), 10, 10.0, 1, 10);
    MonodisperseData data;
    data.support = Box::centred(2, 1.0);
    DiffusionProcess p;
    p.dim = 2;
    p.D = 0.0888;
    LagrangianEstimator est(table, p, data);
    const double x[2] = {0.9, 0.3};
    const double ex = exact::diffusedBoxDensity(1.0, data.support, p.D, 3.0, x);
    int cover = 0;
    for (int r = 0; r < 200; ++r) cover += est.adjointPoint(3.0, x, 400, seedFor(2000, r)).covers(1, ex);
    std::cout << "[coverage] " << cover << " of 200 intervals contain the exact value\n";
    EXPECT_GE(cover, 178);
    EXPECT_LE(cover, 198);
}

//- F (20) for uniform data: rho = n0 u(n0 t) on G, so E[rho_i rho_j] - E rho_i E rho_j =
//  n0^2 u_i u_j P (1 - P), P the Gaussian mass (23); the Monte Carlo F covers it, and it lies
//  below F_R (22). 2-D square and 3-D cube.
TEST(LagrangianDiffusion, EffectiveSourceClosedFormAndBound)
{
    ConstantKernel K(1.0);
    const double n0 = 1.0;
    const HomogeneousTable table = table18(K, 300, 10.0, 20, 400);
    const double C = kernelBoundConstant(K, 100);
    EXPECT_DOUBLE_EQ(C, 1.0);
    Tally tally;
    for (int dim : {2, 3}) {
        DiffusionProcess p;
        p.dim = dim;
        p.D = 0.0888;
        MonodisperseData data;
        data.support = Box::centred(dim, 1.0);
        data.n0 = n0;
        LagrangianEstimator est(table, p, data);
        for (double t : {1.0, 5.0})
            for (double x0 : {0.0, 1.0}) {
                const double x[3] = {x0, 0.0, 0.0};
                const double P = gaussianBoxMass(dim, 1.0, p.D, t, x);
                std::vector<double> u(table.sizes());
                table.solution(n0, t, u.data());
                double S = 0.0;
                for (std::size_t i = 0; i < u.size(); ++i)
                    for (std::size_t j = 0; j < u.size(); ++j)
                        S += table.kernelMatrix()(i, j) * u[i] * u[j];
                const double exF = P * (1.0 - P) * S;
                const EffectiveSource F = est.effectiveSource(t, x, 20000, 2100 + dim);
                const double FR = effectiveSourceBound(dim, n0, C, 1.0, p.D, t, x);
                std::cout << "[F] dim " << dim << " t' " << t << " x " << x0 << ": F " << F.F
                          << " +- " << F.halfWidth << " (closed form " << exF << "), F_R " << FR
                          << "\n";
                tally.check(F, exF);
                EXPECT_LT(F.F + F.halfWidth, FR);
            }
    }
    tally.expect("effective source");
}

//- F_R (22)-(23) against quadrature of the Gaussian pdf over the cube/square.
TEST(LagrangianDiffusion, BoundAgainstQuadrature)
{
    const double R = 1.0, D = 0.355, n0 = 2.0, C = 1.3;
    for (double t : {0.1, 1.0, 4.0})
        for (const std::array<double, 3>& x :
             {std::array<double, 3>{{0, 0, 0}}, std::array<double, 3>{{0.7, -1.2, 0.4}}}) {
            const double sigma = std::sqrt(2.0 * D * t);
            double P2 = 1.0, P3 = 1.0;
            for (int i = 0; i < 3; ++i) {
                const double fi = quad(
                    [&](double y) {
                        return std::exp(-0.5 * (x[i] - y) * (x[i] - y) / (sigma * sigma)) /
                               (sigma * std::sqrt(2.0 * M_PI));
                    },
                    -R, R);
                if (i < 2) P2 *= fi;
                P3 *= fi;
            }
            EXPECT_NEAR(effectiveSourceBound(2, n0, C, R, D, t, x.data()),
                        1.5 * n0 * n0 * C * P2 * (1.0 - P2), 1e-10);
            EXPECT_NEAR(effectiveSourceBound(3, n0, C, R, D, t, x.data()),
                        1.5 * n0 * n0 * C * P3 * (1.0 - P3), 1e-10);
        }
    SaffmanTurnerKernel st(1.0 / 8.0);
    EXPECT_NEAR(kernelBoundConstant(st, 50), 1.0, 1e-12);
}

//- §7: N^D (29) and N^CD = u_1(b t') N^D (30), Saffman-Turner normalised to K11 = 1, in units
//  t' = t/T_D (D' = 1), x' = x/R, b = T_D/T_C (the kernel scaled by b). The adjoint estimator
//  covers the formula; N^CD ~ N^D at b = 0.01 and more than 100 % apart at b = 1, from the
//  formula and from the estimator's intervals (independent seeds for N^D and N^CD).
TEST(LagrangianDiffusion, TurbulentStudySection7)
{
    const double tp = 1.0;
    const HomogeneousTable diffusionOnly = table18(noCoagulation(), 10, 10.0, 1, 10);
    DiffusionProcess p;
    p.dim = 2;
    p.D = 1.0;
    MonodisperseData data;
    data.support = Box::centred(2, 1.0);
    Tally tally;
    std::uint64_t seed = 2200;  // independent paths for every estimate
    for (const std::array<double, 2>& x : {std::array<double, 2>{{0.0, 0.0}},
                                           std::array<double, 2>{{1.5, 0.0}}}) {
        const double ND = exact::diffusedSquare(1.0, 1.0, 1.0, tp, x[0], x[1]);  // (29)
        const Estimate eD =
            LagrangianEstimator(diffusionOnly, p, data).adjointPoint(tp, x.data(), 40000, ++seed);
        tally.check(eD, 1, ND);
        for (double b : {0.01, 0.1, 1.0}) {
            SaffmanTurnerKernel K(b / 8.0);
            const HomogeneousTable table = table18(K, 200, tp, 1, 100);
            const double NCD = table.density(1, tp) * ND;  // (30)
            const Estimate e =
                LagrangianEstimator(table, p, data).adjointPoint(tp, x.data(), 40000, ++seed);
            const double rel = (ND - NCD) / NCD;
            const double relLo = eD.lower(1) / e.upper(1) - 1.0;
            const double relHi = eD.upper(1) / e.lower(1) - 1.0;
            std::cout << "[section 7] x' (" << x[0] << ", " << x[1] << ") b " << b << ": N^D "
                      << ND << " N^CD " << NCD << " estimator " << e.mean[0] << " +- "
                      << e.halfWidth[0] << "; (N^D - N^CD)/N^CD formula " << rel
                      << ", estimator [" << relLo << ", " << relHi << "]\n";
            tally.check(e, 1, NCD);
            if (b == 0.01) {
                EXPECT_LT(rel, 0.02);
                EXPECT_LT(relLo, 0.0);  // the intervals of N^D and N^CD overlap
            }
            if (b == 1.0) {
                EXPECT_GT(rel, 1.0);
                EXPECT_GT(relLo, 1.0);
            }
        }
    }
    tally.expect("section 7");
}

//- A compressible drift, the Ornstein-Uhlenbeck v = -a x: mu = exp(-a |x|^2 / (2D)) solves
//  div(v mu) = D Lap mu, so v* = v - (2D/mu) grad mu = a x (16) and the adjoint score carries
//  mu(t, xi)/mu(0, x0) (17). The forward transition is Gaussian with mean x0 e^{-at} and
//  variance D/a (1 - e^{-2at}): the exact I is a product of 1-D integrals (quadrature over x0).
//  The adjoint with mu, the direct estimator, and the exact value agree; the adjoint without
//  mu (v* = v, weight 1) must not.
TEST(LagrangianDiffusion, CompressibleDriftNeedsMu)
{
    const HomogeneousTable table = table18(noCoagulation(), 10, 10.0, 1, 10);
    const double a = 1.0, D = 0.1, t = 1.0;
    MonodisperseData data;
    data.support = box2(-1.0, 0.5, -0.5, 1.0);
    DiffusionProcess p;
    p.dim = 2;
    p.D = D;
    p.dt = 0.01;
    p.velocity = [a](double, const double* x, double* out) {
        out[0] = -a * x[0];
        out[1] = -a * x[1];
    };
    DiffusionProcess noMu = p;
    p.mu = [a, D](double, const double* x) {
        return std::exp(-a * (x[0] * x[0] + x[1] * x[1]) / (2.0 * D));
    };
    p.gradMu = [a, D](double, const double* x, double* g) {
        const double m = std::exp(-a * (x[0] * x[0] + x[1] * x[1]) / (2.0 * D));
        g[0] = -a * x[0] / D * m;
        g[1] = -a * x[1] / D * m;
    };
    const Box omega = box2(0.0, 0.6, -0.2, 0.4);
    const double decay = std::exp(-a * t), s = std::sqrt(D / a * (1.0 - std::exp(-2.0 * a * t)));
    double ex = 1.0;
    for (int i = 0; i < 2; ++i) {
        const double lo = omega.lo[i], hi = omega.hi[i];
        ex *= quad(
            [&](double x0) {
                const double m = x0 * decay;
                return 0.5 * (std::erf((hi - m) / (s * std::sqrt(2.0))) -
                              std::erf((lo - m) / (s * std::sqrt(2.0))));
            },
            data.support.lo[i], data.support.hi[i]);
    }
    const Estimate d = LagrangianEstimator(table, p, data).direct(t, omega, 40000, 2300);
    const Estimate ad = LagrangianEstimator(table, p, data).adjoint(t, omega, 40000, 2301);
    const Estimate wrong = LagrangianEstimator(table, noMu, data).adjoint(t, omega, 40000, 2302);
    std::cout << "[compressible] exact " << ex << " direct " << d.mean[0] << " +- "
              << d.halfWidth[0] << " adjoint with mu " << ad.mean[0] << " +- " << ad.halfWidth[0]
              << " adjoint with mu = 1 " << wrong.mean[0] << " +- " << wrong.halfWidth[0] << "\n";
    Tally tally;
    tally.check(d, 1, ex);
    tally.check(ad, 1, ex);
    tally.expect("compressible drift");
    EXPECT_GT(std::abs(wrong.mean[0] - ex), 4.0 * wrong.halfWidth[0]);
}
