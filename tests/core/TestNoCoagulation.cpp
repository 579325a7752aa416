// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
// K = 0 (NoCoagulationKernel, the kernel 'none'): the algorithms make inception events only.
#include "TestHelpers.hpp"

using namespace coagtest;

namespace {

class NoCoagulationTest : public ::testing::TestWithParam<std::string> {};

//- A source of monomers at rate I without coagulation: every moment is I t (eq 10 / 20
//  with K = 0), and no pair is ever proposed
TEST_P(NoCoagulationTest, SourceAloneGivesMomentsIt)
{
    const double I = 1.0, V = 500.0;
    NoCoagulationKernel kernel;
    InceptionModel inception;
    inception.rate = I;
    const std::vector<double> times{0.5, 1.0, 2.0};
    auto exact = [&](double t) { return std::array<double, 4>{I * t, I * t, I * t, I * t}; };
    const auto res = runEnsemble(
        GetParam(), kernel, inception, NumberControl{},
        [&] {
            CellPopulation pop;
            pop.volume = V;
            return pop;
        },
        times, 200, 21);
    expectMomentsMatch(res, times, exact, 4, GetParam() + " no coagulation, source");
    EXPECT_GT(res.steps.inceptions, 0u);
    EXPECT_EQ(res.steps.coagulations, 0u);
    EXPECT_EQ(res.steps.fictitious, 0u);
}

//- Without a source the population is left exactly as it was
TEST_P(NoCoagulationTest, PopulationWithoutSourceIsUnchanged)
{
    NoCoagulationKernel kernel;
    auto alg = makeCellAlgorithm(GetParam(), kernel, InceptionModel{}, NumberControl{});
    CellPopulation pop = monodisperse(500, 500.0);
    const CellPopulation before = pop;
    Rng rng(7);
    StepStatistics stats;
    alg->advance(pop, 10.0, rng, stats);
    ASSERT_EQ(pop.particles.size(), before.particles.size());
    for (std::size_t i = 0; i < pop.particles.size(); ++i) {
        EXPECT_EQ(pop.particles[i].type.mass, before.particles[i].type.mass);
        EXPECT_EQ(pop.particles[i].weight, before.particles[i].weight);
    }
    EXPECT_EQ(stats.coagulations + stats.fictitious + stats.inceptions, 0u);
    EXPECT_EQ(kernel.name(), "none");
    EXPECT_EQ(kernel(ParticleType{}, ParticleType{}), 0.0);
}

INSTANTIATE_TEST_SUITE_P(Algorithms, NoCoagulationTest, ::testing::Values("SWA", "DSA1", "DSA2"),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

} // namespace
