// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_CUBEROOT_HPP
#define COAGULATION_CUBEROOT_HPP

#include <cmath>
#include <cstdint>
#include <cstring>

namespace coag {

//- x^(1/3) for the particle masses the kernels take: the exponent divided by three in the
//  bits (Kahan's starting value, good to about 5 bits), two Halley steps
//  y (y^3 + 2x)/(2 y^3 + x) (each about triples the correct bits) and one Newton step: within
//  3 ulp of std::cbrt, without glibc's frexp and ldexp calls (the kernels take cube roots on
//  every proposed pair; doc/performance.md). Arguments outside [1e-300, 1e300], zero,
//  infinity and NaN included, go to std::cbrt.
inline double cubeRoot(double x)
{
    if (!(x >= 1e-300 && x <= 1e300)) return std::cbrt(x);  // y^3 must not overflow
    std::uint64_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    bits = bits / 3 + (std::uint64_t(0x2A9F7893) << 32);
    double y;
    std::memcpy(&y, &bits, sizeof y);
    double y3 = y * y * y;
    y *= (y3 + 2.0 * x) / (2.0 * y3 + x);
    y3 = y * y * y;
    y *= (y3 + 2.0 * x) / (2.0 * y3 + x);
    return y + (x / (y * y) - y) * (1.0 / 3.0);
}

} // namespace coag

#endif
