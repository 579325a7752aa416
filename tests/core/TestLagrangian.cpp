// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
// The Lagrangian trajectory methods of Kolodko-Sabelfeld-Wagner §3-5 (second part):
// the tabulated normalised homogeneous problem (2.32)/(2.33), the Saffman-Turner constant (5.2),
// the trajectory integrators (3.2)/(3.6)/(4.1)/(4.2), the point-source (§4.1), adjoint
// (4.3)/(4.4), direct (3.14) and realisation (4.5) estimators, the functionals (5.5)-(5.8).
// Fixed seeds; the statistical checks use intervals computed from their own samples.
#include "TestHelpers.hpp"

#include "coagulationReferences/smoluchowski/ExactSolutions.hpp"
#include "coagulationReferences/lagrangian/LagrangianCoagulation.hpp"
#include "coagulationReferences/pseudoTurbulence/PseudoTurbulence.hpp"
#include "coagulationReferences/smoluchowski/SmoluchowskiReference.hpp"

#include <cmath>
#include <complex>
#include <cstdio>
#include <vector>

using namespace coagtest;

namespace {

constexpr double twoPi = 6.283185307179586476925286766559;

// The paper's §5 setting in Kolmogorov units (x' = x/eta, t' = t/tau_eta): epsilon' = 1,
// kmax = 2 pi / eta' = 2 pi, k0 = 2 pi / L'.
PseudoTurbulenceParameters kolmogorovUnits(double Lprime, int n0 = 4, int n = 8)
{
    PseudoTurbulenceParameters p;
    p.epsilon = 1.0;
    p.k0 = twoPi / Lprime;
    p.kmax = twoPi;
    p.logIntervals = n0;
    p.nPerInterval = n;
    return p;
}

double dist(const double a[3], const double b[3])
{
    return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                     (a[2] - b[2]) * (a[2] - b[2]));
}

// Solid-body rotation about z, forced along x and z in time: u = (-y + a cos t, x, cos t), a = 1/2
// (time and position do not commute here, so a backward trajectory that reads v at the wrong
// time is caught). Exact, with w = x + i y: w(T) = e^{iT} [w0 + a/2 (T + (1 - e^{-2iT})/(2i))],
// z(T) = z0 + sin T.
constexpr double forcing = 0.5;
void rotation(double t, const double x[3], double u[3])
{
    u[0] = -x[1] + forcing * std::cos(t);
    u[1] = x[0];
    u[2] = std::cos(t);
}

// The steady ABC flow (divergence-free, chaotic streamlines): a field without closed orbits.
void abcFlow(double, const double x[3], double u[3])
{
    const double A = 1.0, B = 0.8, C = 0.6;
    u[0] = A * std::sin(x[2]) + C * std::cos(x[1]);
    u[1] = B * std::sin(x[0]) + A * std::cos(x[2]);
    u[2] = C * std::sin(x[1]) + B * std::cos(x[0]);
}

} // namespace

TEST(Lagrangian, SaffmanTurnerConstant)
{
    // (5.2): K_ij = (pi^2 eps / (120 nu))^(1/2) V1 (i^(1/3) + j^(1/3))^3, K_11 = 8 K0
    const double K0 = saffmanTurnerK0(2.0, 1.5e-5, 3e-24);
    EXPECT_NEAR(K0, std::sqrt(M_PI * M_PI * 2.0 / (120.0 * 1.5e-5)) * 3e-24, 1e-12 * K0);
    SaffmanTurnerKernel k(K0);
    EXPECT_NEAR(k(ParticleType{1.0}, ParticleType{1.0}), 8.0 * K0, 1e-14 * K0);
    EXPECT_NEAR(k(ParticleType{1.0}, ParticleType{8.0}), 27.0 * K0, 1e-13 * K0);
    EXPECT_THROW(saffmanTurnerK0(-1.0, 1.0, 1.0), std::invalid_argument);
}

