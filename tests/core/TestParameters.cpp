// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
// Bad parameters throw std::invalid_argument with a message naming the problem.
#include "TestHelpers.hpp"

using namespace coagtest;

namespace {

template <class F>
void expectInvalid(F&& f, const std::string& fragment)
{
    try {
        f();
        ADD_FAILURE() << "expected std::invalid_argument mentioning '" << fragment << "'";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos)
            << "message '" << e.what() << "' does not mention '" << fragment << "'";
    }
}

} // namespace

TEST(Parameters, KernelsRejectNonpositiveK0AndUnknownNames)
{
    for (const std::string& n : kernelNames()) {
        expectInvalid([&] { makeKernel(n, 0.0); }, "K0");
        expectInvalid([&] { makeKernel(n, -1.0); }, "K0");
        expectInvalid([&] { makeKernel(n, std::nan("")); }, "K0");
    }
    expectInvalid([] { ConstantKernel k(0.0); }, "K0");
    expectInvalid([] { makeKernel("brownian", 1.0); }, "unknown kernel 'brownian'");
    expectInvalid([] { makeKernel("brownian", 1.0); }, "saffmanTurner");
}

TEST(Parameters, CellAlgorithmsRejectBadSettings)
{
    ConstantKernel kernel(1.0);
    expectInvalid([&] { makeCellAlgorithm("MFA", kernel, {}); }, "unknown algorithm 'MFA'");
    expectInvalid([&] { makeCellAlgorithm("MFA", kernel, {}); }, "DSA2");
    expectInvalid([&] { makeCellAlgorithm("SWA", kernel, InceptionModel{-1.0, {}, 1.0}); },
                  "inception rate");
    expectInvalid([&] { makeCellAlgorithm("DSA1", kernel, InceptionModel{1.0, {}, 0.0}); },
                  "inception weight");
    expectInvalid([&] { makeCellAlgorithm("DSA2", kernel, InceptionModel{1.0, {}, -2.0}); },
                  "inception weight");
    NumberControl ctl;
    ctl.maxParticles = 100;
    ctl.minParticles = 60;
    expectInvalid([&] { makeCellAlgorithm("DSA1", kernel, {}, ctl); }, "maxParticles");
}

TEST(Parameters, AdvanceRejectsBadInput)
{
    ConstantKernel kernel(1.0);
    Rng rng(1);
    StepStatistics stats;
    auto swa = makeCellAlgorithm("SWA", kernel, {});
    CellPopulation pop = monodisperse(10, 10.0);
    expectInvalid([&] { swa->advance(pop, -1.0, rng, stats); }, "dt");
    pop.volume = 0.0;
    expectInvalid([&] { swa->advance(pop, 1.0, rng, stats); }, "volume");

    auto dsa = makeCellAlgorithm("DSA1", kernel, InceptionModel{1.0, {}, 1.0});
    CellPopulation mixed = monodisperse(10, 10.0);
    mixed.particles[3].weight = 2.0;
    expectInvalid([&] { dsa->advance(mixed, 1.0, rng, stats); }, "weights");
    CellPopulation heavy = monodisperse(10, 10.0, 2.0);
    expectInvalid([&] { dsa->advance(heavy, 1.0, rng, stats); }, "inception weight");
}

TEST(Parameters, NanbuAndFiniteDifferenceRejectAlphaOutsideUnitInterval)
{
    ConstantKernel kernel(1.0);
    for (double alpha : {0.0, -0.5, 1.5}) {
        NanbuParameters p;
        p.alpha = alpha;
        expectInvalid([&] { NanbuSmoluchowski::fromDensity(kernel, {1.0}, 100, p); }, "alpha");
        expectInvalid([&] { FiniteDifferenceSmoluchowski(kernel, {1.0}, alpha, 10); }, "alpha");
    }
    NanbuParameters ok;
    ok.alpha = 1.0;
    EXPECT_NO_THROW(NanbuSmoluchowski::fromDensity(kernel, {1.0}, 100, ok));
    expectInvalid([&] { NanbuSmoluchowski::fromDensity(kernel, {0.0}, 100, ok); }, "density");
    expectInvalid([&] { kernelMatrix(kernel, 0); }, "maximum size");
}
