// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
// Growth laws against their exact solutions, and growth with coagulation in a closed cell
// against the closed moment equations.
#include "TestHelpers.hpp"

using namespace coagtest;

namespace {

// ---- one particle: the closed forms and the adaptive step

TEST(GrowthLaw, ClosedFormsAreTheExactSolutions)
{
    const double m0 = 2.5, dt = 0.7;
    GrowthLaw constant;
    constant.addPower(0.3, 0.0);
    EXPECT_TRUE(constant.closedForm());
    EXPECT_DOUBLE_EQ(constant.advance(m0, dt, 0.0).mass, m0 + 0.3 * dt);

    GrowthLaw linear;
    linear.addPower(1.3, 1.0);
    EXPECT_NEAR(linear.advance(m0, dt, 0.0).mass / (m0 * std::exp(1.3 * dt)), 1.0, 1e-15);

    // Surface (m^(2/3)): m^(1/3) grows linearly at c/3; diameter (m^(1/3)): m^(2/3) at 2c/3
    GrowthLaw surface;
    surface.addPower(0.8, 2.0 / 3.0);
    const double ySurface = std::cbrt(m0) + 0.8 * dt / 3.0;
    EXPECT_NEAR(surface.advance(m0, dt, 0.0).mass / (ySurface * ySurface * ySurface), 1.0,
                1e-14);
    GrowthLaw continuum;
    continuum.addPower(0.8, 1.0 / 3.0);
    const double zContinuum = std::pow(m0, 2.0 / 3.0) + 2.0 * 0.8 * dt / 3.0;
    EXPECT_NEAR(continuum.advance(m0, dt, 0.0).mass / std::pow(zContinuum, 1.5), 1.0, 1e-14);

    // Any other exponent below 1: m^(1-q) linear in time
    GrowthLaw half;
    half.addPower(0.8, 0.5);
    const double zHalf = std::sqrt(m0) + 0.5 * 0.8 * dt;
    EXPECT_NEAR(half.advance(m0, dt, 0.0).mass / (zHalf * zHalf), 1.0, 1e-14);

    // Terms of one exponent add: still one closed form
    GrowthLaw twice;
    twice.addPower(0.5, 2.0 / 3.0);
    twice.addPower(0.3, 2.0 / 3.0);
    EXPECT_TRUE(twice.closedForm());
    EXPECT_DOUBLE_EQ(twice.advance(m0, dt, 0.0).mass, surface.advance(m0, dt, 0.0).mass);

    // Shrinking to the threshold: gone, at the threshold's mass
    GrowthLaw shrinking;
    shrinking.addPower(-1.0, 0.0);
    EXPECT_FALSE(shrinking.advance(m0, 2.4, 0.0).gone);
    EXPECT_TRUE(shrinking.advance(m0, 2.6, 0.0).gone);
    EXPECT_TRUE(shrinking.advance(m0, 2.0, 0.6).gone);
    EXPECT_EQ(shrinking.advance(m0, 2.0, 0.6).mass, 0.6);
    GrowthLaw decay;
    decay.addPower(-1.0, 1.0);
    EXPECT_FALSE(decay.advance(m0, 30.0, 0.0).gone);  // exponential decay never reaches 0
    EXPECT_TRUE(decay.advance(m0, std::log(m0 / 0.1) + 1e-9, 0.1).gone);
    EXPECT_FALSE(decay.advance(m0, std::log(m0 / 0.1) - 1e-9, 0.1).gone);
}

TEST(GrowthLaw, SizeDistributionsMoveAsTheirClosedForms)
{
    // Spheres of 1800 kg/m3, masses in kg; a lognormal set of diameters (dg 20 nm, sigma_g
    // 1.6, quantiles of -3..3 standard deviations)
    const ParticleMaterial soot{1800.0};
    const double lnSg = std::log(1.6);
    std::vector<double> d0;
    for (int i = 0; i <= 60; ++i) d0.push_back(20e-9 * std::exp(lnSg * (-3.0 + 0.1 * i)));

    // d(d)/dt = a: dm/dt = (rho pi / 2) a d^2 = (rho pi / 2) a (6 / (rho pi))^(2/3) m^(2/3)
    const double a = 3e-9, dt = 2.0, rho = soot.density;
    GrowthLaw surface;
    surface.addPower(0.5 * rho * coag::constants::pi * a *
                         std::pow(6.0 / (rho * coag::constants::pi), 2.0 / 3.0),
                     2.0 / 3.0);
    // dm/dt = sigma m: every diameter times exp(sigma t / 3), sigma_g kept
    const double sigma = 0.9;
    GrowthLaw linear;
    linear.addPower(sigma, 1.0);

    RunningStatistics lnBefore, lnAfter;
    for (double d : d0) {
        const double shifted = soot.diameter(surface.advance(soot.mass(d), dt, 0.0).mass);
        EXPECT_NEAR(shifted, d + a * dt, 1e-12 * (d + a * dt)) << "d0 = " << d;
        const double scaled = soot.diameter(linear.advance(soot.mass(d), dt, 0.0).mass);
        EXPECT_NEAR(scaled / d, std::exp(sigma * dt / 3.0), 1e-13) << "d0 = " << d;
        lnBefore.add(std::log(d));
        lnAfter.add(std::log(scaled));
    }
    EXPECT_NEAR(std::sqrt(lnAfter.variance()), std::sqrt(lnBefore.variance()), 1e-12);
    EXPECT_NEAR(lnAfter.mean() - lnBefore.mean(), sigma * dt / 3.0, 1e-12);
}

TEST(GrowthLaw, AdaptiveStepMatchesTheExactSolution)
{
    // dm/dt = a + b m: m(t) = (m0 + a/b) e^{bt} - a/b, growing and shrinking
    for (const auto& ab : std::vector<std::array<double, 2>>{{0.7, 0.4}, {0.7, -0.4},
                                                             {2.0, 3.0}}) {
        GrowthLaw law;
        law.addPower(ab[0], 0.0);
        law.addPower(ab[1], 1.0);
        EXPECT_FALSE(law.closedForm());
        for (double m0 : {1e-3, 1.0, 40.0}) {
            for (double dt : {1e-3, 0.3, 2.0}) {
                const double exact = (m0 + ab[0] / ab[1]) * std::exp(ab[1] * dt) - ab[0] / ab[1];
                const GrowthLaw::Step s = law.advance(m0, dt, 0.0);
                EXPECT_FALSE(s.gone);
                EXPECT_NEAR(s.mass / exact, 1.0, 1e-9)
                    << "a " << ab[0] << " b " << ab[1] << " m0 " << m0 << " dt " << dt;
            }
        }
    }

    // dm/dt = -a - b m reaches zero at t* = ln(1 + b m0 / a) / b: gone just after, not before
    const double a = 0.5, b = 0.8, m0 = 3.0;
    GrowthLaw loss;
    loss.addPower(-a, 0.0);
    loss.addPower(-b, 1.0);
    const double tStar = std::log1p(b * m0 / a) / b;
    EXPECT_FALSE(loss.advance(m0, 0.999 * tStar, 0.0).gone);
    EXPECT_TRUE(loss.advance(m0, 1.001 * tStar, 0.0).gone);
    // and a threshold mass at the time the exact solution reaches it
    const double mMin = 0.2;
    const double tMin = std::log((m0 + a / b) / (mMin + a / b)) / b;
    EXPECT_FALSE(loss.advance(m0, 0.999 * tMin, mMin).gone);
    const GrowthLaw::Step gone = loss.advance(m0, 1.001 * tMin, mMin);
    EXPECT_TRUE(gone.gone);
    EXPECT_EQ(gone.mass, mMin);
}

TEST(GrowthLaw, TransitionRegimeCondensation)
{
    // F(Kn, alpha): 1 in the continuum, 3 alpha / (4 Kn) in the free-molecular limit
    EXPECT_NEAR(fuchsSutugin(1e-8, 1.0), 1.0, 1e-7);
    EXPECT_NEAR(fuchsSutugin(1e6, 0.5) / (3.0 * 0.5 / (4.0 * 1e6)), 1.0, 1e-5);

    // One transition term: t(d) = (3 / (a b^3)) [d^2/2 + (A - L) d + (B - (A - L) L) ln(d + L)]
    // with L = 2 lambda, A = (4/(3 alpha) + 0.377) L, B = (4/(3 alpha)) L^2 (dt = dm / rate
    // integrated in d = b m^(1/3))
    const double a = 0.6, b = 1.3, lambda = 0.4, alpha = 0.7;
    GrowthLaw law;
    law.addTransition(a, b, lambda, alpha);
    EXPECT_FALSE(law.closedForm());
    const double L = 2.0 * lambda, r = 4.0 / (3.0 * alpha);
    const double A = (r + 0.377) * L, B = r * L * L;
    auto timeAt = [&](double d) {
        return 3.0 / (a * b * b * b) *
               (0.5 * d * d + (A - L) * d + (B - (A - L) * L) * std::log(d + L));
    };
    for (double m0 : {1e-4, 0.05, 2.0}) {
        for (double dt : {0.01, 1.0, 20.0}) {
            const double d0 = b * std::cbrt(m0);
            const double d1 = b * std::cbrt(law.advance(m0, dt, 0.0).mass);
            EXPECT_NEAR((timeAt(d1) - timeAt(d0)) / dt, 1.0, 1e-8) << "m0 " << m0 << " dt " << dt;
        }
    }
    // Evaporation (a < 0) shrinks a particle to nothing in finite time
    GrowthLaw evaporation;
    evaporation.addTransition(-a, b, lambda, alpha);
    const double d0 = b * std::cbrt(0.05);
    const double tGone = (timeAt(d0) - timeAt(0.0));
    EXPECT_FALSE(evaporation.advance(0.05, 0.99 * tGone, 0.0).gone);
    EXPECT_TRUE(evaporation.advance(0.05, 1.01 * tGone, 0.0).gone);
}

TEST(GrowthLaw, AParticleStartingBelowTheMinimumIsGoneAtItsMass)
{
    // An inflow particle smaller than the minimum: gone at once, whatever the law
    GrowthLaw closed;
    closed.addPower(1.0, 2.0 / 3.0);
    GrowthLaw adaptive;
    adaptive.addTransition(0.6, 1.3, 0.4, 0.7);
    GrowthLaw none;
    for (const GrowthLaw* law : {&closed, &adaptive, &none}) {
        for (double dt : {0.0, 0.01, 1.0}) {
            const GrowthLaw::Step s = law->advance(0.1, dt, 0.5);
            EXPECT_TRUE(s.gone);
            EXPECT_EQ(s.mass, 0.1);
        }
    }
    CellPopulation pop;
    pop.particles = {Particle{ParticleType{0.1}, 2.0, 0}, Particle{ParticleType{1.0}, 3.0, 1}};
    StepStatistics stats;
    growPopulation(pop, none, 1.0, 0.5, stats);
    ASSERT_EQ(pop.particles.size(), 1u);
    EXPECT_EQ(pop.particles[0].tag, 1);
    EXPECT_EQ(stats.lostParticles, 1u);
    EXPECT_EQ(stats.lostMass, 0.2);
    EXPECT_EQ(stats.grownMass, 0.0);
}

TEST(Growth, TheMinimumActsWhereTheLawIsEmpty)
{
    // A cell where no model acts (an empty law) with a minimum: the source step removes the
    // particle below it and books it, the jump process runs on the rest
    ConstantKernel kernel(1.0);
    auto alg = makeCellAlgorithm("SWA", kernel, InceptionModel{});
    CellPopulation pop;
    pop.volume = 1.0;
    pop.particles = {Particle{ParticleType{0.1}, 2.0, 0}, Particle{ParticleType{1.0}, 3.0, 1}};
    Rng rng(3);
    StepStatistics stats;
    advanceWithGrowth(*alg, pop, kernel, 0.0, GrowthLaw{}, 0.5, 1e-9, rng, stats);
    ASSERT_EQ(pop.particles.size(), 1u);
    EXPECT_EQ(pop.particles[0].tag, 1);
    EXPECT_EQ(stats.lostParticles, 1u);
    EXPECT_EQ(stats.lostMass, 0.2);
}

TEST(GrowthLaw, RefusesWhatItCannotIntegrate)
{
    GrowthLaw law;
    EXPECT_THROW(law.addPower(1.0, 1.5), std::invalid_argument);
    EXPECT_THROW(law.addPower(std::nan(""), 0.0), std::invalid_argument);
    EXPECT_THROW(law.addTransition(1.0, -1.0, 1.0, 1.0), std::invalid_argument);
    EXPECT_THROW(law.addTransition(1.0, 1.0, 1.0, 1.5), std::invalid_argument);
    law.addPower(1.0, 0.0);
    EXPECT_THROW(law.advance(0.0, 1.0, 0.0), std::invalid_argument);
    EXPECT_THROW(law.advance(1.0, -1.0, 0.0), std::invalid_argument);
    // Linear growth past the largest double: an error, not an infinite mass
    GrowthLaw huge;
    huge.addPower(1e3, 1.0);
    EXPECT_THROW(huge.advance(1.0, 10.0, 0.0), std::runtime_error);
}

// ---- a population: the bookings

TEST(Growth, EveryMassChangeIsBooked)
{
    CellPopulation pop;
    pop.volume = 2.0;
    for (int j = 0; j < 50; ++j) {
        pop.particles.push_back(Particle{ParticleType{0.1 + 0.05 * j}, 1.0 + 0.3 * j, j});
    }
    GrowthLaw oxidation;
    oxidation.addPower(-0.5, 2.0 / 3.0);
    const double minMass = 0.05;
    const double before = totalMass(pop);
    StepStatistics stats;
    growPopulation(pop, oxidation, 0.8, minMass, stats);

    std::uint64_t gone = 0;
    double goneNumber = 0.0;
    for (int j = 0; j < 50; ++j) {
        if (oxidation.advance(0.1 + 0.05 * j, 0.8, minMass).gone) {
            ++gone;
            goneNumber += 1.0 + 0.3 * j;
        }
    }
    ASSERT_GT(gone, 0u);
    ASSERT_LT(gone, 50u);
    EXPECT_EQ(stats.lostParticles, gone);
    EXPECT_EQ(pop.particles.size(), 50u - gone);
    EXPECT_NEAR(stats.lostNumber, goneNumber, 1e-12 * goneNumber);
    EXPECT_NEAR(stats.lostMass, minMass * goneNumber, 1e-12 * goneNumber);
    EXPECT_LT(stats.grownMass, 0.0);
    // domain now = before + growth - loss, to round-off
    EXPECT_NEAR(totalMass(pop), before + stats.grownMass - stats.lostMass, 1e-13 * before);
    // the survivors in their order, weights unchanged
    for (std::size_t i = 1; i < pop.particles.size(); ++i) {
        EXPECT_LT(pop.particles[i - 1].tag, pop.particles[i].tag);
    }
    for (const Particle& p : pop.particles) EXPECT_EQ(p.weight, 1.0 + 0.3 * double(p.tag));
}

// ---- growth with coagulation: the closed moment equations

class GrowthWithCoagulation : public ::testing::TestWithParam<std::string> {};

constexpr int kRealisations = 300;
constexpr std::size_t kParticles = 2000;

//- R realisations of a closed cell of N0 = 1 unit monomers with the constant kernel K0 = 1
//  and the growth law, advanced in steps of dt; moments at the times
EnsembleResult grownEnsemble(const std::string& algorithm, const GrowthLaw& law,
                             const std::vector<double>& times, double dt, std::uint64_t seed)
{
    ConstantKernel kernel(1.0);
    auto alg = makeCellAlgorithm(algorithm, kernel, InceptionModel{});
    EnsembleResult res;
    res.moments.resize(times.size());
    for (int r = 0; r < kRealisations; ++r) {
        Rng rng(seedFor(seed, static_cast<std::uint64_t>(r)));
        CellPopulation pop = monodisperse(kParticles, double(kParticles));
        double t = 0.0;
        for (std::size_t i = 0; i < times.size(); ++i) {
            while (t < times[i] - 1e-12) {
                const double h = std::min(dt, times[i] - t);
                advanceWithGrowth(*alg, pop, kernel, 0.0, law, 0.0, h, rng, res.steps);
                t += h;
            }
            const std::array<double, 4> m = moments(pop);
            for (int k = 0; k < 4; ++k) res.moments[i][k].add(m[k]);
        }
    }
    return res;
}

TEST_P(GrowthWithCoagulation, LinearGrowthFollowsTheClosedMomentEquations)
{
    // sigma t up to 3 (three e-folding times), in steps of 0.25: growth proportional to m
    // commutes with the constant kernel's jumps, so the split step is exact at any dt
    const double sigma = 1.0;
    GrowthLaw law;
    law.addPower(sigma, 1.0);
    const std::vector<double> times{0.5, 1.0, 2.0, 3.0};
    const auto res = grownEnsemble(GetParam(), law, times, 0.25, 41);
    auto exact = [&](double t) {
        return coag::exact::constantKernelLinearGrowthMoments(1.0, 1.0, sigma, t);
    };
    expectMomentsMatch(res, times, exact, 3, GetParam() + " constant kernel, dm/dt = m");
    EXPECT_GT(res.steps.coagulations, 0u);
    EXPECT_GT(res.steps.grownMass, 0.0);
    EXPECT_EQ(res.steps.lostParticles, 0u);
}

TEST_P(GrowthWithCoagulation, ConstantGrowthIsSecondOrderInTheStep)
{
    // dm/dt = g: m1 gains g m0 dt, and m0 falls during the step, so growth and coagulation do
    // not commute; the split step's error in m1 is the trapezoidal rule's on the integral of
    // m0, 7.8e-5 g at dt = 0.05 (dt^2/12 times m0'(2) - m0'(0) = 0.375), well inside the
    // interval. A first-order split (all the growth before the jumps) would be 0.0125 g off.
    const double g = 1.0;
    GrowthLaw law;
    law.addPower(g, 0.0);
    const std::vector<double> times{0.5, 1.0, 2.0};
    const auto res = grownEnsemble(GetParam(), law, times, 0.05, 42);
    auto exact = [&](double t) {
        const std::array<double, 2> m = coag::exact::constantKernelConstantGrowthMoments(
            1.0, 1.0, g, t);
        return std::array<double, 4>{m[0], m[1], 0.0, 0.0};
    };
    expectMomentsMatch(res, times, exact, 2, GetParam() + " constant kernel, dm/dt = 1");
}

INSTANTIATE_TEST_SUITE_P(Algorithms, GrowthWithCoagulation,
                         ::testing::Values("SWA", "DSA1", "DSA2"),
                         [](const auto& info) { return info.param; });

} // namespace
