// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_RNG_HPP
#define COAGULATION_RNG_HPP

#include <cmath>
#include <cstdint>
#include <random>
#include <string>

namespace coag {

//- One seeded generator per cell population (std::mt19937_64 inside).
class Rng {
public:
    explicit Rng(std::uint64_t seed) : engine_(seed) {}

    //- Uniform on the open interval (0,1): 53 random bits, centred in their bin. The top
    //  bin's centre, 1 - 2^-54, is not a double and would round to 1: it becomes 1 - 2^-53,
    //  the largest double below 1 (every other bin is exact, so no other draw changes).
    double uniform()
    {
        const double u =
            (static_cast<double>(engine_() >> 11) + 0.5) * (1.0 / 9007199254740992.0);  // 2^-53
        return u < 1.0 ? u : 1.0 - 1.0 / 9007199254740992.0;  // 1 - 2^-53
    }

    //- Exponentially distributed with the given rate (> 0).
    double exponential(double rate) { return -std::log(uniform()) / rate; }

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

    //- Full generator state as text (std::mt19937_64 stream format).
    std::string state() const;

    //- Restore a state written by state(); throws std::invalid_argument on bad text.
    void setState(const std::string& s);

    std::mt19937_64& engine() { return engine_; }

private:
    [[noreturn]] static void throwZeroRange();

    std::mt19937_64 engine_;
};

} // namespace coag

#endif
