// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
// coag::cubeRoot, the cube root the Brownian kernels take of every mass they meet, against
// std::cbrt: within 3 ulp over the whole range of normal doubles, exact on cubes of small
// integers, and std::cbrt's answer for zero, subnormals, infinity and NaN.
#include "coagulation/kernels/CubeRoot.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace {

double ulpsApart(double a, double b)
{
    const double ulp = std::nextafter(b, std::numeric_limits<double>::infinity()) - b;
    return std::fabs(a - b) / ulp;
}

TEST(CubeRoot, WithinThreeUlpOfCbrtOverTheNormalRange)
{
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> exponent(-1022.0, 1023.0);
    std::uniform_real_distribution<double> mantissa(1.0, 2.0);
    double worst = 0.0;
    for (int i = 0; i < 2000000; ++i) {
        const double x = std::ldexp(mantissa(rng), static_cast<int>(exponent(rng)));
        worst = std::max(worst, ulpsApart(coag::cubeRoot(x), std::cbrt(x)));
    }
    EXPECT_LE(worst, 3.0);
    for (double x : {std::numeric_limits<double>::min(), std::numeric_limits<double>::max(),
                     1.0, 2.0, 0.5, 1e-30, 1e30}) {
        EXPECT_LE(ulpsApart(coag::cubeRoot(x), std::cbrt(x)), 3.0) << x;
    }
}

TEST(CubeRoot, CubesOfIntegersAndSpecialValues)
{
    for (int k = 1; k <= 1000; ++k) {
        const double x = double(k) * k * k;
        EXPECT_NEAR(coag::cubeRoot(x), double(k), 2e-16 * k) << k;
    }
    EXPECT_EQ(coag::cubeRoot(0.0), 0.0);
    const double sub = std::numeric_limits<double>::denorm_min() * 1000.0;
    EXPECT_EQ(coag::cubeRoot(sub), std::cbrt(sub));
    EXPECT_TRUE(std::isinf(coag::cubeRoot(std::numeric_limits<double>::infinity())));
    EXPECT_TRUE(std::isnan(coag::cubeRoot(std::numeric_limits<double>::quiet_NaN())));
}

} // namespace
