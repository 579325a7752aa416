// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
// The random-walk pieces of the core: the counter stream's normals, and the Brownian
// diffusivity against Hinds' table and its two limits.
#include "TestHelpers.hpp"

#include <cmath>

using namespace coagtest;

namespace {

// Keys as the solver makes them: hashed (SplitMix64) from a counter
std::uint64_t hashedKey(std::uint64_t i) { return mix64(i); }

} // namespace

TEST(CounterStream, SameKeySameDrawsOtherKeyOtherDraws)
{
    CounterStream a(hashedKey(7)), b(hashedKey(7)), c(hashedKey(8));
    for (int i = 0; i < 10; ++i) {
        const std::uint64_t x = a.next();
        EXPECT_EQ(x, b.next());
        EXPECT_NE(x, c.next());
    }
}

TEST(CounterStream, Normal3HasStandardMomentsAndUncorrelatedComponents)
{
    // One triple per key, as one particle's step draws it
    const int n = 400000;
    RunningStatistics m[3], sq[3], fourth[3], cross01, cross02, cross12;
    for (int i = 0; i < n; ++i) {
        CounterStream s(hashedKey(std::uint64_t(i)));
        double xi[3];
        s.normal3(xi);
        for (int k = 0; k < 3; ++k) {
            m[k].add(xi[k]);
            sq[k].add(xi[k] * xi[k]);
            fourth[k].add(xi[k] * xi[k] * xi[k] * xi[k]);
        }
        cross01.add(xi[0] * xi[1]);
        cross02.add(xi[0] * xi[2]);
        cross12.add(xi[1] * xi[2]);
    }
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(m[k].mean(), 0.0, 4 * m[k].standardError()) << "component " << k;
        EXPECT_NEAR(sq[k].mean(), 1.0, 4 * sq[k].standardError()) << "component " << k;
        EXPECT_NEAR(fourth[k].mean(), 3.0, 4 * fourth[k].standardError()) << "component " << k;
    }
    EXPECT_NEAR(cross01.mean(), 0.0, 4 * cross01.standardError());
    EXPECT_NEAR(cross02.mean(), 0.0, 4 * cross02.standardError());
    EXPECT_NEAR(cross12.mean(), 0.0, 4 * cross12.standardError());
}

TEST(CounterStream, Normal3TailMatchesTheGaussian)
{
    // P(|xi| > 3) = 2.6998e-3: a Box-Muller slip (a wrong radius) shows in the tail first
    const int n = 400000;
    long beyond = 0;
    for (int i = 0; i < n; ++i) {
        CounterStream s(hashedKey(std::uint64_t(i) + 12345));
        double xi[3];
        s.normal3(xi);
        for (double x : xi) beyond += std::abs(x) > 3.0;
    }
    const double p = 2.699796e-3, trials = 3.0 * n;
    EXPECT_NEAR(double(beyond), p * trials, 4 * std::sqrt(p * (1 - p) * trials));
}

TEST(BrownianDiffusivity, MatchesHindsTableInAirAt293K)
{
    // Hinds, Aerosol Technology (2nd ed.), Table A.9: unit-density spheres in air at
    // 293 K and 101 kPa (lambda = 0.066 um, mu = 1.81e-5 Pa s)
    BrownianGas gas;
    gas.temperature = 293.15;
    gas.viscosity = 1.81e-5;
    gas.meanFreePath = 6.6e-8;
    gas.density = 1000;
    const double pi = 3.14159265358979323846;
    const struct { double d, D; } table[] = {{1e-8, 5.24e-8}, {1e-7, 6.75e-10}, {1e-6, 2.77e-11}};
    for (const auto& row : table) {
        const double mass = gas.density * pi * row.d * row.d * row.d / 6.0;
        EXPECT_NEAR(sphereDiameter(mass, gas), row.d, 1e-12 * row.d);
        EXPECT_NEAR(brownianDiffusivity(mass, gas), row.D, 0.02 * row.D) << "d = " << row.d;
    }
}

TEST(BrownianDiffusivity, ContinuumAndFreeMolecularLimits)
{
    BrownianGas gas;
    gas.massUnit = 2.5e-21;  // masses in units of a monomer
    const double pi = 3.14159265358979323846;
    const double kT = constants::boltzmann * gas.temperature;
    // d >> lambda: Stokes-Einstein, D d = kT/(3 pi mu)
    {
        const double d = 1e-3;
        const double mass = gas.density * pi * d * d * d / 6.0 / gas.massUnit;
        EXPECT_NEAR(brownianDiffusivity(mass, gas) * d, kT / (3 * pi * gas.viscosity),
                    1e-3 * kT / (3 * pi * gas.viscosity));
    }
    // d << lambda: Cc -> 2 lambda (A1 + A2)/d, D d^2 = 2 kT lambda (A1 + A2)/(3 pi mu)
    {
        const double d = 1e-11;
        const double mass = gas.density * pi * d * d * d / 6.0 / gas.massUnit;
        const double limit = 2 * kT * gas.meanFreePath * (gas.slip.A1 + gas.slip.A2) / (3 * pi * gas.viscosity);
        EXPECT_NEAR(brownianDiffusivity(mass, gas) * d * d, limit, 1e-3 * limit);
    }
    EXPECT_THROW(brownianDiffusivity(0.0, gas), std::invalid_argument);
}
