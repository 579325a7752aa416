// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_CELLALGORITHM_HPP
#define COAGULATION_CELLALGORITHM_HPP

#include "coagulation/CellPopulation.hpp"
#include "coagulation/CoagulationKernel.hpp"
#include "coagulation/Inception.hpp"
#include "coagulation/NumberControl.hpp"
#include "coagulation/Rng.hpp"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

namespace coag {

//- Counters accumulated by CellAlgorithm::advance (never reset by it).
struct StepStatistics {
    std::uint64_t coagulations = 0;  //!< accepted coagulation jumps
    std::uint64_t fictitious = 0;    //!< rejected majorant proposals (j1 == j2 or K/Khat rejection)
    std::uint64_t inceptions = 0;    //!< incepted computational particles
    std::uint64_t halvings = 0;      //!< number-control halvings
    std::uint64_t doublings = 0;     //!< number-control doublings
    double inceptedMass = 0;         //!< physical mass added by inception = sum(weight*mass)
    double controlMass = 0;          //!< change of sum(w*m) by number control (SWA: zero mean;
                                     //!< DSA: the sample volume changes with it)

    //- Add another tally (e.g. one cell's, to a run's total)
    StepStatistics& operator+=(const StepStatistics& o)
    {
        coagulations += o.coagulations;
        fictitious += o.fictitious;
        inceptions += o.inceptions;
        halvings += o.halvings;
        doublings += o.doublings;
        inceptedMass += o.inceptedMass;
        controlMass += o.controlMass;
        return *this;
    }
};

//- Stochastic simulation of inception + coagulation in one homogeneous cell
//  (Patterson & Wagner 2011, §2). With V = pop.volume:
//
//  SWA  (eqs 19-22): inception adds (type, w_inc) at rate rate*V/w_inc; each ordered pair
//       (j1 != j2) coagulates at rate K(z1,z2) w2 / V, after which j1 becomes
//       (z1+z2, w1 m1/(m1+m2)) and j2 is unchanged (mass sum w*m conserved exactly).
//  DSA1/DSA2 (eqs 9-15): all weights equal to w (the inception weight when inception is
//       on); inception at rate rate*V/w; each unordered pair coagulates at rate K w / V into
//       one particle of type z1+z2 that sits at x1 (keeping particle 1's tag, hence its position)
//       with probability p and at x2 otherwise; the other particle is removed.
//       DSA1: p = 1/2, DSA2: p = m1/(m1+m2).
//  All three reproduce dn/dt = I + 1/2 sum sum K n n - n sum K n for n = sum(w)/V.
//
//  The jump process is simulated exactly (Gillespie waiting times over [0, dt], the total
//  rate recomputed from the tree totals after every event) with the kernel's product-form
//  majorant Khat = sum_t coeff_t phi_first(z1) phi_second(z2): a term t is picked with
//  probability proportional to coeff_t * S_first * S_secondWeighted (S = sums over the
//  particles of phi, resp. phi*w), then j1 ~ phi_first(z_j1) and j2 ~ phi_second(z_j2)*w_j2;
//  j1 == j2 is rejected and otherwise the proposal is accepted with probability K/Khat
//  (rejections are counted as fictitious jumps). The sums live in a SumTree (fan-out 8, one
//  flat array, exact recomputed sums); factors whose basis function is constant
//  (CoagulationKernel::constantBasis) and carry no varying weight are drawn uniformly and need
//  no tree column (for DSA the common weight is pulled out of the sums). Cost per event
//  O(#terms + log N); the tree is built once per advance() call (O(N)); no allocation per
//  event (particle vector and tree are reserved for the expected number of inceptions; rare
//  growth beyond that is amortised).
//
//  The algorithm object keeps a reference to the kernel (which must outlive it) and
//  reusable work buffers: use one object per thread (kernels are stateless and shareable).
class CellAlgorithm {
public:
    virtual ~CellAlgorithm() = default;
    virtual std::string name() const = 0;  //!< "SWA", "DSA1", "DSA2"

    //- Limit on the expected number of events left in one advance() call (about 20 s of
    //  events in one cell; the paper's largest runs need about 1e6).
    static constexpr double maxExpectedEvents = 1e8;

    //- Advance one homogeneous cell over dt as an exact jump process (inception +
    //  coagulation). Particles may be modified, added (tag -1: the caller
    //  places them) and (DSA) removed; the order of pop.particles is not preserved; DSA number
    //  control may change pop.volume. Accumulates into stats.
    //  Throws std::invalid_argument for dt < 0, volume <= 0, and (DSA) unequal weights;
    //  std::runtime_error when the event rate is not finite (gelation, overflow) or when the
    //  events still expected in the step, rate*(dt - t), exceed maxExpectedEvents (a kernel,
    //  inception rate or dt far too large: the step would not end in any useful time).
    virtual void advance(CellPopulation& pop, double dt, Rng& rng, StepStatistics& stats) = 0;

    //- Bytes of reusable work memory (the sum tree) currently held; for diagnostics.
    virtual std::size_t workspaceBytes() const { return 0; }
};

//- "SWA", "DSA1", "DSA2". Unknown name, negative or non-finite inception rate, nonpositive
//  inception weight, or maxParticles < 2*minParticles (both on) -> std::invalid_argument.
std::unique_ptr<CellAlgorithm> makeCellAlgorithm(const std::string& name,
                                                 const CoagulationKernel& kernel,
                                                 const InceptionModel& inception,
                                                 const NumberControl& control = {});

//- The names makeCellAlgorithm accepts.
std::vector<std::string> cellAlgorithmNames();

} // namespace coag

#endif
