// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
// MajorantSampler on its own: the summed majorant rate and the law of its pair proposals.
#include "coagulation/sampling/MajorantSampler.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

using namespace coag;

namespace {

//- Ordered pairs (j1, j2), j1 == j2 included, are proposed with probability
//  Khat(z1, z2) w2 / sum (weightedSecond, SWA) or Khat(z1, z2) / sum (DSA), and rateSum is that
//  sum; checked for the additive (tree columns only) and the multiplicative-plus-constant
//  shapes by a chi-square test over all 16 pairs (fixed seed, 15 degrees of freedom, 0.1 %
//  critical value 37.7).
void checkProposals(const CoagulationKernel& kernel, bool weightedSecond)
{
    const std::vector<Particle> P{{ParticleType{1.0}, 1.0, 0},
                                  {ParticleType{2.0}, 0.5, 1},
                                  {ParticleType{3.0}, 2.0, 2},
                                  {ParticleType{5.0}, 1.0, 3}};
    const std::size_t n = P.size();
    MajorantSampler sampler(weightedSecond);
    sampler.configure(kernel, "test");
    sampler.build(P, 8);

    std::vector<double> expected(n * n);
    double sum = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t k = 0; k < n; ++k) {
            const double v = kernel.majorant(P[i].type, P[k].type)
                             * (weightedSecond ? P[k].weight : 1.0);
            expected[i * n + k] = v;
            sum += v;
        }
    }
    ASSERT_NEAR(sampler.rateSum(n), sum, 1e-12 * sum);

    Rng rng(4242);
    const int draws = 200000;
    std::vector<double> count(n * n, 0.0);
    for (int d = 0; d < draws; ++d) {
        std::size_t j1 = 0, j2 = 0;
        sampler.propose(rng.uniform() * sum, n, rng, P.data(), j1, j2);
        ASSERT_LT(j1, n);
        ASSERT_LT(j2, n);
        count[j1 * n + j2] += 1.0;
    }
    double chi2 = 0.0;
    for (std::size_t c = 0; c < n * n; ++c) {
        const double e = draws * expected[c] / sum;
        chi2 += (count[c] - e) * (count[c] - e) / e;
    }
    EXPECT_LT(chi2, 37.7) << kernel.name() << (weightedSecond ? " weighted" : " unweighted");
}

TEST(MajorantSampler, ProposesPairsByTheMajorant)
{
    for (bool weighted : {true, false}) {
        checkProposals(*makeKernel("additive", 1.5), weighted);
        checkProposals(*makeKernel("multiplicative", 0.5), weighted);
        checkProposals(*makeKernel("constant", 2.0), weighted);
        checkProposals(*makeKernel("saffmanTurner", 0.5), weighted);
    }
}

//- pairRate() is the rate at which propose() offers the pair: summed over all ordered pairs
//  it is rateSum(), also for values the tree's quantisation covers coarsely (masses over 25
//  decades, so the smallest are one scale unit), and it majorises the target rate K (w2).
//  So K (w2) / pairRate is the acceptance that makes the jump rates exact.
TEST(MajorantSampler, PairRatesSumToTheRateSumAndMajoriseTheKernel)
{
    for (const char* name : {"additive", "multiplicative", "saffmanTurner", "constant"}) {
        for (bool weighted : {true, false}) {
            auto kernel = makeKernel(name, 1.5);
            std::vector<Particle> P;
            for (int j = 0; j < 40; ++j) {
                P.push_back(Particle{ParticleType{std::pow(10.0, -25.0 + 25.0 * (j % 8) / 7.0)},
                                     weighted ? std::pow(2.0, j % 5 - 2.0) : 1.0, j});
            }
            MajorantSampler sampler(weighted);
            sampler.configure(*kernel, "test");
            sampler.build(P, P.size());
            const double rate = sampler.rateSum(P.size());
            double sum = 0.0;
            for (const Particle& a : P) {
                for (const Particle& b : P) {
                    const double pair = sampler.pairRate(a, b);
                    sum += pair;
                    ASSERT_GE(pair, sampler.targetRate((*kernel)(a.type, b.type), b)) << name;
                }
            }
            EXPECT_NEAR(sum, rate, 1e-12 * rate) << name << (weighted ? " weighted" : "");
        }
    }
}