TEST(Lagrangian, TableMatchesConstantKernelExactSolution)
{
    // constant kernel K0 = 3: k_ij = 1 after (2.32)'s normalisation; exact f_l(s) with K0 = 1
    ConstantKernel k(3.0);
    double err20 = 0.0, err10 = 0.0;
    for (std::size_t M : {20u, 40u}) {
        const auto t = HomogeneousTable::fromOde(k, 4.0, 128, M);
        EXPECT_LT(std::abs(t.lostMass()), 1e-12);
        double e = 0.0;
        for (int i = 0; i < 40; ++i) {
            const double s = 4.0 * (i + 0.37) / 40.0;
            for (std::size_t l = 1; l <= 8; ++l)
                e = std::max(e, std::abs(t.density(l, s) - exact::constantKernelDensity(1.0, 1.0, s, l)));
            EXPECT_NEAR(t.total(s), 1.0 / (1.0 + s / 2.0), 2e-5);
            EXPECT_NEAR(t.mass(s), 1.0, 1e-9);
        }
        (M == 20 ? err10 : err20) = e;
    }
    std::printf("table vs exact (constant kernel): max error %.3g (20 intervals), %.3g (40), "
                "ratio %.1f (cubic Hermite: 16)\n", err10, err20, err10 / err20);
    EXPECT_LT(err20, 5e-6);
    EXPECT_GT(err10 / err20, 10.0);   // fourth order between nodes
    const auto t = HomogeneousTable::fromOde(k, 4.0, 128, 10);
    EXPECT_THROW(t.density(1, 4.01), std::out_of_range);
}

TEST(Lagrangian, TableScalingRelation)
{
    // (2.33): n_l(t) = n f_l(n K_11 t) for the unnormalised Saffman-Turner kernel (5.2)
    const double K0 = 0.37, n = 2.5, time = 0.6;
    SaffmanTurnerKernel k(K0);
    const auto table = HomogeneousTable::fromOde(k, n * 8.0 * K0 * time, 64, 40);
    DiscreteSmoluchowski ode(k, 64);
    ode.setTolerances(1e-11, 1e-15);
    Eigen::VectorXd n0 = Eigen::VectorXd::Zero(64);
    n0[0] = n;
    const Eigen::VectorXd nt = ode.integrate(n0, 0.0, time);
    double e = 0.0;
    for (std::size_t l = 1; l <= 12; ++l)
        e = std::max(e, std::abs(nt[Eigen::Index(l - 1)] - n * table.density(l, n * 8.0 * K0 * time)) / n);
    std::printf("(2.33) scaling: max |n_l - n f_l| / n = %.3g\n", e);
    EXPECT_LT(e, 1e-9);
}

TEST(Lagrangian, TableFromNanbuMethod)
{
    // The paper's alternative (§2.1): Nanbu tables over R seeds against the ODE table; the
    // Nanbu method converges to the finite-difference scheme (2.27), O(alpha) from the ODE.
    ConstantKernel k(2.0);
    const double alpha = 0.02, s = 0.8;
    const auto ode = HomogeneousTable::fromOde(k, 1.0, 64, 20);
    const int R = 6;
    std::vector<RunningStatistics> st(3);
    for (int r = 0; r < R; ++r) {
        const auto nb = HomogeneousTable::fromNanbu(k, 1.0, 64, 20000, alpha, seedFor(17, r));
        EXPECT_FALSE(nb.hermite());
        for (std::size_t l = 1; l <= 3; ++l) st[l - 1].add(nb.density(l, s));
    }
    for (std::size_t l = 1; l <= 3; ++l) {
        const double ref = exact::constantKernelDensity(1.0, 1.0, s, l);   // k_ij = 1 after (2.32)
        EXPECT_NEAR(ode.density(l, s), ref, 1e-6);
        const double tol = 4.0 * st[l - 1].standardError() + 2.0 * alpha * ref;
        std::printf("Nanbu table f_%zu(%.1f) = %.5f +- %.5f, exact %.5f\n", l, s, st[l - 1].mean(),
                    st[l - 1].standardError(), ref);
        EXPECT_NEAR(st[l - 1].mean(), ref, tol);
    }
}

