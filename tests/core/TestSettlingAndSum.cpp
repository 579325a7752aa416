// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
// Coagulation by differential settling (GravitationalSettlingKernel) and sums of kernels
// (SumKernel): values against a hand computation, the product-sum majorants over the grid of
// gases and diameters, the sampler's summed majorant, and a closed cell of the sum of the
// Brownian and settling kernels against the discrete Smoluchowski reference.
#include "TestHelpers.hpp"

#include "coagulation/sampling/MajorantSampler.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

using namespace coagtest;

namespace {

//- The Saffman-Turner kernel 1.3 (eps/nu)^(1/2) (ri + rj)^3 of masses in kg of density rho:
//  K0 = 1.3 (eps/nu)^(1/2) 3 / (4 pi rho)
std::shared_ptr<const CoagulationKernel> saffmanTurner(double rho)
{
    const double eps = 0.1, nu = 1.5e-5;
    return std::make_shared<SaffmanTurnerKernel>(1.3 * std::sqrt(eps / nu) * 3.0
                                                 / (4.0 * constants::pi * rho));
}

//- The largest K / Khat (the least group's Khat) over the grid of diameters 1 nm to 100 um,
//  T 250 to 2500 K, p 0.1 to 10 bar, densities 1000 and 4000 kg/m3, of the kernel that
//  make(gas, material) returns; every group's Khat is checked against K on the way (the
//  largest ratio of any group goes to worstGroup)
template <class Make>
double largestKernelOverMajorant(const Make& make, double& worstGroup)
{
    double largest = 0.0;
    worstGroup = 0.0;
    for (double T : {250.0, 600.0, 1200.0, 2500.0}) {
        for (double p : {1e4, 1e5, 1e6}) {
            for (double rho : {1000.0, 4000.0}) {
                const ParticleMaterial material{rho};
                const auto K = make(air(T, p), material);
                for (double d1 : gridDiameters()) {
                    for (double d2 : gridDiameters()) {
                        const ParticleType a{material.mass(d1)}, b{material.mass(d2)};
                        const double k = (*K)(a, b);
                        largest = std::max(largest, k / K->majorant(a, b));
                        for (int g = 0; g < K->nMajorantGroups(); ++g) {
                            worstGroup = std::max(worstGroup, k / K->majorant(a, b, g));
                        }
                    }
                }
            }
        }
    }
    return largest;
}

std::shared_ptr<const CoagulationKernel> settling(const GasState& gas,
                                                  const ParticleMaterial& material)
{
    return std::make_shared<GravitationalSettlingKernel>(gas, material);
}

std::shared_ptr<const CoagulationKernel> brownianSettlingTurbulence(const GasState& gas,
                                                                    const ParticleMaterial& m)
{
    return std::make_shared<SumKernel>(std::vector<SumKernel::Part>{
        std::make_shared<BrownianKernel>(BrownianRegime::transition, gas, m), settling(gas, m),
        saffmanTurner(m.density)});
}

//- Equal particles settle together
TEST(GravitationalSettlingKernel, EqualParticlesDoNotCollide)
{
    const ParticleMaterial m{1500.0};
    const GravitationalSettlingKernel K(air(293.0, 101325.0), m);
    for (double d : {1e-9, 1e-6, 50e-6}) {
        EXPECT_EQ(K(ParticleType{m.mass(d)}, ParticleType{m.mass(d)}), 0.0) << d;
    }
}

//- 1 um and 5 um spheres of 1000 kg/m3 in air at 293 K, 1 atm, mu = 1.81e-5 Pa s, by hand:
//  lambda = 2 mu / (p sqrt(8 M/(pi R T))) = 64.93 nm; C(1 um) = 1.16324, C(5 um) = 1.03265;
//  v = rho g d^2 C / (18 mu) = 3.5026e-5 and 7.7734e-4 m/s;
//  K = (pi/4)(6 um)^2 (7.7734e-4 - 3.5026e-5) = 2.0988e-14 m3/s; E = 0.5 halves it.
TEST(GravitationalSettlingKernel, KnownValueInAir)
{
    GasState gas;
    gas.T = 293.0;
    gas.p = 101325.0;
    gas.mu = 1.81e-5;
    const ParticleMaterial m{1000.0};
    const GravitationalSettlingKernel K(gas, m);
    EXPECT_NEAR(gas.meanFreePath(), 64.929e-9, 0.001e-9);
    EXPECT_NEAR(K.settlingVelocity(m.mass(1e-6)), 3.5026e-5, 1e-4 * 3.5026e-5);
    EXPECT_NEAR(K.settlingVelocity(m.mass(5e-6)), 7.7734e-4, 1e-4 * 7.7734e-4);
    const ParticleType a{m.mass(1e-6)}, b{m.mass(5e-6)};
    EXPECT_NEAR(K(a, b), 2.0988e-14, 1e-4 * 2.0988e-14);
    EXPECT_NEAR(K(b, a), K(a, b), 1e-15 * K(a, b));
    const GravitationalSettlingKernel half(gas, m, 0.5);
    EXPECT_NEAR(half(a, b), 0.5 * K(a, b), 1e-15 * K(a, b));
    // masses in another unit: the same kernel at the same physical masses
    ParticleMaterial inMonomers = m;
    inMonomers.massUnit = m.mass(1e-6);
    const GravitationalSettlingKernel Kunit(gas, inMonomers);
    EXPECT_NEAR(Kunit(ParticleType{1.0}, ParticleType{125.0}), K(a, b), 1e-12 * K(a, b));
}

TEST(GravitationalSettlingKernel, RefusesInvalidParameters)
{
    const GasState gas;
    const ParticleMaterial m;
    EXPECT_THROW(GravitationalSettlingKernel(gas, m, -0.5), std::invalid_argument);
    EXPECT_THROW(GravitationalSettlingKernel(gas, m, 0.0), std::invalid_argument);
    EXPECT_THROW(GravitationalSettlingKernel(gas, m, 1.0, -9.81), std::invalid_argument);
    EXPECT_THROW(GravitationalSettlingKernel(gas, m, 1.0, std::nan("")), std::invalid_argument);
}

//- K <= Khat on the grid, and tight: the largest K / Khat (very unequal particles, where
//  vj << vi and C is near its bound) is within 1 % of 1, so a majorant 1 % lower fails
TEST(GravitationalSettlingKernel, MajorantBoundsTheKernelOverTheGrid)
{
    double worstGroup = 0.0;
    const double largest = largestKernelOverMajorant(settling, worstGroup);
    EXPECT_LE(largest, 1.0 + 1e-12);
    EXPECT_GT(largest, 0.99);
    EXPECT_GT(largest / 0.99, 1.0) << "a majorant 1 % lower would pass";
}

//- The sum of the Brownian transition kernel, settling and Saffman-Turner: K <= Khat of
//  every group on the grid, and the least group's Khat is within 1 % of K somewhere
TEST(SumKernel, MajorantBoundsTheKernelOverTheGrid)
{
    double worstGroup = 0.0;
    const double largest = largestKernelOverMajorant(brownianSettlingTurbulence, worstGroup);
    EXPECT_LE(worstGroup, 1.0 + 1e-12);
    EXPECT_LE(largest, 1.0 + 1e-12);
    EXPECT_GT(largest, 0.99);
}

//- The sum's value, basis and majorant are the parts' ones: K and every group's Khat the sums
//  of the parts' (group combinations in mixed radix), the least group's Khat the sum of the
//  parts' least ones
TEST(SumKernel, ValuesAndMajorantsAreThePartsSums)
{
    const GasState gas = air(1200.0, 1e5);
    const ParticleMaterial m{2000.0};
    auto t1 = std::make_shared<BrownianKernel>(BrownianRegime::transition, gas, m);
    auto t2 = std::make_shared<BrownianKernel>(BrownianRegime::transition, air(300.0, 1e5), m);
    auto s = std::make_shared<GravitationalSettlingKernel>(gas, m, 0.7, 20.0);
    const SumKernel sum({t1, s, t2});
    EXPECT_EQ(sum.name(), "sum");
    EXPECT_EQ(sum.nBasis(), 7 + 5 + 7);
    EXPECT_EQ(sum.nMajorantGroups(), 4);
    // the four combinations: t1 (4 terms in each group), s (9), t2 (4 in each group)
    EXPECT_EQ(sum.majorantTerms().size(), std::size_t(2 * 8 + 4 * 9 + 2 * 8));
    EXPECT_TRUE(sum.constantBasis(0));
    EXPECT_FALSE(sum.constantBasis(1));
    EXPECT_TRUE(sum.constantBasis(7));
    EXPECT_TRUE(sum.constantBasis(12));
    EXPECT_FALSE(sum.constantBasis(18));
    for (double d1 : gridDiameters()) {
        for (double d2 : {3e-9, 1e-7, 3e-6}) {
            const ParticleType a{m.mass(d1)}, b{m.mass(d2)};
            const double k = (*t1)(a, b) + (*s)(a, b) + (*t2)(a, b);
            EXPECT_NEAR(sum(a, b), k, 1e-14 * k);
            for (int g1 = 0; g1 < 2; ++g1) {
                for (int g2 = 0; g2 < 2; ++g2) {
                    const double khat =
                        t1->majorant(a, b, g1) + s->majorant(a, b) + t2->majorant(a, b, g2);
                    EXPECT_NEAR(sum.majorant(a, b, 2 * g1 + g2), khat, 1e-13 * khat);
                }
            }
            const double least = t1->majorant(a, b) + s->majorant(a, b) + t2->majorant(a, b);
            EXPECT_NEAR(sum.majorant(a, b), least, 1e-13 * least);
        }
    }
}

TEST(SumKernel, RefusesNoPartAndNullParts)
{
    EXPECT_THROW(SumKernel(std::vector<SumKernel::Part>{}), std::invalid_argument);
    EXPECT_THROW(SumKernel({std::make_shared<ConstantKernel>(1.0), nullptr}),
                 std::invalid_argument);
}

//- The sampler's limits: the sum of the Brownian transition kernel, settling and
//  Saffman-Turner has 17 terms in its first majorant group, more than
//  MajorantSampler::maxTerms; the free-molecular kernel, settling and the additive kernel have
//  14 basis functions and 15 terms but 19 columns under SWA, more than
//  QuantizedSumTree::maxColumns. The sampler refuses both, naming the kernel
//  and the limit. The Brownian kernels with settling fit, each group on its own: 13 terms and
//  16 columns at most.
TEST(SumKernel, SamplerRefusesASumBeyondItsLimits)
{
    const auto K = brownianSettlingTurbulence(air(300.0, 1e5), ParticleMaterial{1000.0});
    EXPECT_GT(K->majorantTerms().size(), MajorantSampler::maxTerms);
    MajorantSampler sampler(false);
    try {
        sampler.configure(*K, "test");
        FAIL() << "configured";
    } catch (const std::invalid_argument& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("'sum'"), std::string::npos) << what;
        EXPECT_NE(what.find("at most"), std::string::npos) << what;
    }
    const GasState gas = air(300.0, 1e5);
    const ParticleMaterial m{1000.0};
    auto fm = std::make_shared<BrownianKernel>(BrownianRegime::freeMolecular, gas, m);
    const SumKernel tooWide({fm, settling(gas, m), std::make_shared<AdditiveKernel>(1e-20)});
    MajorantSampler dsa(false), swa(true);
    EXPECT_NO_THROW(dsa.configure(tooWide, "test"));
    try {
        swa.configure(tooWide, "test");
        FAIL() << "configured";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("sampler columns"), std::string::npos) << e.what();
    }
    for (BrownianRegime r : {BrownianRegime::freeMolecular, BrownianRegime::transition}) {
        const SumKernel fits({std::make_shared<BrownianKernel>(r, gas, m), settling(gas, m)});
        EXPECT_NO_THROW(swa.configure(fits, "test")) << brownianRegimeName(r);
    }
}

