// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
// The deterministic ODE reference (Dormand-Prince on the truncated discrete system) against
// exact solutions, and the exact solutions against their own moment formulas.
#include "TestHelpers.hpp"

using namespace coagtest;

namespace {

Eigen::VectorXd monomers(std::size_t L, double N0)
{
    Eigen::VectorXd n = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(L));
    n[0] = N0;
    return n;
}

} // namespace

TEST(OdeReference, MatchesConstantKernelExactSolution)
{
    const double K0 = 1.5, N0 = 2.0;
    ConstantKernel kernel(K0);
    const std::size_t L = 300;
    DiscreteSmoluchowski ode(kernel, L);
    Eigen::VectorXd n = monomers(L, N0);
    double t = 0.0;
    for (double t1 : {0.25, 1.0, 2.0}) {
        n = ode.integrate(n, t, t1);
        t = t1;
        for (std::size_t k = 1; k <= 30; ++k) {
            const double ex = exact::constantKernelDensity(K0, N0, t, k);
            EXPECT_NEAR(n[static_cast<Eigen::Index>(k - 1)], ex, 1e-6 * ex) << "k = " << k << ", t = " << t;
        }
    }
    EXPECT_GT(ode.acceptedSteps(), 0u);
}

TEST(OdeReference, MatchesAdditiveKernelExactSolution)
{
    const double K0 = 1.0, N0 = 1.0;
    AdditiveKernel kernel(K0);
    const std::size_t L = 800;
    DiscreteSmoluchowski ode(kernel, L);
    Eigen::VectorXd n = monomers(L, N0);
    double t = 0.0;
    for (double t1 : {0.3, 1.0}) {
        n = ode.integrate(n, t, t1);
        t = t1;
        for (std::size_t k = 1; k <= 30; ++k) {
            const double ex = exact::additiveKernelDensity(K0, N0, t, k);
            EXPECT_NEAR(n[static_cast<Eigen::Index>(k - 1)], ex, 1e-6 * ex) << "k = " << k << ", t = " << t;
        }
    }
}

TEST(OdeReference, MatchesMultiplicativeKernelExactSolutionBeforeGelation)
{
    MultiplicativeKernel kernel(1.0);
    const std::size_t L = 400;
    DiscreteSmoluchowski ode(kernel, L);
    const Eigen::VectorXd n = ode.integrate(monomers(L, 1.0), 0.0, 0.5);
    for (std::size_t k = 1; k <= 20; ++k) {
        const double ex = exact::multiplicativeKernelDensity(1.0, 1.0, 0.5, k);
        EXPECT_NEAR(n[static_cast<Eigen::Index>(k - 1)], ex, 1e-6 * ex) << "k = " << k;
    }
}

TEST(OdeReference, ConstantSourceMomentsMatch)
{
    const double K0 = 1.0, I = 2.0, t = 1.5;
    ConstantKernel kernel(K0);
    const std::size_t L = 400;
    Eigen::VectorXd F = Eigen::VectorXd::Zero(1);
    F[0] = I;
    DiscreteSmoluchowski ode(kernel, L, F);
    const Eigen::VectorXd n = ode.integrate(Eigen::VectorXd::Zero(static_cast<Eigen::Index>(L)), 0.0, t);
    std::array<double, 4> m{0, 0, 0, 0};
    for (std::size_t l = 1; l <= L; ++l) {
        double p = 1.0;
        for (int k = 0; k < 4; ++k) {
            m[k] += p * n[static_cast<Eigen::Index>(l - 1)];
            p *= double(l);
        }
    }
    const auto ex = exact::constantKernelSourceMoments(K0, I, t);
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(m[k], ex[k], 1e-6 * ex[k]) << "m" << k;
}

TEST(ExactSolutions, DensitiesSumToTheMoments)
{
    const double K0 = 0.8, N0 = 1.3;
    for (double t : {0.1, 0.5}) {
        std::array<double, 4> c{0, 0, 0, 0}, a{0, 0, 0, 0}, m{0, 0, 0, 0};
        for (std::size_t k = 1; k <= 4000; ++k) {
            double p = 1.0;
            for (int j = 0; j < 4; ++j) {
                c[j] += p * exact::constantKernelDensity(K0, N0, t, k);
                a[j] += p * exact::additiveKernelDensity(K0, N0, t, k);
                m[j] += p * exact::multiplicativeKernelDensity(K0, N0, t, k);
                p *= double(k);
            }
        }
        const auto ce = exact::constantKernelMoments(K0, N0, t);
        const auto ae = exact::additiveKernelMoments(K0, N0, t);
        const auto me = exact::multiplicativeKernelMoments(K0, N0, t);
        for (int j = 0; j < 4; ++j) {
            EXPECT_NEAR(c[j], ce[j], 1e-9 * ce[j]) << "constant m" << j;
            EXPECT_NEAR(a[j], ae[j], 1e-9 * ae[j]) << "additive m" << j;
            EXPECT_NEAR(m[j], me[j], 1e-9 * me[j]) << "multiplicative m" << j;
        }
    }
    EXPECT_THROW(exact::multiplicativeKernelMoments(1.0, 1.0, 1.0), std::domain_error);
}
