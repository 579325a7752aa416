// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
// The stochastic algorithms with the Brownian kernels against the deterministic reference:
// from a monodisperse start every mass is a multiple of the first one, so the discrete
// Smoluchowski equation (DiscreteSmoluchowski, Dormand–Prince, truncated far in the tail) is
// the exact reference.
#include "TestHelpers.hpp"

#include <cmath>

using namespace coagtest;

namespace {

//- Closed cell of 10 nm spheres (1800 kg/m3, masses in these monomers: the material's
//  massUnit) in air at 1500 K and 1 bar, number density N0 = 1/K11 per m3: SWA, DSA1 and
//  DSA2 against the discrete reference at 0.2, 2 and 20 / (K11 N0) (up to ten coagulation times
//  2 / (K11 N0)), for the free-molecular, continuum and transition kernels. The reference's
//  truncation (L = 400 and 800) changes its moments by less than 1e-6.
class BrownianReferenceTest : public ::testing::TestWithParam<std::string> {};

TEST_P(BrownianReferenceTest, ClosedCellAgainstTheDiscreteReference)
{
    const GasState gas = air(1500.0, 1e5);
    const ParticleMaterial material = monomersOf(1800.0, 10e-9);
    for (BrownianRegime regime : {BrownianRegime::freeMolecular, BrownianRegime::continuum,
                                  BrownianRegime::transition}) {
        const BrownianKernel kernel(regime, gas, material);
        // N0 K11 = 1/s: the times in seconds are in units of 1/(K11 N0)
        const double N0 = 1.0 / kernel(ParticleType{1.0}, ParticleType{1.0});
        const std::vector<double> times{0.2, 2.0, 20.0};

        const auto refAt =
            discreteReference(kernel, N0, times, "Brownian " + brownianRegimeName(regime));

        const auto res = runEnsemble(GetParam(), kernel, InceptionModel{}, NumberControl{},
                                     [&] { return monodisperse(1000, 1000.0 / N0); }, times, 60,
                                     41);
        expectMomentsMatch(res, times, refAt, 3,
                           GetParam() + " Brownian " + brownianRegimeName(regime));
    }
}

INSTANTIATE_TEST_SUITE_P(Algorithms, BrownianReferenceTest,
                         ::testing::Values("SWA", "DSA1", "DSA2"),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

} // namespace
