// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
// MajorantSampler on its own: the summed majorant rate and the law of its pair proposals.
#include "coagulation/MajorantSampler.hpp"

#include <gtest/gtest.h>

#include <cmath>
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
    }
}

//- After a removal by swap and a change in place the sums follow the particles
TEST(MajorantSampler, FollowsChangesAndRemovals)
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

} // namespace