//- The sampler's summed majorant over a polydisperse population (1 nm to 10 um) is the
//  directly summed pair total of the terms (the least group), and every pair's proposal rate
//  majorises its K (w2): settling alone and the sum of the Brownian continuum kernel and
//  settling (13 terms, 12 basis functions, 16 columns under SWA: the sampler's limit)
TEST(SumKernel, SamplerSumsTheMajorantOverAPopulation)
{
    const ParticleMaterial m{1800.0};
    const GasState gas = air(600.0, 1e5);
    const auto set = settling(gas, m);
    const auto sum = std::make_shared<SumKernel>(std::vector<SumKernel::Part>{
        std::make_shared<BrownianKernel>(BrownianRegime::continuum, gas, m), set});
    for (const auto& K : {set, std::shared_ptr<const CoagulationKernel>(sum)}) {
        for (bool weighted : {true, false}) {
            std::vector<Particle> P;
            for (int j = 0; j < 40; ++j) {
                const double d = 1e-9 * std::pow(10.0, 4.0 * (j % 9) / 8.0);
                P.push_back(Particle{ParticleType{m.mass(d)},
                                     weighted ? std::pow(2.0, j % 5 - 2.0) : 1.0, j});
            }
            MajorantSampler sampler(weighted);
            sampler.configure(*K, "test");
            sampler.build(P, P.size());
            const double rate = sampler.rateSum(P.size());
            double sum = 0.0, direct = 0.0;
            for (const Particle& a : P) {
                for (const Particle& b : P) {
                    const double pair = sampler.pairRate(a, b);
                    sum += pair;
                    direct += K->majorant(a.type, b.type) * (weighted ? b.weight : 1.0);
                    ASSERT_GE(pair, sampler.targetRate((*K)(a.type, b.type), b)) << K->name();
                }
            }
            EXPECT_NEAR(sum, rate, 1e-12 * rate) << K->name();
            // the tree's quantised values round up, by at most a few parts in a thousand
            EXPECT_GE(rate, direct * (1.0 - 1e-12)) << K->name();
            EXPECT_LT(rate, direct * 1.01) << K->name();
        }
    }
}