TEST(Trajectory, OrderOfConvergenceOnRotation)
{
    const VelocityField v = rotation;
    const double T = 2.0, x0[3] = {1.0, 0.5, -0.3};
    const std::complex<double> I(0.0, 1.0);
    const std::complex<double> w = std::exp(I * T) *
        (std::complex<double>(x0[0], x0[1]) + forcing / 2.0 * (T + (1.0 - std::exp(-2.0 * I * T)) / (2.0 * I)));
    const double exact[3] = {w.real(), w.imag(), x0[2] + std::sin(T)};
    for (TrajectoryScheme s : {TrajectoryScheme::Euler, TrajectoryScheme::Heun, TrajectoryScheme::RK4}) {
        std::vector<double> errF, errB;
        for (int M : {16, 32, 64, 128}) {
            TrajectoryOptions o;
            o.scheme = s;
            o.maxStep = T / M;
            double x[3] = {x0[0], x0[1], x0[2]};
            forwardTrajectory(v, o, 0.0, T, x);
            errF.push_back(dist(x, exact));
            // backward (3.6) from the exact arrival point at time T goes back to x0
            double y[3] = {exact[0], exact[1], exact[2]};
            backwardTrajectory(v, o, T, y);
            errB.push_back(dist(y, x0));
        }
        const double pF = std::log2(errF[2] / errF[3]), pB = std::log2(errB[2] / errB[3]);
        std::printf("%s: errors %.3g %.3g %.3g %.3g, order %.3f forward, %.3f backward\n",
                    trajectorySchemeName(s).c_str(), errF[0], errF[1], errF[2], errF[3], pF, pB);
        const double p = trajectorySchemeOrder(s);
        EXPECT_NEAR(pF, p, 0.15);
        EXPECT_NEAR(pB, p, 0.15);
    }
}

TEST(Trajectory, BackwardThenForwardReturns)
{
    // a steady field: forward from X*(t, x) returns to x, to the integrator's order
    const VelocityField v = abcFlow;
    const double T = 3.0, x0[3] = {0.3, -1.2, 2.0};
    for (TrajectoryScheme s : {TrajectoryScheme::Euler, TrajectoryScheme::Heun, TrajectoryScheme::RK4}) {
        std::vector<double> err;
        for (int M : {32, 64, 128}) {
            TrajectoryOptions o{s, T / M};
            double x[3] = {x0[0], x0[1], x0[2]};
            backwardTrajectory(v, o, T, x);
            forwardTrajectory(v, o, 0.0, T, x);
            err.push_back(dist(x, x0));
        }
        const double p = std::log2(err[1] / err[2]);
        std::printf("ABC %s: return errors %.3g %.3g %.3g, order %.2f\n",
                    trajectorySchemeName(s).c_str(), err[0], err[1], err[2], p);
        // the round trip's leading errors of the two legs cancel for a symmetric scheme, so
        // the order is at least the scheme's
        EXPECT_GT(p, trajectorySchemeOrder(s) - 0.2);
        EXPECT_LT(err[2], trajectorySchemeOrder(s) == 4 ? 1e-7 : 0.05);
    }
    // a pseudo-turbulence sample at the tutorials' step (RK4, dt' = 0.05, t' = 1.25)
    PseudoTurbulence field(kolmogorovUnits(1000.0), 4242);
    const VelocityField vt = velocityField(field);
    double worst = 0.0;
    for (int i = 0; i < 20; ++i) {
        double x[3] = {7.0 * i, -3.0 * i, 11.0}, y[3] = {x[0], x[1], x[2]};
        backwardTrajectory(vt, TrajectoryOptions{}, 1.25, y);
        forwardTrajectory(vt, TrajectoryOptions{}, 0.0, 1.25, y);
        worst = std::max(worst, dist(x, y));
    }
    std::printf("pseudo-turbulence (L' = 1000, 32 harmonics): max return error %.3g eta\n", worst);
    EXPECT_LT(worst, 1e-3);
}

