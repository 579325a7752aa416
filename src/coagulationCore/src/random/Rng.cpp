// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#include "coagulation/random/Rng.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace coag {

namespace {

//- Marsaglia & Tsang's tables for the exponential, scaled to a 53-bit abscissa: region 0 is
//  the base strip (a rectangle of width q = v e^r and the tail beyond r), regions 1..255 the
//  rectangles under exp(-x) between x_i and x_{i-1}, x_i = -log(v / x_{i+1} + exp(-x_{i+1}))
//  from x_255 = r down, each of area v
Rng::Ziggurat makeZiggurat()
{
    Rng::Ziggurat z{};
    const double m = 9007199254740992.0;  // 2^53
    const double r = Rng::Ziggurat::r, v = Rng::Ziggurat::v;
    const double q = v / std::exp(-r);
    double de = r, te = r;
    z.k[0] = static_cast<std::uint64_t>((de / q) * m);
    z.k[1] = 0;
    z.w[0] = q / m;
    z.w[255] = de / m;
    z.f[0] = 1.0;
    z.f[255] = std::exp(-de);
    for (int i = 254; i >= 1; --i) {
        de = -std::log(v / de + std::exp(-de));
        z.k[i + 1] = static_cast<std::uint64_t>((de / te) * m);
        te = de;
        z.f[i] = std::exp(-de);
        z.w[i] = de / m;
    }
    return z;
}

} // namespace

const Rng::Ziggurat& Rng::ziggurat()
{
    static const Ziggurat z = makeZiggurat();
    return z;
}

double Rng::exponentialSlow(std::size_t i, std::uint64_t m)
{
    const Ziggurat& z = *zig_;
    for (;;) {
        // the tail beyond r: r + Exp(1), the exponential being memoryless
        if (i == 0) return Ziggurat::r - std::log(uniform());
        // the wedge of region i, between its rectangle's core and the curve: x is taken with
        // the chance that a uniform height in [f_i, f_{i-1}] lies under exp(-x)
        const double x = static_cast<double>(m) * z.w[i];
        if (z.f[i] + uniform() * (z.f[i - 1] - z.f[i]) < std::exp(-x)) return x;
        const std::uint64_t w = engine_();
        i = w & 255;
        m = w >> 11;
        if (m < z.k[i]) return static_cast<double>(m) * z.w[i];
    }
}

void Rng::throwZeroRange()
{
    throw std::invalid_argument("coag::Rng::uniformIndex: n must be > 0");
}

std::string Rng::state() const
{
    std::ostringstream os;
    os << "xoshiro256++";
    for (const std::uint64_t w : engine_.words()) os << ' ' << w;
    return os.str();
}

void Rng::setState(const std::string& s)
{
    std::istringstream is(s);
    std::string name;
    std::array<std::uint64_t, 4> w{};
    is >> name >> w[0] >> w[1] >> w[2] >> w[3];
    std::string rest;
    if (is.fail() || name != "xoshiro256++" || (is >> rest) || !engine_.setWords(w)) {
        throw std::invalid_argument("coag::Rng::setState: text is not an xoshiro256++ state "
                                    "(the name and four words, not all zero)");
    }
}

} // namespace coag
