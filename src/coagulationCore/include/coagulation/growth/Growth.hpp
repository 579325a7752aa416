// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_GROWTH_HPP
#define COAGULATION_GROWTH_HPP

// Growth in the source step of a cell. With G(t) the growth of every particle by the cell's
// law (GrowthLaw) and J(t) the jump process of inception and coagulation (CellAlgorithm),
// the source step is the symmetric (Strang) composition
//
//     S(dt) = G(dt/2) J(dt) G(dt/2),
//
// second order in dt for the source operator I + C + G, so that the transport splittings
// (Lie, Strang, StrangSAS) keep their order. Each G is exact (GrowthLaw: closed forms, else
// an adaptive step to 1e-10), so the only error is the splitting's, and there is none where
// the two commute: pure growth, and coagulation with a kernel that does not depend on the
// mass under growth with dm/dt proportional to m (a merged particle then grows as its parts
// would have, and the SWA weight factor m1/(m1 + m2) does not change). The jump process keeps
// its majorant exact as it is: the masses do not change during J.
//
// Weights are unchanged by growth (SWA and DSA alike); a particle that shrinks to the
// threshold leaves the population.

#include "coagulation/algorithms/CellAlgorithm.hpp"
#include "coagulation/growth/GrowthLaw.hpp"

namespace coag {

//- Every particle of pop after dt of law, its weight unchanged; the particles that reach
//  minMass (or zero), or start at or below it, removed, the others kept in their order.
//  Into stats: grownMass += sum w (m_end - m) (a gone particle's to the threshold), and
//  for the gone ones lostParticles, lostNumber (sum w) and lostMass (sum w m_end).
void growPopulation(CellPopulation& pop, const GrowthLaw& law, double dt, double minMass,
                    StepStatistics& stats);

//- The source step S(dt) = G(dt/2) J(dt) G(dt/2) of a cell: growth by law around the
//  algorithm's advance over dt with the kernel and the inception rate given; an empty law
//  with no minimum is the advance alone
void advanceWithGrowth(CellAlgorithm& algorithm, CellPopulation& pop,
                       const CoagulationKernel& kernel, double inceptionRate,
                       const GrowthLaw& law, double minMass, double dt, Rng& rng,
                       StepStatistics& stats);

} // namespace coag

#endif
