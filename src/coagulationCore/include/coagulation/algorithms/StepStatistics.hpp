// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_STEPSTATISTICS_HPP
#define COAGULATION_STEPSTATISTICS_HPP

#include <cstdint>

namespace coag {

//- Counters accumulated by CellAlgorithm::advance and the number control (never reset by
//  them).
struct StepStatistics {
    std::uint64_t coagulations = 0;  //!< accepted coagulation jumps
    std::uint64_t fictitious = 0;    //!< rejected majorant proposals (j1 == j2 or K/Khat rejection)
    std::uint64_t inceptions = 0;    //!< incepted computational particles
    std::uint64_t halvings = 0;      //!< number-control halvings
    std::uint64_t doublings = 0;     //!< number-control doublings
    double inceptedMass = 0;         //!< physical mass added by inception = sum(weight*mass)
    double controlMass = 0;          //!< change of sum(w*m) by number control (SWA: zero mean;
                                     //!< DSA: the sample volume changes with it)
    double grownMass = 0;            //!< change of sum(w*m) by growth (negative: shrinking)
    std::uint64_t lostParticles = 0; //!< computational particles gone by shrinking
    double lostNumber = 0;           //!< their physical particles, sum(w)
    double lostMass = 0;             //!< their mass when they went, sum(w*m)

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
        grownMass += o.grownMass;
        lostParticles += o.lostParticles;
        lostNumber += o.lostNumber;
        lostMass += o.lostMass;
        return *this;
    }
};

} // namespace coag

#endif
