// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_EVENTLOOP_HPP
#define COAGULATION_EVENTLOOP_HPP

#include "coagulation/algorithms/CellAlgorithm.hpp"

#include <memory>
#include <string>

namespace coag {

//- The engine words (Rng draws) that one coagulation proposal of the jump process takes, in
//  the order it takes them (JumpProcess.hpp). The event loop's draws made ahead compute a
//  later proposal from the engine's next words before the current event is over, so they
//  must know how many words lie between: a wrong count costs no result (the draws are
//  checked and redone where they differ) but makes every draw made ahead useless.
struct EventWords {
    //- The waiting time, Rng::exponential: one word where the ziggurat accepts at once (its
    //  rectangles, nearly every draw); its wedges and tail draw more, and the draws made ahead
    //  then decline
    static constexpr int waitingTime = 1;
    //- The uniform that chooses inception or coagulation, and the majorant's term
    static constexpr int choice = 1;
    //- The pair: one Rng::uniformIndex per factor (the walks' integers or a uniform index),
    //  one word unless Lemire's rejection draws again (probability below n / 2^64)
    static constexpr int pair = 2;
    //- The acceptance's uniform, drawn for every pair with j1 != j2
    static constexpr int acceptance = 1;
    //- A whole proposal with its acceptance
    static constexpr int event = waitingTime + choice + pair + acceptance;
};

//- Whether the event loop may draw proposals ahead (MajorantSampler::lookAhead,
//  lookTwoAhead) where the sum tree is too big for the caches. The results are the same bit
//  for bit either way; `never` is for tests and same-binary benchmarks.
enum class DrawsAhead { whereTheyPay, never };

namespace detail {

//- makeCellAlgorithm with the draws made ahead chosen
std::unique_ptr<CellAlgorithm> makeCellAlgorithm(const std::string& name,
                                                 const CoagulationKernel& kernel,
                                                 const InceptionModel& inception,
                                                 const NumberControl& control,
                                                 DrawsAhead drawsAhead);

} // namespace detail
} // namespace coag

#endif