TEST(Lagrangian, ZeroVelocityReproducesHomogeneousSolution)
{
    // v = 0: every estimator gives the homogeneous solution from the local source (5.3)
    SaffmanTurnerKernel k(1.0 / 8.0);   // K_11 = 1
    const double rate = 0.7, t = 1.5;   // S K_11 = 0.7
    const auto table = HomogeneousTable::fromOde(k, rate * t, 64, 40);
    InitialSource src{InitialSource::Profile::Linear, Sphere{{{1.0, 2.0, 3.0}}, 10.0}};
    LagrangianSolution sol(table, src, rate, 8);
    const VelocityField zero = uniformVelocity(0.0, 0.0, 0.0);
    SaffmanTurnerKernel kS(rate / 8.0);   // the unnormalised problem with S = 1
    DiscreteSmoluchowski ode(kS, 64);
    ode.setTolerances(1e-11, 1e-15);
    for (double rho : {0.0, 2.5, 7.0, 9.9}) {
        const double x[3] = {1.0 + rho, 2.0, 3.0};
        const Score sc = adjointPoint(zero, TrajectoryOptions{}, sol, t, x);
        Eigen::VectorXd n0 = Eigen::VectorXd::Zero(64);
        n0[0] = 1.0 - rho / 10.0;
        const Eigen::VectorXd n = ode.integrate(n0, 0.0, t);
        for (std::size_t l = 1; l <= 8; ++l)
            EXPECT_NEAR(sc.sizes[l - 1], n[Eigen::Index(l - 1)], 1e-9) << "rho " << rho << " l " << l;
    }
    // Monte Carlo integrals over Omega_r with v = 0 against the radial quadrature (5.22)-(5.25)
    for (double r : {4.0, 10.0, 14.0}) {
        const Sphere omega{src.D.centre, r};
        const IntegralEstimate a = adjointIntegral(zero, TrajectoryOptions{}, sol, t, omega, 4000, 5);
        const IntegralEstimate d = directIntegrals(zero, TrajectoryOptions{}, sol, t, {omega}, 4000, 6)[0];
        const SphereFunctionals det = deterministicFunctionals(sol, t, r);
        std::printf("v = 0, r = %g: In adjoint %.4f +- %.4f, direct %.4f +- %.4f, quadrature %.4f\n",
                    r, a.total, a.totalSe, d.total, d.totalSe, det.In);
        EXPECT_NEAR(a.total, det.In, 4.0 * a.totalSe);
        EXPECT_NEAR(d.total, det.In, 4.0 * d.totalSe);
        for (std::size_t l = 1; l <= 4; ++l) EXPECT_NEAR(a.sizes[l - 1], det.In_l[l - 1], 4.0 * a.sizesSe[l - 1]);
        EXPECT_NEAR(a.mass, det.Ms * det.In, 4.0 * a.massSe);
    }
    // (5.7), (5.8): Ms = mass / In, Sp_l = In_l / In
    for (double r : {4.0, 10.0}) {
        const SphereFunctionals f = deterministicFunctionals(sol, t, r);
        for (std::size_t l = 0; l < 8; ++l) EXPECT_NEAR(f.Sp[l] * f.In, f.In_l[l], 1e-12 * f.In);
        double sum = 0.0;
        for (double x : f.Sp) sum += x;
        EXPECT_LT(sum, 1.0);
    }
    // (5.24): deterministic Ms of the linear source in closed form
    const SphereFunctionals det = deterministicFunctionals(sol, t, 5.0);
    const double massClosed = 4.0 / 3.0 * M_PI * 125.0 * (1.0 - 0.75 * 0.5);
    EXPECT_NEAR(det.Ms * det.In, massClosed * table.mass(rate * t) , 1e-6 * massClosed);
}

