// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
// The 2-D coagulation-diffusion collocation reference of Sabelfeld-Kolodko §6 against
// the discrete Smoluchowski system, the exact constant-kernel solution (no diffusion), the exact
// diffusion of the square (no coagulation), and its convergence in dx, dt and gamma.
#include "TestHelpers.hpp"

#include "coagulationReferences/coagulationDiffusion/CoagulationDiffusionReference.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>

using namespace coagtest;

namespace {

using Opt = CoagulationDiffusionOptions;

//- Homogeneous runs: D = 0 on a 4 x 4 quadrant grid; the node at the centre is a full cell
//  inside the square, so it evolves as the homogeneous system from n_1 = n0.
Opt homogeneous(double gamma, double dt, Opt::Scheme scheme, std::size_t Lambda = 14000)
{
    Opt o;
    o.diffusion = 0.0;
    o.halfWidth = 1.5;
    o.dx = 0.5;
    o.dt = dt;
    o.gamma = gamma;
    o.scheme = scheme;
    o.maxSize = Lambda;
    return o;
}

struct SizeErrors {
    double monomer = 0;
    double consecutive = 0;  // sizes 2..14: every size a node at gamma = 1.1
    double coarse = 0;       // sizes 15..20 (nodes 16, 17, 19; 15, 18, 20 interpolated)
};

//- Relative errors of n_l(t, 0) against the constant-kernel solution (K = n0 = 1), sizes
//  1..20 whose exact density is above 1e-6 (below it the relative error of the far tail at
//  early times says nothing).
SizeErrors constantKernelErrors(const CoagulationDiffusion2D& sol)
{
    SizeErrors e;
    for (std::size_t l = 1; l <= 20; ++l) {
        const double ex = exact::constantKernelDensity(1.0, 1.0, sol.time(), l);
        if (ex < 1e-6) continue;
        const double d = std::abs(sol.density(l, 0.0, 0.0) / ex - 1.0);
        double& m = l == 1 ? e.monomer : l <= 14 ? e.consecutive : e.coarse;
        m = std::max(m, d);
    }
    return e;
}

//- Largest relative error of pure diffusion against the exact square at grid points common
//  to dx = 0.14, 0.07, 0.035.
double diffusionError(const CoagulationDiffusion2D& sol)
{
    double e = 0.0;
    const double pts[][2] = {{0, 0}, {0.7, 0}, {0.7, 0.7}, {1.4, 0}, {1.4, 0.7}};
    for (const auto& p : pts) {
        const Opt& o = sol.options();
        const double ex = exact::diffusedSquare(o.n0, o.R, o.diffusion, sol.time(), p[0], p[1]);
        e = std::max(e, std::abs(sol.density(1, p[0], p[1]) / ex - 1.0));
    }
    return e;
}

Opt pureDiffusion(double dx, Opt::Scheme scheme)
{
    Opt o;
    o.coagulation = false;
    o.maxSize = 2;
    o.halfWidth = 4.0;
    o.dx = dx;
    o.dt = 0.0125 * (dx / 0.07) * (dx / 0.07);  // r = 0.2265 at D = 8.88e-2
    o.scheme = scheme;
    return o;
}

double order(double coarse, double fine, double ratio = 2.0)
{
    return std::log(coarse / fine) / std::log(ratio);
}

} // namespace

TEST(CoagulationDiffusion, CollocationNodes)
{
    ConstantKernel K(1.0);
    SizeCollocation s(K, 14000, 1.1);
    // distinct round(1.1^p) below 14000, then 14000: 1..14, 16, 17, 19, 21, 23, 26, ...
    const std::vector<std::size_t> first{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 16, 17, 19, 21, 23, 26};
    ASSERT_GE(s.nNodes(), first.size());
    for (std::size_t i = 0; i < first.size(); ++i) EXPECT_EQ(s.nodes()[i], first[i]);
    EXPECT_EQ(s.nodes().back(), 14000u);
    EXPECT_EQ(s.nNodes(), 87u);
}

