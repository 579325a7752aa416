// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_COUNTERSTREAM_HPP
#define COAGULATION_COUNTERSTREAM_HPP

#include "coagulation/random/Normal.hpp"
#include "coagulation/random/Rng.hpp"
#include "coagulation/random/SplitMix64.hpp"

#include <cstdint>

namespace coag {

//- A counter-based stream: the k-th draw is a pure function of (key, k), the SplitMix64
//  sequence started at key (SplitMix64.hpp). Every particle of every transport step gets its
//  own key, so that a random walk step does not depend on which thread moves the particle or
//  on anything drawn before it; seeding costs nothing.
class CounterStream {
public:
    explicit CounterStream(std::uint64_t key) : state_(key) {}

    std::uint64_t next() { return splitMix64Next(state_); }

    //- Uniform on the open interval (0,1), as Rng::uniform.
    double uniform() { return Rng::toUniform(next()); }

    //- Three independent standard normals (Box-Muller on two uniform pairs; the fourth
    //  normal is dropped so that every particle uses exactly four draws).
    void normal3(double xi[3])
    {
        const double u1 = uniform();
        const double u2 = uniform();
        const double u3 = uniform();
        const double u4 = uniform();
        const NormalPair a = boxMuller(u1, u2);
        const NormalPair b = boxMuller(u3, u4);
        xi[0] = a.first;
        xi[1] = a.second;
        xi[2] = b.first;
    }

private:
    std::uint64_t state_;
};

} // namespace coag

#endif