//- Closed cell of 1 um spheres (1500 kg/m3, masses in these monomers) in air at 293 K and
//  1 atm, Brownian (continuum) coagulation and differential settling together, number density
//  N0 = 1/K11 (K11 the Brownian one: equal spheres do not settle into each other): SWA and DSA1
//  against the discrete reference at 0.2, 1 and 3 / (K11 N0). Settling grows with the clusters'
//  size (K ~ m^(4/3) for large ones: the sum gels later, about t = 10): at t = 3 the reference's
//  M0 is 12 % below, its M2 36 % above Brownian coagulation's alone; the reference's truncation
//  (L = 400 and 800) changes its moments by less than 1e-6.
class SumReferenceTest : public ::testing::TestWithParam<std::string> {};

//- The reference's kernel: the two parts' values added here, not by SumKernel, so that a sum
//  that loses a part differs from the reference (the discrete reference reads K only)
class DirectSum : public CoagulationKernel {
public:
    DirectSum(const CoagulationKernel& a, const CoagulationKernel& b) : a_(a), b_(b) {}
    std::string name() const override { return "directSum"; }
    double operator()(const ParticleType& x, const ParticleType& y) const override
    {
        return a_(x, y) + b_(x, y);
    }
    int nBasis() const override { return 1; }
    void basis(const ParticleType&, double* phi) const override { phi[0] = 1.0; }
    const std::vector<MajorantTerm>& majorantTerms() const override { return none_; }

private:
    const CoagulationKernel& a_;
    const CoagulationKernel& b_;
    std::vector<MajorantTerm> none_;
};

TEST_P(SumReferenceTest, ClosedCellAgainstTheDiscreteReference)
{
    const GasState gas = air(293.0, 101325.0);
    const ParticleMaterial material = monomersOf(1500.0, 1e-6);
    const auto brownian = std::make_shared<BrownianKernel>(BrownianRegime::continuum, gas,
                                                           material);
    const auto settles = std::make_shared<GravitationalSettlingKernel>(gas, material);
    const SumKernel kernel({brownian, settles});
    const DirectSum direct(*brownian, *settles);
    const double N0 = 1.0 / direct(ParticleType{1.0}, ParticleType{1.0});
    const std::vector<double> times{0.2, 1.0, 3.0};

    const auto refAt = discreteReference(direct, N0, times, "Brownian + settling");

    const auto res = runEnsemble(GetParam(), kernel, InceptionModel{}, NumberControl{},
                                 [&] { return monodisperse(1000, 1000.0 / N0); }, times, 40, 43);
    expectMomentsMatch(res, times, refAt, 3, GetParam() + " Brownian + settling");
}

INSTANTIATE_TEST_SUITE_P(Algorithms, SumReferenceTest, ::testing::Values("SWA", "DSA1"),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                             return info.param;
                         });

} // namespace