//- pairRateAt(j1, j2), which reads the tree's leaves, is pairRate(p1, p2), which
//  quantises the particles' values afresh, bit for bit: after the build, after changes in
//  place, after coarsenings (a particle a million times heavier than the column's largest),
//  after appends that grow the tree (fewer bits a leaf: every column coarsened) and after
//  removals by swap; for every kernel shape and both weightings.
TEST(MajorantSampler, PairRateFromTheLeavesIsThePairRateFromTheParticles)
{
    for (const char* name : {"additive", "multiplicative", "saffmanTurner", "constant"}) {
        for (bool weighted : {true, false}) {
            auto kernel = makeKernel(name, 1.5);
            std::vector<Particle> P;
            for (int j = 0; j < 20; ++j) {
                P.push_back(Particle{ParticleType{1.0 + 0.37 * j}, 0.5 + 0.11 * (j % 7), j});
            }
            MajorantSampler sampler(weighted);
            sampler.configure(*kernel, "test");
            sampler.build(P, P.size());
            Rng rng(7);
            std::size_t compared = 0;
            auto compare = [&](const char* after) {
                const std::size_t n = P.size();
                sampler.rateSum(n);
                for (int k = 0; k < 25; ++k) {
                    const std::size_t a = rng.uniformIndex(n), b = rng.uniformIndex(n);
                    ASSERT_EQ(sampler.pairRateAt(a, b), sampler.pairRate(P[a], P[b]))
                        << name << (weighted ? " weighted" : "") << " after " << after;
                    ++compared;
                }
            };
            compare("the build");
            for (int s = 0; s < 300; ++s) {
                const std::size_t n = P.size();
                const double r = rng.uniform();
                if (r < 0.6) {
                    const std::size_t a = rng.uniformIndex(n), b = rng.uniformIndex(n);
                    const double m1 = P[a].type.mass, m2 = P[b].type.mass;
                    P[a].type.mass = m1 + m2;
                    P[a].weight *= m1 / (m1 + m2);
                    sampler.set(P[a], a);
                    compare("a change");
                } else if (r < 0.65) {
                    const std::size_t a = rng.uniformIndex(n);
                    P[a].type.mass *= 1e6;  // past the column's headroom: coarsened
                    sampler.set(P[a], a);
                    compare("a coarsening");
                } else if (r < 0.85) {
                    P.push_back(Particle{ParticleType{0.5 + rng.uniform()}, rng.uniform(), -1});
                    sampler.append(P.back(), P.size() - 1);
                    compare("an append");
                } else if (n > 10) {
                    const std::size_t k = rng.uniformIndex(n);
                    sampler.removeBySwap(k, n - 1);
                    P[k] = P[n - 1];
                    P.pop_back();
                    compare("a removal");
                }
            }
            EXPECT_GT(compared, 5000u);
        }
    }
}

