// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#include "coagulationReferences/smoluchowski/ExactSolutions.hpp"

#include <cmath>
#include <stdexcept>

namespace coag::exact {

namespace {

void checkIndex(std::size_t k)
{
    if (k < 1) throw std::invalid_argument("coag::exact: size index k must be >= 1");
}

} // namespace

double constantKernelDensity(double K0, double N0, double t, std::size_t k)
{
    checkIndex(k);
    const double tau = 0.5 * K0 * N0 * t;
    const double kd = static_cast<double>(k);
    return N0 * std::pow(tau, kd - 1.0) / std::pow(1.0 + tau, kd + 1.0);
}

std::array<double, 4> constantKernelMoments(double K0, double N0, double t)
{
    const double T = K0 * N0 * t;
    return {N0 / (1.0 + 0.5 * T), N0, N0 * (1.0 + T), N0 * (1.0 + 3.0 * T + 1.5 * T * T)};
}

std::array<double, 4> constantKernelLinearGrowthMoments(double K0, double N0, double sigma,
                                                        double t)
{
    const std::array<double, 4> m = constantKernelMoments(K0, N0, t);
    const double e = std::exp(sigma * t);
    return {m[0], m[1] * e, m[2] * e * e, m[3] * e * e * e};
}

std::array<double, 2> constantKernelConstantGrowthMoments(double K0, double N0, double g,
                                                          double t)
{
    const double T = K0 * N0 * t;
    return {N0 / (1.0 + 0.5 * T), N0 + 2.0 * g / K0 * std::log1p(0.5 * T)};
}

double additiveKernelDensity(double K0, double N0, double t, std::size_t k)
{
    checkIndex(k);
    const double s = -std::expm1(-K0 * N0 * t);
    if (k == 1) return N0 * (1.0 - s) * std::exp(-s);
    if (s <= 0.0) return 0.0;
    const double kd = static_cast<double>(k);
    const double logv = std::log(N0) + std::log1p(-s) + (kd - 1.0) * std::log(kd * s) - kd * s
                        - std::lgamma(kd + 1.0);
    return std::exp(logv);
}

std::array<double, 4> additiveKernelMoments(double K0, double N0, double t)
{
    const double e = std::exp(K0 * N0 * t);
    return {N0 / e, N0, N0 * e * e, N0 * e * e * e * (3.0 * e - 2.0)};
}

double multiplicativeKernelDensity(double K0, double N0, double t, std::size_t k)
{
    checkIndex(k);
    const double T = K0 * N0 * t;
    if (!(T < 1.0)) {
        throw std::domain_error("coag::exact::multiplicativeKernelDensity: t is at or after "
                                "gelation (K0 N0 t >= 1)");
    }
    if (k == 1) return N0 * std::exp(-T);
    if (T <= 0.0) return 0.0;
    const double kd = static_cast<double>(k);
    const double logv = std::log(N0) + (kd - 2.0) * std::log(kd) + (kd - 1.0) * std::log(T)
                        - kd * T - std::lgamma(kd + 1.0);
    return std::exp(logv);
}

std::array<double, 4> multiplicativeKernelMoments(double K0, double N0, double t)
{
    const double T = K0 * N0 * t;
    if (!(T < 1.0)) {
        throw std::domain_error("coag::exact::multiplicativeKernelMoments: t is at or after "
                                "gelation (K0 N0 t >= 1)");
    }
    const double g = 1.0 / (1.0 - T);
    return {N0 * (1.0 - 0.5 * T), N0, N0 * g, N0 * g * g * g};
}

std::array<double, 4> constantKernelSourceMoments(double K0, double I, double t)
{
    const double t3 = t * t * t;
    return {std::sqrt(2.0 * I / K0) * std::tanh(t * std::sqrt(0.5 * I * K0)), I * t,
            I * t + K0 * I * I * t3 / 3.0,
            I * t + K0 * I * I * t3 + K0 * K0 * I * I * I * t3 * t * t / 5.0};
}

} // namespace coag::exact
