// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#include "TestHelpers.hpp"

using namespace coagtest;

TEST(Kernels, ValuesAndNames)
{
    const ParticleType a{2.0}, b{5.0};
    EXPECT_DOUBLE_EQ((*makeKernel("constant", 3.0))(a, b), 3.0);
    EXPECT_DOUBLE_EQ((*makeKernel("additive", 3.0))(a, b), 21.0);
    EXPECT_DOUBLE_EQ((*makeKernel("multiplicative", 3.0))(a, b), 30.0);
    const double st = std::pow(std::cbrt(2.0) + std::cbrt(5.0), 3);
    EXPECT_NEAR((*makeKernel("saffmanTurner", 3.0))(a, b), 3.0 * st, 1e-12 * st);
    // K0 = 1/8 gives K11 = 1 (Kolodko-Sabelfeld-Wagner normalisation)
    EXPECT_DOUBLE_EQ(SaffmanTurnerKernel(0.125)(ParticleType{1.0}, ParticleType{1.0}), 1.0);
    for (const std::string& n : kernelNames()) EXPECT_EQ(makeKernel(n, 1.0)->name(), n);
}

TEST(Kernels, MajorantsAreExactProductForms)
{
    Rng rng(4);
    for (const std::string& n : kernelNames()) {
        auto k = makeKernel(n, 0.7);
        for (int i = 0; i < 1000; ++i) {
            const ParticleType a{std::exp(10 * rng.uniform())}, b{std::exp(10 * rng.uniform())};
            const double K = (*k)(a, b), Khat = k->majorant(a, b);
            EXPECT_NEAR(Khat, K, 1e-12 * K) << n;
            EXPECT_NEAR((*k)(b, a), K, 1e-14 * K) << n << " symmetry";
        }
        std::vector<double> phi(static_cast<std::size_t>(k->nBasis()));
        k->basis(ParticleType{3.0}, phi.data());
        for (double v : phi) EXPECT_GE(v, 0.0);
        for (const MajorantTerm& t : k->majorantTerms()) {
            EXPECT_GT(t.coeff, 0.0);
            EXPECT_LT(t.first, k->nBasis());
            EXPECT_LT(t.second, k->nBasis());
        }
    }
}