TEST(Lagrangian, UniformTranslationShiftsExactly)
{
    SaffmanTurnerKernel k(1.0 / 8.0);
    const double rate = 0.5, t = 2.0, c[3] = {1.5, -0.5, 0.25};
    const auto table = HomogeneousTable::fromOde(k, rate * t, 32, 20);
    InitialSource src{InitialSource::Profile::Linear, Sphere{{{0.0, 0.0, 0.0}}, 5.0}};
    LagrangianSolution sol(table, src, rate, 6);
    const VelocityField v = uniformVelocity(c[0], c[1], c[2]);
    for (TrajectoryScheme s : {TrajectoryScheme::Euler, TrajectoryScheme::RK4}) {
        TrajectoryOptions o{s, 0.05};
        for (int i = 0; i < 10; ++i) {
            const double x[3] = {0.7 * i - 2.0, 0.3 * i, -0.2 * i + 1.0};
            const double x0[3] = {x[0] - c[0] * t, x[1] - c[1] * t, x[2] - c[2] * t};
            const Score a = adjointPoint(v, o, sol, t, x);
            Score b;
            sol.fromOrigin(x0, t, b);   // n(t, x) = n_hom(t; S^I(x - c t))
            for (std::size_t l = 0; l < 6; ++l) EXPECT_NEAR(a.sizes[l], b.sizes[l], 1e-12);
            EXPECT_NEAR(a.total, b.total, 1e-12);
        }
    }
    // point source (§4.1): x_i = x* + c tau_i, n_l = S^P(T - tau) f_l(S^P(T - tau) rate tau)
    const double xs[3] = {1.0, 2.0, 3.0};
    auto SP = [](double time) { return 1.0 + 0.5 * std::sin(time); };
    const auto ps = pointSource(v, TrajectoryOptions{TrajectoryScheme::RK4, 0.1}, table, rate, 6, xs, t, SP);
    ASSERT_EQ(ps.size(), 21u);
    for (const PointSourceSample& p : ps) {
        for (int d = 0; d < 3; ++d) EXPECT_NEAR(p.x[d], xs[d] + c[d] * p.tau, 1e-12);
        const double sp = SP(t - p.tau);
        for (std::size_t l = 1; l <= 6; ++l)
            EXPECT_NEAR(p.n.sizes[l - 1], sp * table.density(l, sp * rate * p.tau), 1e-14);
    }
    EXPECT_NEAR(ps.back().tau, t, 1e-14);
    EXPECT_NEAR(ps.front().n.sizes[0], SP(t), 1e-14);   // just emitted: monomers only
}

TEST(Lagrangian, DirectAndAdjointAgreeInPseudoTurbulence)
{
    // one frozen field sample; the integral over a ball that D's image only partly covers
    SaffmanTurnerKernel k(1.0 / 8.0);
    const double rate = 0.2, t = 2.0;
    const auto table = HomogeneousTable::fromOde(k, rate * t, 32, 20);
    InitialSource src{InitialSource::Profile::Linear, Sphere{{{0.0, 0.0, 0.0}}, 10.0}};
    LagrangianSolution sol(table, src, rate, 4);
    PseudoTurbulence field(kolmogorovUnits(100.0), 99);
    const VelocityField v = velocityField(field);
    const Sphere omega{{{6.0, 2.0, 0.0}}, 7.0};
    const IntegralEstimate a = adjointIntegral(v, TrajectoryOptions{}, sol, t, omega, 4000, 11);
    const IntegralEstimate d = directIntegrals(v, TrajectoryOptions{}, sol, t, {omega}, 4000, 12)[0];
    std::printf("direct In %.3f +- %.3f (hits %zu), adjoint %.3f +- %.3f (hits %zu)\n", d.total,
                d.totalSe, d.hits, a.total, a.totalSe, a.hits);
    auto agree = [](double x, double sx, double y, double sy) {
        return std::abs(x - y) <= 3.0 * std::sqrt(sx * sx + sy * sy);
    };
    EXPECT_TRUE(agree(d.total, d.totalSe, a.total, a.totalSe));
    EXPECT_TRUE(agree(d.mass, d.massSe, a.mass, a.massSe));
    for (std::size_t l = 0; l < 4; ++l)
        EXPECT_TRUE(agree(d.sizes[l], d.sizesSe[l], a.sizes[l], a.sizesSe[l])) << "l = " << l + 1;
    // v = 0 gives a different value here (the field matters)
    const IntegralEstimate z = adjointIntegral(uniformVelocity(0, 0, 0), TrajectoryOptions{}, sol, t, omega, 4000, 11);
    EXPECT_FALSE(agree(z.total, z.totalSe, a.total, a.totalSe));
}