//- With every size a node (gamma = 1.01 below size 100) the quadratic form is the discrete
//  Smoluchowski right hand side, for a size-dependent kernel.
TEST(CoagulationDiffusion, IntegerNodesGiveTheDiscreteSystem)
{
    SaffmanTurnerKernel K(0.125);
    const std::size_t L = 40;
    SizeCollocation s(K, L, 1.01);
    ASSERT_EQ(s.nNodes(), L);
    DiscreteSmoluchowski ode(K, L);
    std::mt19937 gen(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const std::ptrdiff_t pts = 3;
    Eigen::MatrixXd Y(pts, static_cast<Eigen::Index>(L)), R(pts, static_cast<Eigen::Index>(L));
    for (Eigen::Index k = 0; k < Y.size(); ++k) Y.data()[k] = u(gen) * std::exp(-0.1 * double(k / pts));
    s.rates(Y.data(), pts, pts, R.data(), pts);
    for (std::ptrdiff_t k = 0; k < pts; ++k) {
        const Eigen::VectorXd ref = ode.rhs(Y.row(k).transpose());
        for (Eigen::Index l = 0; l < ref.size(); ++l)
            EXPECT_NEAR(R(k, l), ref[l], 1e-12 * (1.0 + std::abs(ref[l]))) << "point " << k << ", size " << l + 1;
    }
}

TEST(CoagulationDiffusion, ConstantKernelWithoutDiffusion)
{
    ConstantKernel K(1.0);
    for (Opt::Scheme scheme : {Opt::Scheme::Heun, Opt::Scheme::Euler}) {
        const bool heun = scheme == Opt::Scheme::Heun;
        CoagulationDiffusion2D sol(K, homogeneous(1.1, 0.014, scheme));
        for (double t : {1.0, 5.0, 10.0}) {
            sol.advanceTo(t);
            const SizeErrors e = constantKernelErrors(sol);
            std::cout << "[ measured ] K = 1, D = 0, gamma 1.1, dt' 0.014, " << (heun ? "Heun" : "Euler")
                      << ", t' = " << sol.time() << ": monomer " << e.monomer
                      << ", sizes 2-14 " << e.consecutive << ", sizes 15-20 " << e.coarse << "\n";
            if (heun) {
                EXPECT_LT(e.monomer, 1e-3) << "t' = " << t;      // measured 7.4e-4 at t' = 10
                EXPECT_LT(e.consecutive, 3e-3) << "t' = " << t;  // 1.9e-3 at t' = 1 (size 14)
                EXPECT_LT(e.coarse, 0.1) << "t' = " << t;        // interpolation: 8.7e-2 at t' = 5
            } else {
                EXPECT_LT(e.monomer, 0.012) << "t' = " << t;  // first order: 1.08e-2 at t' = 10
            }
            // the centre is uniform data: its neighbour inside the square agrees
            EXPECT_NEAR(sol.density(1, 0.5, 0.5), sol.density(1, 0.0, 0.0), 1e-14);
        }
    }
}

TEST(CoagulationDiffusion, DiffusionWithoutCoagulation)
{
    ConstantKernel K(1.0);
    for (Opt::Scheme scheme : {Opt::Scheme::Euler, Opt::Scheme::Heun}) {
        CoagulationDiffusion2D sol(K, pureDiffusion(0.07, scheme));
        for (double t : {1.0, 5.0}) {
            sol.advanceTo(t);
            const double e = diffusionError(sol);
            std::cout << "[ measured ] pure diffusion D = 8.88e-2, dx' 0.07, dt' 0.0125, "
                      << (scheme == Opt::Scheme::Heun ? "Heun" : "Euler") << ", t' = " << sol.time()
                      << ": max relative error at 5 points " << e << "\n";
            EXPECT_LT(e, 5e-3) << "t' = " << t;
        }
    }
    // zero flux: the number of particles is conserved exactly
    Opt o = pureDiffusion(0.14, Opt::Scheme::Euler);
    o.halfWidth = 2.0;
    o.boundary = Opt::Boundary::ZeroFlux;
    CoagulationDiffusion2D closed(K, o);
    closed.advanceTo(10.0);
    EXPECT_NEAR(closed.totalNumber(), 4.0, 1e-10);
}

TEST(CoagulationDiffusion, RejectsUnstableSteps)
{
    ConstantKernel K(1.0);
    Opt o;
    o.maxSize = 100;
    o.dt = 0.014;  // the paper's pair: r = 8.88e-2 * 0.014 / 0.07^2 = 0.2537
    EXPECT_THROW(CoagulationDiffusion2D(K, o), std::invalid_argument);
    o.dt = 0.0137;  // r = 0.2483
    EXPECT_NO_THROW(CoagulationDiffusion2D(K, o));
}

TEST(CoagulationDiffusion, ConvergesInSpaceAndTime)
{
    ConstantKernel K(1.0);
    // space (dt proportional to dx^2): pure diffusion at t' = 1
    std::vector<double> e;
    for (double dx : {0.14, 0.07, 0.035}) {
        CoagulationDiffusion2D sol(K, pureDiffusion(dx, Opt::Scheme::Euler));
        sol.advanceTo(1.0);
        e.push_back(diffusionError(sol));
    }
    std::cout << "[ measured ] diffusion errors dx' 0.14, 0.07, 0.035: " << e[0] << " " << e[1] << " "
              << e[2] << "; orders " << order(e[0], e[1]) << " " << order(e[1], e[2]) << "\n";
    EXPECT_GT(order(e[0], e[1]), 1.8);
    EXPECT_GT(order(e[1], e[2]), 1.8);

    // time: every size a node (no size error), the monomer and size 5 at t' = 5
    for (Opt::Scheme scheme : {Opt::Scheme::Euler, Opt::Scheme::Heun}) {
        std::vector<double> et;
        for (double dt : {0.05, 0.025, 0.0125}) {
            CoagulationDiffusion2D sol(K, homogeneous(1.01, dt, scheme, 60));
            sol.advanceTo(5.0);
            double m = 0.0;
            for (std::size_t l : {1u, 5u})
                m = std::max(m, std::abs(sol.density(l, 0, 0) / exact::constantKernelDensity(1, 1, sol.time(), l) - 1));
            et.push_back(m);
        }
        const bool heun = scheme == Opt::Scheme::Heun;
        std::cout << "[ measured ] " << (heun ? "Heun" : "Euler") << " time errors dt' 0.05, 0.025, 0.0125: "
                  << et[0] << " " << et[1] << " " << et[2] << "; orders " << order(et[0], et[1]) << " "
                  << order(et[1], et[2]) << "\n";
        const double p = heun ? 2.0 : 1.0;
        EXPECT_NEAR(order(et[0], et[1]), p, 0.2);
        EXPECT_NEAR(order(et[1], et[2]), p, 0.2);
    }

    // size grid: gamma 1.2, 1.1, 1.05 (Heun, dt' 0.014), monomers at t' = 10
    std::vector<double> eg;
    for (double gamma : {1.2, 1.1, 1.05}) {
        CoagulationDiffusion2D sol(K, homogeneous(gamma, 0.014, Opt::Scheme::Heun));
        sol.advanceTo(10.0);
        eg.push_back(constantKernelErrors(sol).monomer);
    }
    std::cout << "[ measured ] gamma 1.2, 1.1, 1.05 monomer errors at t' = 10: " << eg[0] << " " << eg[1]
              << " " << eg[2] << "; orders in (gamma - 1) " << order(eg[0], eg[1]) << " "
              << order(eg[1], eg[2]) << "\n";
    EXPECT_GT(order(eg[0], eg[1]), 2.0);
    EXPECT_GT(order(eg[1], eg[2]), 2.0);
}
