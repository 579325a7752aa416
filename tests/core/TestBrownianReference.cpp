// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
// The stochastic algorithms with the Brownian kernels against the deterministic reference:
// from a monodisperse start every mass is a multiple of the first one, so the discrete
// Smoluchowski equation (DiscreteSmoluchowski, Dormand–Prince, truncated far in the tail) is
// the exact reference.
#include "TestHelpers.hpp"

#include <cmath>

using namespace coagtest;

namespace {

std::array<double, 4> discreteMoments(const Eigen::VectorXd& n)
{
    std::array<double, 4> m{0, 0, 0, 0};
    for (Eigen::Index l = 0; l < n.size(); ++l) {
        double p = 1.0;
        for (int k = 0; k < 4; ++k) {
            m[k] += p * n[l];
            p *= static_cast<double>(l + 1);
        }
    }
    return m;
}

//- Closed cell of 10 nm spheres (1800 kg/m3, masses in these monomers: the material's
//  massUnit) in air at 1500 K and 1 bar, number density N0 = 1/K11 per m3: SWA, DSA1 and
//  DSA2 against the discrete reference at 0.2, 2 and 20 / (K11 N0) (up to ten coagulation times
//  2 / (K11 N0)), for the free-molecular, continuum and transition kernels. The reference's
//  truncation (L = 400 and 800) changes its moments by less than 1e-6.
class BrownianReferenceTest : public ::testing::TestWithParam<std::string> {};

TEST_P(BrownianReferenceTest, ClosedCellAgainstTheDiscreteReference)
{
    GasState gas;
    gas.T = 1500.0;
    gas.p = 1e5;
    gas.mu = sutherlandViscosity(gas.T);
    ParticleMaterial material{1800.0};
    material.massUnit = material.mass(10e-9);
    for (BrownianRegime regime : {BrownianRegime::freeMolecular, BrownianRegime::continuum,
                                  BrownianRegime::transition}) {
        const BrownianKernel kernel(regime, gas, material);
        // N0 K11 = 1/s: the times in seconds are in units of 1/(K11 N0)
        const double N0 = 1.0 / kernel(ParticleType{1.0}, ParticleType{1.0});
        const std::vector<double> times{0.2, 2.0, 20.0};

        std::vector<std::array<double, 4>> reference[2];
        for (int level = 0; level < 2; ++level) {
            const std::size_t L = 400u << level;
            DiscreteSmoluchowski ode(kernel, L);
            ode.setTolerances(1e-10, 1e-14 * N0);  // the default absolute tolerance for N0 = 1
            Eigen::VectorXd n = Eigen::VectorXd::Zero(Eigen::Index(L));
            n[0] = N0;
            double t = 0.0;
            for (double ti : times) {
                n = ode.integrate(n, t, ti);
                t = ti;
                reference[level].push_back(discreteMoments(n));
            }
        }
        for (std::size_t i = 0; i < times.size(); ++i) {
            for (int k = 0; k < 3; ++k) {
                EXPECT_NEAR(reference[0][i][k] / reference[1][i][k], 1.0, 1e-6)
                    << brownianRegimeName(regime) << " M" << k;
            }
        }

        const auto res = runEnsemble(GetParam(), kernel, InceptionModel{}, NumberControl{},
                                     [&] { return monodisperse(1000, 1000.0 / N0); }, times, 60,
                                     41);
        auto refAt = [&](double t) {
            std::size_t i = 0;
            while (i + 1 < times.size() && times[i] != t) ++i;
            return reference[1][i];
        };
        expectMomentsMatch(res, times, refAt, 3,
                           GetParam() + " Brownian " + brownianRegimeName(regime));
    }
}

INSTANTIATE_TEST_SUITE_P(Algorithms, BrownianReferenceTest,
                         ::testing::Values("SWA", "DSA1", "DSA2"),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

} // namespace
