// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_RNG_HPP
#define COAGULATION_RNG_HPP

#include "coagulation/random/SplitMix64.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

namespace coag {

//- xoshiro256++ (Blackman & Vigna, "Scrambled linear pseudorandom number generators",
//  ACM TOMS 47, 2021): 256 bits of state, period 2^256 - 1, all 64 output bits pass
//  BigCrush and PractRand. A standard UniformRandomBitGenerator (std:: distributions take it).
//
//  Why not std::mt19937_64: every cell step seeds its own stream (counter-style seeding,
//  streamSeeds), and seeding a Mersenne twister fills 312 words and refills them on the first
//  draw, about 1 microsecond, a fifth of a cell step with a hundred particles
//  (doc/performance.md). seed() here is four SplitMix64 steps (Vigna's recommended initialisation: it
//  never gives the all-zero state, and nearby seeds give unrelated states).
class Xoshiro256pp {
public:
    using result_type = std::uint64_t;
    static constexpr result_type min() { return 0; }
    static constexpr result_type max() { return ~result_type(0); }

    explicit Xoshiro256pp(std::uint64_t s = 0) { seed(s); }

    void seed(std::uint64_t s)
    {
        for (std::uint64_t& word : s_) word = splitMix64Next(s);
    }

    result_type operator()()
    {
        const std::uint64_t result = rotl(s_[0] + s_[3], 23) + s_[0];
        const std::uint64_t t = s_[1] << 17;
        s_[2] ^= s_[0];
        s_[3] ^= s_[1];
        s_[1] ^= s_[2];
        s_[0] ^= s_[3];
        s_[2] ^= t;
        s_[3] = rotl(s_[3], 45);
        return result;
    }

    //- The four state words (for state text and tests); setWords rejects the all-zero state
    const std::array<std::uint64_t, 4>& words() const { return s_; }
    bool setWords(const std::array<std::uint64_t, 4>& w)
    {
        if ((w[0] | w[1] | w[2] | w[3]) == 0) return false;
        s_ = w;
        return true;
    }

    bool operator==(const Xoshiro256pp& o) const { return s_ == o.s_; }
    bool operator!=(const Xoshiro256pp& o) const { return s_ != o.s_; }

private:
    static std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }

    std::array<std::uint64_t, 4> s_;
};

//- One seeded generator per cell population (Xoshiro256pp inside).
class Rng {
public:
    using Engine = Xoshiro256pp;

    explicit Rng(std::uint64_t seed) : engine_(seed), zig_(&ziggurat()) {}

    //- Uniform on the open interval (0,1): 53 random bits, centred in their bin. The top
    //  bin's centre, 1 - 2^-54, is not a double and would round to 1: it becomes 1 - 2^-53,
    //  the largest double below 1 (every other bin is exact, so no other draw changes).
    double uniform() { return toUniform(engine_()); }

    //- The uniform() of one engine word
    static double toUniform(std::uint64_t word)
    {
        const double u =
            (static_cast<double>(word >> 11) + 0.5) * (1.0 / 9007199254740992.0);  // 2^-53
        return u < 1.0 ? u : 1.0 - 1.0 / 9007199254740992.0;  // 1 - 2^-53
    }

    //- The uniformIndex(n) of one engine word when that word is not rejected (Lemire's
    //  multiply-high; uniformIndex draws again for the first (2^64 mod n) values of the low
    //  half): a prediction for prefetching, exact except for a rejected word
    static std::uint64_t predictedIndex(std::uint64_t word, std::uint64_t n)
    {
        __extension__ typedef unsigned __int128 uint128;
        return static_cast<std::uint64_t>((static_cast<uint128>(word) * n) >> 64);
    }

    //- Exponentially distributed with the given rate (> 0)
    double exponential(double rate) { return standardExponential() / rate; }

    //- Exp(1) by the ziggurat method (Marsaglia & Tsang, "The ziggurat method for generating
    //  random variables", J. Stat. Softw. 5(8), 2000, its exponential with 256 regions): one
    //  engine word, a table compare and a multiply in 98.9 % of the draws, where -log(u)
    //  took a library logarithm (measured: 61 fewer instructions an SWA event, 82 -> 79 ns
    //  at N = 1e3).
    //  The region is the word's low 8 bits and the abscissa its top 53 (disjoint bits, so
    //  the two are independent, unlike the paper's 32-bit word used for both). The rest, a
    //  wedge or the tail beyond r, goes to exponentialSlow(): exact in law either way.
    double standardExponential()
    {
        const std::uint64_t w = engine_();
        const std::size_t i = w & 255;
        const std::uint64_t m = w >> 11;
        if (m < zig_->k[i]) return static_cast<double>(m) * zig_->w[i];
        return exponentialSlow(i, m);
    }

    //- The ziggurat's tables: region i's abscissa per unit of the 53-bit word (w), the part
    //  of it under the curve for every abscissa (k: accepted at once below it), exp(-x_i) (f)
    struct Ziggurat {
        static constexpr double r = 7.697117470131487;      // the base strip's right end
        static constexpr double v = 3.949659822581572e-3;   // each region's area
        std::uint64_t k[256];
        double w[256];
        double f[256];
    };
    static const Ziggurat& ziggurat();

    //- Uniform on {0, ..., n-1}, unbiased (Lemire, "Fast random integer generation in an
    //  interval", 2019); n must be > 0. Inline: it is drawn in the inner event loops.
    std::uint64_t uniformIndex(std::uint64_t n)
    {
        if (n == 0) throwZeroRange();
        __extension__ typedef unsigned __int128 uint128;
        uint128 m = static_cast<uint128>(engine_()) * n;
        std::uint64_t low = static_cast<std::uint64_t>(m);
        if (low < n) {
            const std::uint64_t threshold = (0 - n) % n;
            while (low < threshold) {
                m = static_cast<uint128>(engine_()) * n;
                low = static_cast<std::uint64_t>(m);
            }
        }
        return static_cast<std::uint64_t>(m >> 64);
    }

    //- Full generator state as text: "xoshiro256++" and the four state words.
    std::string state() const;

    //- Restore a state written by state(); throws std::invalid_argument on bad text.
    void setState(const std::string& s);

    Engine& engine() { return engine_; }

private:
    [[noreturn]] static void throwZeroRange();

    //- standardExponential() past the rectangle of region i (the word's abscissa m)
    double exponentialSlow(std::size_t i, std::uint64_t m);

    Engine engine_;
    const Ziggurat* zig_;  // ziggurat(), held: no guard of its static in the hot path
};

} // namespace coag

#endif