TEST(Lagrangian, RealisationIntervalIsStudentT)
{
    RealisationStatistics st;
    for (double x : {1.0, 2.0, 3.0}) st.add({x, 2.0 * x});
    EXPECT_EQ(st.count(), 3u);
    EXPECT_NEAR(st.mean()[0], 2.0, 1e-15);
    // t_{0.975, 2} = 4.302653; sd = 1 and 2
    EXPECT_NEAR(st.halfWidth95()[0], 4.302653 / std::sqrt(3.0), 1e-5);
    EXPECT_NEAR(st.halfWidth95()[1], 2.0 * 4.302653 / std::sqrt(3.0), 1e-5);
}

TEST(Lagrangian, ExpectationFunctionalsAreRatiosOfMeans)
{
    // three realisations: In = 1, 3, 0 (none in Omega), In_1 = 1, 1, 0, mass = 1, 5, 0
    ExpectationFunctionals ef;
    auto est = [](double total, double in1, double mass) {
        IntegralEstimate e;
        e.total = total;
        e.mass = mass;
        e.sizes = {in1, total - in1};
        return e;
    };
    ef.add(est(1.0, 1.0, 1.0));
    ef.add(est(3.0, 1.0, 5.0));
    ef.add(est(0.0, 0.0, 0.0));
    EXPECT_EQ(ef.count(), 3u);
    const SphereFunctionals m = ef.mean(), h = ef.halfWidth95();
    EXPECT_NEAR(m.In, 4.0 / 3.0, 1e-15);
    // <Sp_1> = <In_1>/<In> = 0.5, not the mean of the ratios 1 and 1/3 (2/3), nor 4/9 with 0 for
    // the empty realisation; <Ms> = 6/4
    EXPECT_NEAR(m.Sp[0], 0.5, 1e-15);
    EXPECT_NEAR(m.Sp[1], 0.5, 1e-15);
    EXPECT_NEAR(m.Ms, 1.5, 1e-15);
    // delta method: residuals In_1 - 0.5 In = 0.5, -0.5, 0: sd 0.5; t_{0.975,2} = 4.302653
    EXPECT_NEAR(h.Sp[0], 4.302653 * 0.5 / std::sqrt(3.0) / (4.0 / 3.0), 1e-6);
    // mass - 1.5 In = -0.5, 0.5, 0: sd 0.5
    EXPECT_NEAR(h.Ms, 4.302653 * 0.5 / std::sqrt(3.0) / (4.0 / 3.0), 1e-6);
    EXPECT_NEAR(h.In, 4.302653 * std::sqrt(7.0 / 3.0) / std::sqrt(3.0), 1e-6);
}

namespace {

// Realisations (4.5) of the functionals over Omega_r by the adjoint estimator, the paper's
// parameters (beta = 0.0039, L' = 1000, R' = 100) at t' = 1.25.
struct StudyResult {
    SphereFunctionals mean, hw, det;
};

StudyResult paperStudy(InitialSource::Profile profile, double r, int R, std::size_t N, std::uint64_t seed)
{
    static SaffmanTurnerKernel k(1.0 / 8.0);
    const double beta = 0.0039, t = 1.25;
    static const auto table = HomogeneousTable::fromOde(k, beta * 55.0, 64, 200);
    InitialSource src{profile, Sphere{{{0.0, 0.0, 0.0}}, 100.0}};
    LagrangianSolution sol(table, src, beta, 12);
    ExpectationFunctionals st;   // the paper's <Sp> = <In_l>/<In>, <Ms> = <mass>/<In>
    for (int i = 0; i < R; ++i) {
        PseudoTurbulence field(kolmogorovUnits(1000.0), seedFor(seed, i));
        st.add(adjointIntegral(velocityField(field), TrajectoryOptions{}, sol, t,
                               Sphere{{{0.0, 0.0, 0.0}}, r}, N, seedFor(seed + 1, i)));
    }
    return {st.mean(), st.halfWidth95(), deterministicFunctionals(sol, t, r)};
}

} // namespace

