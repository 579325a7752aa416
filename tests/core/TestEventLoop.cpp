// coagulationFoam core tests. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#include "TestHelpers.hpp"

#include <map>

namespace {

using namespace coag;
using namespace coagtest;

//- The engine words between two states of one engine (-1: more than 64)
int wordsBetween(Rng::Engine before, const Rng::Engine& after)
{
    for (int k = 0; k <= 64; ++k) {
        if (before == after) return k;
        before();
    }
    return -1;
}

//- The fraction of the counts that equal `expected`, and the most frequent count
struct Tally {
    std::map<int, int> counts;
    int total = 0;
    void add(int k)
    {
        ++counts[k];
        ++total;
    }
    double fraction(int k) const
    {
        const auto it = counts.find(k);
        return it == counts.end() ? 0.0 : double(it->second) / total;
    }
    int mode() const
    {
        int best = -2, n = -1;
        for (const auto& c : counts) {
            if (c.second > n) {
                best = c.first;
                n = c.second;
            }
        }
        return best;
    }
};

} // namespace

//- EventWords, which the draws made ahead rely on, holds the words that the jump process's
//  draws take, measured draw by draw in the event loop's order (waiting time, choice, pair,
//  acceptance) on a polydisperse population in a sum tree: the pair from two tree columns
//  (additive, multiplicative) and from a uniform index and a tree column (constant, SWA's
//  weighted second factor). Each constant is the most frequent count, taken by every draw of
//  the choice and the acceptance, 99.9 % of the pairs, and 97 % of the waiting times and
//  whole events (the ziggurat takes more words outside its rectangles).
TEST(EventWords, AreTheWordsTheEventLoopsDrawsTake)
{
    for (const char* name : {"additive", "multiplicative", "constant"}) {
        auto kernel = makeKernel(name, 1.0);
        std::vector<Particle> P;
        for (int j = 0; j < 1000; ++j) {
            P.push_back(Particle{ParticleType{1.0 + j % 7}, 0.5 + 0.1 * (j % 5), j});
        }
        const std::size_t n = P.size();
        MajorantSampler sampler(true);
        sampler.configure(*kernel, "test");
        sampler.build(P, n);
        const double sum = sampler.rateSum(n);
        Rng rng(2024);
        Tally waiting, choice, pair, acceptance, event;
        for (int d = 0; d < 20000; ++d) {
            const Rng::Engine e0 = rng.engine();
            rng.exponential(sum);
            const Rng::Engine e1 = rng.engine();
            const double u = rng.uniform() * sum;
            const Rng::Engine e2 = rng.engine();
            std::size_t j1 = 0, j2 = 0;
            sampler.propose(u, n, rng, P.data(), j1, j2);
            const Rng::Engine e3 = rng.engine();
            rng.uniform();
            const Rng::Engine e4 = rng.engine();
            waiting.add(wordsBetween(e0, e1));
            choice.add(wordsBetween(e1, e2));
            pair.add(wordsBetween(e2, e3));
            acceptance.add(wordsBetween(e3, e4));
            event.add(wordsBetween(e0, e4));
        }
        EXPECT_EQ(waiting.mode(), EventWords::waitingTime) << name;
        EXPECT_GE(waiting.fraction(EventWords::waitingTime), 0.97) << name;
        EXPECT_EQ(choice.fraction(EventWords::choice), 1.0) << name;
        EXPECT_EQ(pair.mode(), EventWords::pair) << name;
        EXPECT_GE(pair.fraction(EventWords::pair), 0.999) << name;
        EXPECT_EQ(acceptance.fraction(EventWords::acceptance), 1.0) << name;
        EXPECT_EQ(event.mode(), EventWords::event) << name;
        EXPECT_GE(event.fraction(EventWords::event), 0.97) << name;
    }
}
