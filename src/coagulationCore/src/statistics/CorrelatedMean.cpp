// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#include "coagulation/statistics/CorrelatedMean.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace coag {

namespace {
const double nan = std::numeric_limits<double>::quiet_NaN();
const double pi = 3.14159265358979323846;
}

double studentT975(double nu)
{
    nu = std::max(nu, 1.0);
    // Start: the Cornish-Fisher expansion (Abramowitz & Stegun 26.7.5) about z_{0.975}
    const double z = 1.959963984540054;
    const double z2 = z * z, z3 = z2 * z, z5 = z3 * z2, z7 = z5 * z2, z9 = z7 * z2;
    const double g1 = (z3 + z) / 4;
    const double g2 = (5 * z5 + 16 * z3 + 3 * z) / 96;
    const double g3 = (3 * z7 + 19 * z5 + 17 * z3 - 15 * z) / 384;
    const double g4 = (79 * z9 + 776 * z7 + 1482 * z5 - 1920 * z3 - 945 * z) / 92160;
    double t = z + g1 / nu + g2 / (nu * nu) + g3 / (nu * nu * nu) + g4 / (nu * nu * nu * nu);
    if (nu > 1e6) {
        return t;
    }
    // Newton on int_0^t f = 0.475, f the density of t_nu, the integral by Simpson's rule
    const double c = std::exp(std::lgamma(0.5 * (nu + 1)) - std::lgamma(0.5 * nu))
                   / std::sqrt(nu * pi);
    auto f = [&](double x) { return c * std::pow(1 + x * x / nu, -0.5 * (nu + 1)); };
    t = std::min(t, 12.706204736174698 * 1.01);
    for (int it = 0; it < 50; ++it) {
        const int n = 2000;
        const double h = t / n;
        double s = f(0) + f(t);
        for (int i = 1; i < n; ++i) s += (i % 2 ? 4 : 2) * f(i * h);
        const double F = s * h / 3;
        const double step = (F - 0.475) / f(t);
        t -= step;
        if (std::abs(step) < 1e-12 * t) break;
    }
    return t;
}


CorrelatedMean correlatedMean(const std::vector<double>& x, std::size_t minWindow, double c)
{
    CorrelatedMean r;
    const std::size_t N = x.size();
    r.count = N;
    if (N == 0) {
        r.mean = r.sd = r.ci95 = nan;
        return r;
    }
    r.mean = std::accumulate(x.begin(), x.end(), 0.0) / double(N);
    double m2 = 0, amax = 0;
    for (double v : x) {
        m2 += (v - r.mean) * (v - r.mean);
        amax = std::max(amax, std::abs(v));
    }
    r.sd = N > 1 ? std::sqrt(m2 / double(N - 1)) : nan;
    r.neff = double(N);
    if (N < 4) {
        r.ci95 = nan;
        return r;
    }
    const double g0 = m2 / double(N);
    if (!(g0 > 1e-28 * std::max(1e-300, amax) * std::max(1e-300, amax))) {
        r.ci95 = 0;          // a constant series
        return r;
    }
    // autocovariances up to N/4 lags (direct sums: the series are short)
    const std::size_t Mmax = std::max<std::size_t>(N / 4, 1);
    std::vector<double> taus(Mmax + 1, 0.5);   // taus[M] = 1/2 + sum_{t=1}^{M} rho(t)
    double acc = 0.5;
    for (std::size_t t = 1; t <= Mmax; ++t) {
        double s = 0;
        for (std::size_t i = 0; i + t < N; ++i) s += (x[i] - r.mean) * (x[i + t] - r.mean);
        acc += s / double(N) / g0;
        taus[t] = acc;
    }
    std::size_t M = Mmax;
    for (std::size_t t = 1; t <= Mmax; ++t) {
        if (double(t) >= c * taus[t]) {
            M = t;
            break;
        }
    }
    double tau = taus[M];
    const double Nf = double(N);
    const std::size_t Mw = std::min(std::max(M, minWindow), Mmax);
    if (taus[Mw] / (Nf - 2.0 * double(Mw) - 1) > tau / (Nf - 2.0 * double(M) - 1)) {
        M = Mw;
        tau = taus[Mw];
    }
    tau = std::max(tau, 0.5);
    const double varMean =
        std::max(2.0 * tau, 1e-3) * g0 / std::max(Nf - 2.0 * double(M) - 1, 1.0);
    r.tauInt = tau;
    r.window = M;
    r.neff = (m2 / (Nf - 1)) / varMean;
    r.ci95 = studentT975(Nf / (2.0 * double(M) + 1.0)) * std::sqrt(varMean);
    return r;
}

} // namespace coag
