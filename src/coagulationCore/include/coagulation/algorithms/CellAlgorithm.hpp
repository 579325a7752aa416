// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_CELLALGORITHM_HPP
#define COAGULATION_CELLALGORITHM_HPP

#include "coagulation/population/CellPopulation.hpp"
#include "coagulation/kernels/CoagulationKernel.hpp"
#include "coagulation/population/Inception.hpp"
#include "coagulation/algorithms/NumberControl.hpp"
#include "coagulation/random/Rng.hpp"
#include "coagulation/algorithms/StepStatistics.hpp"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

namespace coag {

//- Stochastic simulation of inception + coagulation in one homogeneous cell
//  (Patterson & Wagner 2011, §2). With V = pop.volume (the sample volume the cell's particles
//  stand for: the paper's n V1) and w the weights:
//
//  SWA  (SwaAlgorithm.cpp): inception adds (z_incep, w_incep) (eq 19) at rate I V / w_incep
//       (eq 20); each ordered pair (j1 != j2) coagulates at rate K(z1,z2) w2 / V (eq 22), after
//       which j1 becomes (z1+z2, w1 m1/(m1+m2)) and j2 is unchanged (eq 21): sum w*m is
//       conserved exactly. Limit: eq 23.
//  DSA1/DSA2 (DsaAlgorithm.cpp): all weights equal to w (the inception weight when inception
//       is on; the paper's w = 1); inception (eq 9) at rate I V / w (eq 10); each unordered
//       pair coagulates at rate K w / V (eq 12) into one particle of type z1+z2 (eq 11) that
//       keeps the place (tag) of particle 1 with probability p and of particle 2 otherwise
//       (eq 14); the other particle is removed. DSA1: p = 1/2, DSA2: p = m1/(m1+m2) (eq 15).
//       Limits: eqs 16 and 17.
//  All three reproduce dn/dt = I + 1/2 sum sum K n n - n sum K n for n = sum(w)/V.
//
//  The jump process is simulated exactly (JumpProcess.hpp: Gillespie waiting times over
//  [0, dt], the total rate recomputed after every event) with pair proposals from the
//  kernel's product-form majorant (MajorantSampler.hpp) accepted with probability K/Khat
//  (Khat as the sampler's tree holds it: integer majorants of its factors).
//  Number control (NumberControl.hpp) halves or doubles the population. Cost per event
//  O(#terms + log N); the sampler is built once per advance() call (O(N)); no allocation per
//  event (particle vector and tree are reserved for the expected number of inceptions; rare
//  growth beyond that is amortised).
//
//  The algorithm object keeps a reference to its default kernel (which must outlive it) and
//  reusable work buffers: use one object per thread (kernels are stateless and shareable).
//  advance() may be given another kernel per call (a cell's own kernel, e.g. of its
//  temperature); the majorant layout is then taken from that kernel for the call. It may be
//  given the cell's own inception rate too (a source read from a field); the incepted type
//  and weight stay the algorithm's.
class CellAlgorithm {
public:
    explicit CellAlgorithm(const CoagulationKernel& kernel) : kernel_(kernel) {}
    virtual ~CellAlgorithm() = default;
    virtual std::string name() const = 0;  //!< "SWA", "DSA1", "DSA2"

    //- Limit on the expected number of events left in one advance() call (about 20 s of
    //  events in one cell; the paper's largest runs need about 1e6).
    static constexpr double maxExpectedEvents = 1e8;

    //- Advance one homogeneous cell over dt as an exact jump process (inception +
    //  coagulation) with the given kernel. Particles may be modified, added (tag -1: the
    //  caller places them) and (DSA) removed; the order of pop.particles is not preserved; DSA
    //  number control may change pop.volume. Accumulates into stats.
    //  Throws std::invalid_argument for dt < 0, volume <= 0, an unusable kernel majorant, and
    //  (DSA) unequal weights; std::runtime_error when the event rate is not finite (gelation,
    //  overflow) or when the events still expected in the step, rate*(dt - t), exceed
    //  maxExpectedEvents (a kernel, inception rate or dt far too large: the step would not
    //  end in any useful time).
    //  The inception rate is the algorithm's (InceptionModel::rate).
    void advance(CellPopulation& pop, const CoagulationKernel& kernel, double dt, Rng& rng,
                 StepStatistics& stats)
    {
        advance(pop, kernel, inception().rate, dt, rng, stats);
    }

    //- The same with the cell's own inception rate (physical particles per unit volume and
    //  time; finite and >= 0, else std::invalid_argument) in place of inception().rate: 0
    //  incepts nothing. The incepted type and weight are inception()'s; DSA's closed-cell
    //  doubling applies where this rate is 0.
    virtual void advance(CellPopulation& pop, const CoagulationKernel& kernel,
                         double inceptionRate, double dt, Rng& rng, StepStatistics& stats) = 0;

    //- The same with the algorithm's own kernel and inception rate
    void advance(CellPopulation& pop, double dt, Rng& rng, StepStatistics& stats)
    {
        advance(pop, kernel_, inception().rate, dt, rng, stats);
    }

    const CoagulationKernel& kernel() const { return kernel_; }

    //- The inception it was constructed with
    virtual const InceptionModel& inception() const = 0;

    //- Bytes of reusable work memory (the sum tree) currently held; for diagnostics.
    virtual std::size_t workspaceBytes() const { return 0; }

private:
    const CoagulationKernel& kernel_;
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