//- proposeAhead() after lookAhead() proposes exactly the pairs propose() does, along a
//  population that changes between the two calls as SWA's does (one set()) and otherwise
//  (coarsenings, appends, removals by swap): two samplers on the same particles and random
//  streams, one looking ahead with the stream's next words (or, every third proposal,
//  with other words), for 4 kernels (SWA's weighted second factors); and a third making
//  its draws ahead in two halves (lookTwoAhead() for the proposal after next,
//  finishLookAhead() for the next), the same way. A bigger tree than the rest of this file
//  (400 particles, 3 levels), so that the draws made ahead have walks to save.
TEST(MajorantSampler, ProposalsDrawnAheadAreTheProposals)
{
    for (const char* name : {"additive", "multiplicative", "saffmanTurner", "constant"}) {
        auto kernel = makeKernel(name, 1.5);
        std::vector<Particle> P;
        for (int j = 0; j < 400; ++j) {
            P.push_back(Particle{ParticleType{1.0 + 0.37 * (j % 50)}, 0.5 + 0.11 * (j % 7), j});
        }
        MajorantSampler plain(true), ahead(true), halves(true);
        plain.configure(*kernel, "test");
        ahead.configure(*kernel, "test");
        halves.configure(*kernel, "test");
        plain.build(P, P.size());
        ahead.build(P, P.size());
        halves.build(P, P.size());
        Rng rngPlain(11), rngAhead(11), rngHalves(11), changes(5);
        std::size_t compared = 0;
        for (int s = 0; s < 6000; ++s) {
            const std::size_t n = P.size();
            const double sum = plain.rateSum(n);
            ASSERT_EQ(ahead.rateSum(n), sum);
            const double u = rngPlain.uniform() * sum;
            ASSERT_EQ(rngAhead.uniform() * sum, u);
            ASSERT_EQ(halves.rateSum(n), sum);
            ASSERT_EQ(rngHalves.uniform() * sum, u);
            std::size_t a1 = 0, a2 = 0, b1 = 0, b2 = 0, h1 = 0, h2 = 0;
            plain.propose(u, n, rngPlain, P.data(), a1, a2);
            ahead.proposeAhead(u, n, rngAhead, P.data(), b1, b2);
            halves.proposeAhead(u, n, rngHalves, P.data(), h1, h2);
            ASSERT_EQ(a1, b1) << name << " proposal " << s;
            ASSERT_EQ(a2, b2) << name << " proposal " << s;
            ASSERT_EQ(a1, h1) << name << " proposal " << s << " (two halves)";
            ASSERT_EQ(a2, h2) << name << " proposal " << s << " (two halves)";
            ++compared;
            // the next proposal drawn ahead, before this one's change; every third from other
            // words (a wrong guess, often of another term: declined or exact all the same)
            if (s % 3 == 2) {
                Rng::Engine peek = changes.engine();
                ahead.lookAhead(changes.uniform() * sum, n, peek, P.data());
            } else {
                Rng::Engine peek = rngAhead.engine();
                ahead.lookAhead(Rng::toUniform(peek()) * sum, n, peek, P.data());
            }
            halves.finishLookAhead(P.data());
            if (s % 3 == 1) {
                Rng::Engine peek = changes.engine();
                halves.lookTwoAhead(changes.uniform() * sum, n, peek, P.data());
            } else {
                Rng::Engine peek = rngHalves.engine();
                for (int word = 0; word < 3; ++word) peek();  // the next: a uniform, two integers
                halves.lookTwoAhead(Rng::toUniform(peek()) * sum, n, peek, P.data());
            }
            const double r = changes.uniform();
            if (r < 0.7) {
                if (a1 == a2) continue;
                const double m1 = P[a1].type.mass, m2 = P[a2].type.mass;  // eq 21
                P[a1].type.mass = m1 + m2;
                P[a1].weight *= m1 / (m1 + m2);
                plain.set(P[a1], a1);
                ahead.set(P[a1], a1);
                halves.set(P[a1], a1);
            } else if (r < 0.72) {
                const std::size_t a = changes.uniformIndex(n);
                P[a].type.mass *= 1e6;  // past the column's headroom: coarsened
                plain.set(P[a], a);
                ahead.set(P[a], a);
                halves.set(P[a], a);
            } else if (r < 0.86) {
                P.push_back(Particle{ParticleType{0.5 + changes.uniform()}, changes.uniform(), -1});
                plain.append(P.back(), P.size() - 1);
                ahead.append(P.back(), P.size() - 1);
                halves.append(P.back(), P.size() - 1);
            } else if (n > 200) {
                const std::size_t k = changes.uniformIndex(n);
                plain.removeBySwap(k, n - 1);
                ahead.removeBySwap(k, n - 1);
                halves.removeBySwap(k, n - 1);
                P[k] = P[n - 1];
                P.pop_back();
            }
        }
        EXPECT_EQ(compared, 6000u);
    }
}

