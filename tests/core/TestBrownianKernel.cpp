// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
// Brownian coagulation of aerosol spheres: the gas and particle quantities against textbook
// values, the regimes' limits, and the product-sum majorants the algorithms sample from.
#include "TestHelpers.hpp"

#include "coagulation/kernels/BrownianKernel.hpp"
#include "coagulation/aerosol/AerosolProperties.hpp"
#include "coagulation/sampling/MajorantSampler.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

using namespace coagtest;

namespace {

const BrownianRegime allRegimes[] = {BrownianRegime::freeMolecular, BrownianRegime::continuum,
                                     BrownianRegime::transition};

//- The least Khat / K over the grid of the acceptance test: both diameters 1 nm to 100 um,
//  T 250 to 2500 K, p 0.1 to 10 bar, densities 1000 and 4000 kg/m3
double leastMajorantRatio(BrownianRegime regime, double scale = 1.0)
{
    double least = HUGE_VAL;
    for (double T : {250.0, 600.0, 1200.0, 2500.0}) {
        for (double p : {1e4, 1e5, 1e6}) {
            for (double rho : {1000.0, 4000.0}) {
                const ParticleMaterial material{rho};
                const BrownianKernel K(regime, air(T, p), material);
                for (double d1 : gridDiameters()) {
                    for (double d2 : gridDiameters()) {
                        const ParticleType a{material.mass(d1)}, b{material.mass(d2)};
                        least = std::min(least, scale * K.majorant(a, b) / K(a, b));
                    }
                }
            }
        }
    }
    return least;
}

TEST(AerosolProperties, MeanFreePathAndViscosityOfAir)
{
    // Seinfeld & Pandis: lambda of air at 298 K and 1 atm is 0.0651 um (mu = 1.8e-5 Pa s)
    GasState g;
    g.T = 298.15;
    g.p = 101325.0;
    g.mu = 1.8e-5;
    EXPECT_NEAR(g.meanFreePath(), 65.1e-9, 0.005 * 65.1e-9);
    // Air's viscosity at 300 K: 1.846e-5 Pa s (Sutherland's law with OpenFOAM's coefficients)
    EXPECT_NEAR(sutherlandViscosity(300.0), 1.846e-5, 0.01 * 1.846e-5);
    // A sphere's diameter from its mass and back
    const ParticleMaterial silica{2200.0};
    EXPECT_NEAR(silica.diameter(silica.mass(37e-9)), 37e-9, 1e-22);
    EXPECT_THROW(ParticleMaterial{-1.0}.check(), std::invalid_argument);
    GasState bad = g;
    bad.T = 0.0;
    EXPECT_THROW(BrownianKernel(BrownianRegime::transition, bad, silica), std::invalid_argument);
}

TEST(AerosolProperties, SlipCorrectionLimits)
{
    const SlipCorrection C;
    EXPECT_NEAR(C(1e-4), 1.0, 2e-4);                                   // continuum: no slip
    const double Kn = 1e4;                                             // free molecular
    EXPECT_NEAR(C(Kn) / C.bound(Kn), 1.0, 1e-3);
    for (double kn : {1e-3, 0.1, 1.0, 10.0}) EXPECT_LE(C(kn), C.bound(kn));
}

//- Equal spheres without slip meet at 8kT/(3 mu) whatever their size (Smoluchowski)
TEST(BrownianKernel, ContinuumLimitOfEqualSpheres)
{
    const GasState g = air(300.0, 1e5);
    const ParticleMaterial m{1000.0};
    const BrownianKernel K(BrownianRegime::continuum, g, m);
    const ParticleType big{m.mass(100e-6)};
    EXPECT_NEAR(K(big, big) / (8.0 * constants::boltzmann * g.T / (3.0 * g.mu)), 1.0, 2e-3);
}

//- Fuchs' interpolation tends to the free-molecular kernel as Kn -> infinity (1 nm at
//  0.1 bar, Kn ~ 1300) and to the slip-corrected continuum kernel as Kn -> 0 (100 um at
//  10 bar, Kn ~ 1e-4), within 1 %
TEST(BrownianKernel, TransitionTendsToTheLimits)
{
    const ParticleMaterial m{1000.0};
    {
        const BrownianKernel K(BrownianRegime::transition, air(300.0, 1e4), m);
        for (double d2 : {1e-9, 2e-9}) {
            const ParticleType a{m.mass(1e-9)}, b{m.mass(d2)};
            EXPECT_NEAR(K.transition(a, b) / K.freeMolecular(a, b), 1.0, 0.01);
        }
    }
    {
        const BrownianKernel K(BrownianRegime::transition, air(300.0, 1e6), m);
        for (double d2 : {100e-6, 50e-6}) {
            const ParticleType a{m.mass(100e-6)}, b{m.mass(d2)};
            EXPECT_NEAR(K.transition(a, b) / K.continuum(a, b), 1.0, 0.01);
        }
    }
    // in between it is below both (here at Kn ~ 1)
    const BrownianKernel K(BrownianRegime::transition, air(300.0, 1e5), m);
    const ParticleType a{m.mass(100e-9)}, b{m.mass(150e-9)};
    EXPECT_LT(K.transition(a, b), K.freeMolecular(a, b));
    EXPECT_LT(K.transition(a, b), K.continuum(a, b));
}

//- K <= Khat on the whole grid for every regime, and tight: the least ratio is within 1 % of
//  1 for the free-molecular and continuum majorants, so a majorant 1 % lower fails the check
TEST(BrownianKernel, MajorantsBoundTheKernelsOverTheGrid)
{
    for (BrownianRegime r : allRegimes) {
        const double least = leastMajorantRatio(r);
        EXPECT_GE(least, 1.0 - 1e-12) << brownianRegimeName(r);
        if (r != BrownianRegime::transition) {
            EXPECT_LT(least, 1.01) << brownianRegimeName(r);
            EXPECT_LT(leastMajorantRatio(r, 0.99), 1.0) << brownianRegimeName(r) << " lowered 1 %";
        }
    }
}

//- The majorants' documented looseness: free molecular at most freeMolecularFactor (1.42),
//  continuum at most (A1 + A2)/A1; the free-molecular factor is the least that bounds K: the
//  largest of (1 + t)^2 sqrt(1 + t^-3) / ((1 + t^2)(1 + t^(-3/2))), t = xj/xi, on a fine
//  scan is within 0.2 % below it
TEST(BrownianKernel, MajorantsAreWithinTheirBounds)
{
    double largest = 0.0;
    for (int k = -4000; k <= 4000; ++k) {
        const double t = std::pow(10.0, k / 1000.0);
        largest = std::max(largest, (1.0 + t) * (1.0 + t) * std::sqrt(1.0 + std::pow(t, -3.0))
                                        / ((1.0 + t * t) * (1.0 + std::pow(t, -1.5))));
    }
    EXPECT_LT(largest, BrownianKernel::freeMolecularFactor);
    EXPECT_GT(largest, 0.998 * BrownianKernel::freeMolecularFactor);

    const ParticleMaterial m{2200.0};
    for (BrownianRegime r : {BrownianRegime::freeMolecular, BrownianRegime::continuum}) {
        const double bound = r == BrownianRegime::freeMolecular
                                 ? BrownianKernel::freeMolecularFactor
                                 : (SlipCorrection{}.A1 + SlipCorrection{}.A2) / SlipCorrection{}.A1;
        const BrownianKernel K(r, air(1000.0, 1e5), m);
        for (double d1 : gridDiameters()) {
            for (double d2 : gridDiameters()) {
                const ParticleType a{m.mass(d1)}, b{m.mass(d2)};
                ASSERT_LE(K.majorant(a, b) / K(a, b), bound * (1.0 + 1e-12))
                    << brownianRegimeName(r) << " " << d1 << " " << d2;
            }
        }
    }
}

//- The sampler's summed majorant over a polydisperse population (1 nm to 10 um) is the
//  directly summed pair total of the majorant group with the least total, and every pair's
//  proposal rate majorises its K (w2)
TEST(BrownianKernel, SamplerSumsTheMajorantOverAPopulation)
{
    const ParticleMaterial m{1800.0};
    for (BrownianRegime r : allRegimes) {
        for (bool weighted : {true, false}) {
            const BrownianKernel K(r, air(1500.0, 1e5), m);
            std::vector<Particle> P;
            for (int j = 0; j < 40; ++j) {
                const double d = 1e-9 * std::pow(10.0, 4.0 * (j % 9) / 8.0);
                P.push_back(Particle{ParticleType{m.mass(d)},
                                     weighted ? std::pow(2.0, j % 5 - 2.0) : 1.0, j});
            }
            MajorantSampler sampler(weighted);
            sampler.configure(K, "test");
            sampler.build(P, P.size());
            const double rate = sampler.rateSum(P.size());
            double sum = 0.0;
            std::vector<double> groups(K.nMajorantGroups(), 0.0);
            for (const Particle& a : P) {
                for (const Particle& b : P) {
                    const double pair = sampler.pairRate(a, b);
                    sum += pair;
                    for (std::size_t g = 0; g < groups.size(); ++g) {
                        groups[g] += K.majorant(a.type, b.type, int(g)) * (weighted ? b.weight : 1.0);
                    }
                    ASSERT_GE(pair, sampler.targetRate(K(a.type, b.type), b))
                        << brownianRegimeName(r);
                }
            }
            // the group of the least sum is the one sampled (transition: two groups)
            const double direct = *std::min_element(groups.begin(), groups.end());
            EXPECT_NEAR(sum, rate, 1e-12 * rate) << brownianRegimeName(r);
            // the tree's quantised values round up, by at most a few parts in a thousand
            EXPECT_GE(rate, direct * (1.0 - 1e-12)) << brownianRegimeName(r);
            EXPECT_LT(rate, direct * 1.01) << brownianRegimeName(r);
        }
    }
}

//- Masses in another unit (massUnit kg each): the same kernel and majorant at the same
//  physical masses
TEST(BrownianKernel, MassUnit)
{
    const ParticleMaterial kg{1800.0};
    const double m0 = kg.mass(10e-9);
    const ParticleMaterial monomers{1800.0, m0};
    EXPECT_NEAR(monomers.diameter(1.0), 10e-9, 1e-20);
    for (BrownianRegime r : allRegimes) {
        const BrownianKernel a(r, air(1200.0, 1e5), kg), b(r, air(1200.0, 1e5), monomers);
        for (double x : {1.0, 3.0, 1000.0}) {
            const ParticleType one{1.0}, other{x}, oneKg{m0}, otherKg{x * m0};
            EXPECT_NEAR(b(one, other) / a(oneKg, otherKg), 1.0, 1e-12) << brownianRegimeName(r);
            EXPECT_NEAR(b.majorant(one, other) / a.majorant(oneKg, otherKg), 1.0, 1e-12)
                << brownianRegimeName(r);
        }
    }
}

TEST(BrownianKernel, RegimeNames)
{
    for (BrownianRegime r : allRegimes) EXPECT_EQ(parseBrownianRegime(brownianRegimeName(r)), r);
    EXPECT_THROW(parseBrownianRegime("slipFlow"), std::invalid_argument);
}

} // namespace