TEST(Lagrangian, UniformSourceMeanSizeAndSpectrumUnchanged)
{
    // the identity after (5.20): <Ms> = Ms-bar, <Sp> = Sp-bar for the uniform source
    const StudyResult s = paperStudy(InitialSource::Profile::Uniform, 100.0, 12, 300, 71);
    std::printf("uniform, r' = R': <In>/S %.1f +- %.1f, det %.1f; <Ms> %.8f +- %.2g, det %.8f\n",
                s.mean.In, s.hw.In, s.det.In, s.mean.Ms, s.hw.Ms, s.det.Ms);
    // after (5.20): Ms = sum_i i f_i(beta t') / sum_i f_i(beta t'), Sp_l = f_l(beta t') / sum_i f_i
    static SaffmanTurnerKernel k(1.0 / 8.0);
    const auto table = HomogeneousTable::fromOde(k, 0.0039 * 55.0, 64, 200);   // as paperStudy
    const double s1 = 0.0039 * 1.25, msPaper = table.mass(s1) / table.total(s1);
    EXPECT_NEAR(s.det.Ms, msPaper, 1e-9);
    EXPECT_NEAR(s.mean.Ms, msPaper, s.hw.Ms + 1e-9);
    for (std::size_t l = 0; l < 12; ++l) {
        const double spPaper = table.density(l + 1, s1) / table.total(s1);
        EXPECT_NEAR(s.det.Sp[l], spPaper, 1e-7 * spPaper) << "l = " << l + 1;
        EXPECT_NEAR(s.mean.Sp[l], spPaper, s.hw.Sp[l] + 1e-7 * spPaper) << "l = " << l + 1;
    }
    // particles leave D: fewer clusters in Omega_R' than without transport (Fig 1's r' = R')
    EXPECT_LT(s.mean.In + s.hw.In, s.det.In);
}

TEST(Lagrangian, LinearSourceStochasticSpectrumBelowDeterministic)
{
    // Figs 3 and 7 at t' = 1.25, r' = 0.1 R': fewer large clusters and a smaller mean size
    const StudyResult s = paperStudy(InitialSource::Profile::Linear, 10.0, 12, 300, 72);
    for (std::size_t l : {1u, 5u, 6u, 8u, 10u})
        std::printf("linear, r' = 10: Sp_%zu %.4g +- %.2g, det %.4g\n", l, s.mean.Sp[l - 1],
                    s.hw.Sp[l - 1], s.det.Sp[l - 1]);
    std::printf("linear, r' = 10: <Ms> - 1 = %.6g +- %.2g, det %.6g\n", s.mean.Ms - 1.0, s.hw.Ms,
                s.det.Ms - 1.0);
    for (std::size_t l = 5; l <= 10; ++l)
        EXPECT_LT(s.mean.Sp[l - 1] + s.hw.Sp[l - 1], s.det.Sp[l - 1]) << "l = " << l;
    EXPECT_LT(s.mean.Ms + s.hw.Ms, s.det.Ms);
    // at r' = R' the difference (relative to the value) is much smaller than at r' = 0.1 R'
    const StudyResult b = paperStudy(InitialSource::Profile::Linear, 100.0, 12, 1500, 73);
    for (std::size_t l = 5; l <= 10; ++l) {
        std::printf("Sp_%zu / det: %.3f +- %.3f at r' = 10, %.3f +- %.3f at r' = 100\n", l,
                    s.mean.Sp[l - 1] / s.det.Sp[l - 1], s.hw.Sp[l - 1] / s.det.Sp[l - 1],
                    b.mean.Sp[l - 1] / b.det.Sp[l - 1], b.hw.Sp[l - 1] / b.det.Sp[l - 1]);
        EXPECT_NEAR(b.mean.Sp[l - 1], b.det.Sp[l - 1], b.hw.Sp[l - 1]) << "l = " << l;
    }
}