//- After a removal by swap and a change in place the sums follow the particles
TEST(MajorantSamplerStore, FollowsChangesAndRemovals)
{
    auto kernel = makeKernel("additive", 1.0);
    std::vector<Particle> P{{ParticleType{1.0}, 1.0, 0},
                            {ParticleType{2.0}, 1.0, 1},
                            {ParticleType{4.0}, 1.0, 2}};
    MajorantSampler sampler(true);
    sampler.configure(*kernel, "test");
    sampler.build(P, 3);
    auto direct = [&] {
        double s = 0.0;
        for (const Particle& a : P)
            for (const Particle& b : P) s += kernel->majorant(a.type, b.type) * b.weight;
        return s;
    };
    P[0].type.mass = 7.0;
    P[0].weight = 0.25;
    sampler.set(P[0], 0);
    EXPECT_NEAR(sampler.rateSum(P.size()), direct(), 1e-12);
    sampler.removeBySwap(1, 2);
    P[1] = P[2];
    P.pop_back();
    EXPECT_NEAR(sampler.rateSum(P.size()), direct(), 1e-12);
    P.push_back(Particle{ParticleType{3.0}, 2.0, -1});
    sampler.append(P.back(), P.size() - 1);  // grows the tree past its capacity 3
    EXPECT_NEAR(sampler.rateSum(P.size()), direct(), 1e-12);
}

//- After many accepted-style changes (SWA's eq 21 on random pairs), appends and removals,
//  the proposals still follow Khat w2: chi-square of the first and the second index
//  against their exact marginals (0.1 % critical values).
TEST(MajorantSamplerStore, ProposalsFollowAChangingPopulation)
{
    auto kernel = makeKernel("additive", 1.0);
    std::vector<Particle> P;
    for (int j = 0; j < 30; ++j) P.push_back(Particle{ParticleType{1.0 + j % 4}, 1.0, j});
    MajorantSampler sampler(true);
    sampler.configure(*kernel, "test");
    sampler.build(P, P.size());
    Rng rng(99);
    for (int s = 0; s < 400; ++s) {
        const std::size_t n = P.size();
        const double r = rng.uniform();
        if (r < 0.7) {
            const std::size_t a = rng.uniformIndex(n), b = rng.uniformIndex(n);
            if (a == b) continue;
            const double m1 = P[a].type.mass, m2 = P[b].type.mass;
            P[a].type.mass = m1 + m2;
            P[a].weight *= m1 / (m1 + m2);
            sampler.set(P[a], a);
        } else if (r < 0.85) {
            P.push_back(Particle{ParticleType{0.5 + rng.uniform()}, 3.0 * rng.uniform(), -1});
            sampler.append(P.back(), P.size() - 1);
        } else if (n > 10) {
            const std::size_t k = rng.uniformIndex(n);
            sampler.removeBySwap(k, n - 1);
            P[k] = P[n - 1];
            P.pop_back();
        }
    }
    const std::size_t n = P.size();
    std::vector<double> e1(n, 0.0), e2(n, 0.0);
    double sum = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t k = 0; k < n; ++k) {
            const double v = kernel->majorant(P[i].type, P[k].type) * P[k].weight;
            e1[i] += v;
            e2[k] += v;
            sum += v;
        }
    }
    ASSERT_NEAR(sampler.rateSum(n), sum, 1e-12 * sum);
    const int draws = 400000;
    std::vector<double> c1(n, 0.0), c2(n, 0.0);
    for (int d = 0; d < draws; ++d) {
        std::size_t j1 = 0, j2 = 0;
        sampler.propose(rng.uniform() * sum, n, rng, P.data(), j1, j2);
        ASSERT_LT(j1, n);
        ASSERT_LT(j2, n);
        c1[j1] += 1.0;
        c2[j2] += 1.0;
    }
    double chi1 = 0.0, chi2 = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const double a = draws * e1[i] / sum, b = draws * e2[i] / sum;
        chi1 += (c1[i] - a) * (c1[i] - a) / a;
        chi2 += (c2[i] - b) * (c2[i] - b) / b;
    }
    const double z = 3.09, k = static_cast<double>(n - 1);  // Wilson-Hilferty, 0.1 %
    const double crit = k * std::pow(1.0 - 2.0 / (9.0 * k) + z * std::sqrt(2.0 / (9.0 * k)), 3);
    EXPECT_LT(chi1, crit) << n << " particles";
    EXPECT_LT(chi2, crit) << n << " particles";
}


} // namespace

