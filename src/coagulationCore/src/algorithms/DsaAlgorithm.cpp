// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
// The Direct Simulation Algorithms DSA1 and DSA2 (Patterson & Wagner 2011, §2.1): their
// coagulation jump. Inception (eqs 9-10), the pair rate K w / V per unordered pair (eq 12)
// and the event loop are JumpProcess's; all weights are equal (w, the paper's 1).
#include "JumpProcess.hpp"

namespace coag {
namespace detail {

namespace {

//- Eq 14: the probability p that the merged particle takes particle 1's place
struct HalfRule {  // DSA1: p = 1/2
    static constexpr const char* name = "DSA1";
    static double p(double, double) { return 0.5; }
};
struct MassRule {  // DSA2, eq 15: p = m1/(m1 + m2), the centre of mass kept in mean
    static constexpr const char* name = "DSA2";
    static double p(double m1, double m2) { return m1 / (m1 + m2); }
};

template <class Rule>
struct DsaJump {
    static constexpr const char* name = Rule::name;
    static constexpr bool equalWeights = true;
    static constexpr bool lookahead = false;  // the removal of j2 by swap changes two leaves more

    //- Eq 11: (x1, z1), (x2, z2) -> (x~, z1 + z2), x~ = x1 with probability p, else x2
    //  (eq 14; the place is the particle's slot and tag). The other one is removed by moving
    //  the last particle into its slot.
    void coagulate(CellPopulation& pop, std::size_t j1, std::size_t j2, Rng& rng,
                   MajorantSampler& sampler) const
    {
        ParticleVector& P = pop.particles;
        const ParticleType merged = P[j1].type + P[j2].type;
        const bool keepFirst = rng.uniform() < Rule::p(P[j1].type.mass, P[j2].type.mass);
        const std::size_t s = keepFirst ? j1 : j2;
        const std::size_t r = keepFirst ? j2 : j1;
        P[s].type = merged;
        sampler.set(P[s], s);
        const std::size_t last = P.size() - 1;
        if (r != last) P[r] = P[last];
        sampler.removeBySwap(r, last);
        P.pop_back();
    }
};

} // namespace

std::unique_ptr<CellAlgorithm> makeDsa1(const CoagulationKernel& kernel,
                                        const InceptionModel& inception,
                                        const NumberControl& control, DrawsAhead drawsAhead)
{
    return std::make_unique<JumpProcess<DsaJump<HalfRule>>>(kernel, inception, control, drawsAhead);
}

std::unique_ptr<CellAlgorithm> makeDsa2(const CoagulationKernel& kernel,
                                        const InceptionModel& inception,
                                        const NumberControl& control, DrawsAhead drawsAhead)
{
    return std::make_unique<JumpProcess<DsaJump<MassRule>>>(kernel, inception, control, drawsAhead);
}

} // namespace detail
} // namespace coag
