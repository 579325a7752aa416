// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_SPLITMIX64_HPP
#define COAGULATION_SPLITMIX64_HPP

#include <cstdint>

namespace coag {

//- SplitMix64 (Steele, Lea & Flood, "Fast splittable pseudorandom number generators",
//  OOPSLA 2014): a Weyl sequence state += golden, each state scrambled by the finaliser
//  below. The project's one mixer: the generator's seeding, the counter-based streams, and
//  the keys of every random stream (streamSeeds) are made with it.
constexpr std::uint64_t splitMix64Golden = 0x9e3779b97f4a7c15ULL;

//- The finaliser (Stafford's variant 13 of MurmurHash3's fmix64): a bijection of the 64-bit
//  words in which every input bit flips about half of the output bits.
constexpr std::uint64_t splitMix64Finalise(std::uint64_t z)
{
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

//- The next word of the sequence whose state is s (advances s).
inline std::uint64_t splitMix64Next(std::uint64_t& s)
{
    return splitMix64Finalise(s += splitMix64Golden);
}

//- The first word of the sequence started at z: a hash of z, used to derive unrelated keys
//  from neighbouring seeds, counters and indices.
constexpr std::uint64_t mix64(std::uint64_t z)
{
    return splitMix64Finalise(z + splitMix64Golden);
}

} // namespace coag

#endif