namespace {

//- A kernel with nb basis functions phi_b = m^b and the given terms (majorant only: the
//  sampler's limits are what is tested)
class PowerBasisKernel : public CoagulationKernel {
public:
    PowerBasisKernel(int nb, std::vector<MajorantTerm> terms) : nb_(nb), terms_(std::move(terms)) {}
    std::string name() const override { return "powerBasis"; }
    double operator()(const ParticleType& a, const ParticleType& b) const override
    {
        return majorant(a, b);
    }
    int nBasis() const override { return nb_; }
    void basis(const ParticleType& z, double* phi) const override
    {
        for (int b = 0; b < nb_; ++b) phi[b] = std::pow(z.mass, b);
    }
    const std::vector<MajorantTerm>& majorantTerms() const override { return terms_; }

private:
    int nb_;
    std::vector<MajorantTerm> terms_;
};

} // namespace

TEST(MajorantSampler, RefusesKernelsPastItsLimits)
{
    // within the limits: 16 basis functions, 16 terms, 16 tree columns (SWA weights the
    // second factors: columns m^0..m^14 and m^0 w; the last term repeats the first)
    std::vector<MajorantTerm> terms;
    for (int b = 0; b < 15; ++b) terms.push_back({1.0, b, 0});
    terms.push_back({1.0, 0, 0});
    const PowerBasisKernel within(16, terms);
    MajorantSampler sampler(true);
    ASSERT_NO_THROW(sampler.configure(within, "test"));
    std::vector<Particle> P{{ParticleType{1.5}, 2.0, 0}, {ParticleType{0.5}, 3.0, 1}};
    sampler.build(P, 2);
    double expected = 0.0;  // sum over ordered pairs, j1 == j2 included, of Khat(z1, z2) w2
    for (const Particle& p1 : P) {
        for (const Particle& p2 : P) expected += within.majorant(p1.type, p2.type) * p2.weight;
    }
    EXPECT_NEAR(sampler.rateSum(2), expected, 1e-6 * expected);

    auto message = [](const CoagulationKernel& k) {
        MajorantSampler s(true);
        try {
            s.configure(k, "who");
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    const std::string basis = message(PowerBasisKernel(17, {{1.0, 16, 0}}));
    EXPECT_NE(basis.find("who: kernel 'powerBasis' has 17 basis functions"), std::string::npos)
        << basis;
    std::vector<MajorantTerm> many(17, MajorantTerm{1.0, 0, 1});
    const std::string termCount = message(PowerBasisKernel(2, many));
    EXPECT_NE(termCount.find("17 terms in a majorant, at most 16"), std::string::npos)
        << termCount;
    std::vector<MajorantTerm> wide;
    for (int b = 0; b < 9; ++b) wide.push_back({1.0, b, b});  // 9 + 9 tree columns
    const std::string columns = message(PowerBasisKernel(9, wide));
    EXPECT_NE(columns.find("needs more than 16 sampler columns"), std::string::npos) << columns;
}
