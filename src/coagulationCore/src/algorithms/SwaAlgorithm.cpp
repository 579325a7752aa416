// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
// The Stochastic Weighted Algorithm (Patterson & Wagner 2011, §2.2): its coagulation jump.
// Inception (eqs 19-20), the pair rate K w2 / V (eq 22) and the event loop are JumpProcess's.
#include "JumpProcess.hpp"

namespace coag {
namespace detail {

namespace {

struct SwaJump {
    static constexpr const char* name = "SWA";
    static constexpr bool equalWeights = false;
    static constexpr bool lookahead = true;  // eq 21 changes one particle: one set()

    //- Eq 21: (z1, w1), (z2, w2) -> (z1 + z2, w1 m1/(m1 + m2)), (z2, w2). Only particle j1
    //  changes, in place; sum w*m is conserved exactly.
    void coagulate(CellPopulation& pop, std::size_t j1, std::size_t j2, Rng&,
                   MajorantSampler& sampler) const
    {
        Particle& a = pop.particles[j1];
        const double m1 = a.type.mass;
        const double m2 = pop.particles[j2].type.mass;
        a.type = a.type + pop.particles[j2].type;
        a.weight *= m1 / (m1 + m2);
        sampler.set(a, j1);
    }
};

} // namespace

std::unique_ptr<CellAlgorithm> makeSwa(const CoagulationKernel& kernel,
                                       const InceptionModel& inception,
                                       const NumberControl& control, DrawsAhead drawsAhead)
{
    return std::make_unique<JumpProcess<SwaJump>>(kernel, inception, control, drawsAhead);
}

} // namespace detail
} // namespace coag
