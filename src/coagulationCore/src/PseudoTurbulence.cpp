// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#include "coagulation/PseudoTurbulence.hpp"

#include "coagulation/Dispersion.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace coag {

namespace {

constexpr double twoPi = 6.283185307179586476925286766559;

// SplitMix64 finaliser: the stream's key from the user's seed (neighbouring seeds give
// unrelated streams)
std::uint64_t mixSeed(std::uint64_t s)
{
    std::uint64_t z = s + 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

void cross(const double a[3], const double b[3], double c[3])
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

} // namespace

PseudoTurbulenceParameters PseudoTurbulenceParameters::fromDissipation(
    double epsilon, double nu, double L, int logIntervals, int nPerInterval, double C1)
{
    if (!(epsilon > 0) || !(nu > 0) || !(L > 0)) {
        throw std::invalid_argument("PseudoTurbulence: epsilon, nu and L must be positive");
    }
    PseudoTurbulenceParameters p;
    p.epsilon = epsilon;
    p.k0 = twoPi / L;
    p.kmax = twoPi / std::pow(nu * nu * nu / epsilon, 0.25);
    p.C1 = C1;
    p.logIntervals = logIntervals;
    p.nPerInterval = nPerInterval;
    p.check();
    return p;
}

PseudoTurbulenceParameters PseudoTurbulenceParameters::fromScales(
    double u0, double eta, double L, int logIntervals, int nPerInterval, double C1)
{
    if (!(u0 > 0) || !(eta > 0) || !(L > eta) || !(C1 > 0)) {
        throw std::invalid_argument("PseudoTurbulence: need u0 > 0, 0 < eta < L, C1 > 0");
    }
    PseudoTurbulenceParameters p;
    p.k0 = twoPi / L;
    p.kmax = twoPi / eta;
    p.C1 = C1;
    p.logIntervals = logIntervals;
    p.nPerInterval = nPerInterval;
    // (5.13): u0^2 = C1 epsilon^(2/3) (k0^(-2/3) - kmax^(-2/3))
    const double e23 = u0 * u0 / (C1 * (std::pow(p.k0, -2.0 / 3) - std::pow(p.kmax, -2.0 / 3)));
    p.epsilon = std::pow(e23, 1.5);
    p.check();
    return p;
}

void PseudoTurbulenceParameters::check() const
{
    if (!(k0 > 0) || !(kmax > k0) || !(epsilon > 0) || !(C1 > 0) || logIntervals < 1
        || nPerInterval < 1 || !std::isfinite(kmax) || !std::isfinite(epsilon)) {
        throw std::invalid_argument("PseudoTurbulence: need 0 < k0 < kmax, epsilon > 0, C1 > 0 "
                                    "and at least one interval and one harmonic per interval");
    }
}

double PseudoTurbulenceParameters::energyBetween(double a, double b) const
{
    // int_a^b C1 eps^(2/3) k^(-5/3) dk = 3/2 C1 eps^(2/3) (a^(-2/3) - b^(-2/3))
    return 1.5 * C1 * std::pow(epsilon, 2.0 / 3) * (std::pow(a, -2.0 / 3) - std::pow(b, -2.0 / 3));
}

double PseudoTurbulenceParameters::u0Squared() const
{
    return energyBetween(k0, kmax) / 1.5;   // (5.13)
}

double PseudoTurbulenceParameters::u0() const { return std::sqrt(u0Squared()); }
double PseudoTurbulenceParameters::eta() const { return twoPi / kmax; }
double PseudoTurbulenceParameters::L() const { return twoPi / k0; }

double PseudoTurbulenceParameters::spectrum(double k) const
{
    if (k < k0 || k > kmax) return 0.0;
    return C1 * std::pow(epsilon, 2.0 / 3) * std::pow(k, -5.0 / 3);   // (5.12)
}

PseudoTurbulence::PseudoTurbulence(const PseudoTurbulenceParameters& p, std::uint64_t seed)
    : p_(p)
{
    p_.check();
    const int n0 = p_.logIntervals, n = p_.nPerInterval;
    const std::size_t N = std::size_t(n0) * std::size_t(n);
    for (auto* v : {&k_, &E_, &kx_, &ky_, &kz_, &ax_, &ay_, &az_, &bx_, &by_, &bz_}) v->resize(N);

    CounterStream s(mixSeed(seed));
    const double Q = std::pow(p_.kmax / p_.k0, 1.0 / n0);
    std::size_t j = 0;
    for (int i = 0; i < n0; ++i) {
        // log-scale part [khat_i, khat_(i+1)); the last ends exactly at kmax
        const double lo = p_.k0 * std::pow(Q, i);
        const double hi = (i + 1 == n0) ? p_.kmax : p_.k0 * std::pow(Q, i + 1);
        const double slo = std::pow(lo, -2.0 / 3), shi = std::pow(hi, -2.0 / 3);
        // (5.15): n parts of equal energy, each harmonic carries E_j = energy of the part / n
        const double Ej = p_.energyBetween(lo, hi) / n;
        const double amp = std::sqrt(Ej);
        for (int m = 0; m < n; ++m, ++j) {
            // boundaries of Delta_j in s = k^(-2/3), linear in the energy
            const double s0 = slo + (shi - slo) * m / n;
            const double s1 = slo + (shi - slo) * (m + 1) / n;
            // (5.16): invert the energy within Delta_j
            const double gamma = s.uniform();
            const double kj = std::pow(s0 - gamma * (s0 - s1), -1.5);
            // isotropic unit vector
            const double mu = 2.0 * s.uniform() - 1.0;
            const double phi = twoPi * s.uniform();
            const double rho = std::sqrt(std::max(0.0, 1.0 - mu * mu));
            const double Om[3] = {rho * std::cos(phi), rho * std::sin(phi), mu};
            double xi[3], et[3], a[3], b[3];
            s.normal3(xi);
            s.normal3(et);
            cross(xi, Om, a);
            cross(et, Om, b);
            k_[j] = kj;
            E_[j] = Ej;
            kx_[j] = kj * Om[0];
            ky_[j] = kj * Om[1];
            kz_[j] = kj * Om[2];
            ax_[j] = amp * a[0];
            ay_[j] = amp * a[1];
            az_[j] = amp * a[2];
            bx_[j] = amp * b[0];
            by_[j] = amp * b[1];
            bz_[j] = amp * b[2];
        }
    }
}

void PseudoTurbulence::waveVector(std::size_t j, double k[3]) const
{
    k[0] = kx_[j];
    k[1] = ky_[j];
    k[2] = kz_[j];
}

void PseudoTurbulence::amplitudes(std::size_t j, double a[3], double b[3]) const
{
    a[0] = ax_[j];
    a[1] = ay_[j];
    a[2] = az_[j];
    b[0] = bx_[j];
    b[1] = by_[j];
    b[2] = bz_[j];
}

void PseudoTurbulence::velocity(const double x[3], double u[3]) const
{
    double u0 = 0, u1 = 0, u2 = 0;
    const std::size_t N = k_.size();
    for (std::size_t j = 0; j < N; ++j) {
        const double th = kx_[j] * x[0] + ky_[j] * x[1] + kz_[j] * x[2];
        const double c = std::cos(th), sn = std::sin(th);
        u0 += ax_[j] * c + bx_[j] * sn;
        u1 += ay_[j] * c + by_[j] * sn;
        u2 += az_[j] * c + bz_[j] * sn;
    }
    u[0] = u0;
    u[1] = u1;
    u[2] = u2;
}

void PseudoTurbulence::velocityGradient(const double x[3], double u[3], double grad[3][3]) const
{
    for (int i = 0; i < 3; ++i) {
        u[i] = 0;
        for (int l = 0; l < 3; ++l) grad[i][l] = 0;
    }
    const std::size_t N = k_.size();
    for (std::size_t j = 0; j < N; ++j) {
        const double kv[3] = {kx_[j], ky_[j], kz_[j]};
        const double a[3] = {ax_[j], ay_[j], az_[j]};
        const double b[3] = {bx_[j], by_[j], bz_[j]};
        const double th = kv[0] * x[0] + kv[1] * x[1] + kv[2] * x[2];
        const double c = std::cos(th), sn = std::sin(th);
        for (int i = 0; i < 3; ++i) {
            u[i] += a[i] * c + b[i] * sn;
            const double d = -a[i] * sn + b[i] * c;   // d/dtheta of component i
            for (int l = 0; l < 3; ++l) grad[i][l] += d * kv[l];
        }
    }
}

double PseudoTurbulence::divergence(const double x[3]) const
{
    double u[3], g[3][3];
    velocityGradient(x, u, g);
    return g[0][0] + g[1][1] + g[2][2];
}

void PseudoTurbulence::velocities(std::size_t nPoints, const double* x, const double* y,
                                  const double* z, double* ux, double* uy, double* uz) const
{
    for (std::size_t p = 0; p < nPoints; ++p) ux[p] = uy[p] = uz[p] = 0.0;
    const std::size_t N = k_.size();
    for (std::size_t j = 0; j < N; ++j) {
        const double kx = kx_[j], ky = ky_[j], kz = kz_[j];
        const double ax = ax_[j], ay = ay_[j], az = az_[j];
        const double bx = bx_[j], by = by_[j], bz = bz_[j];
        for (std::size_t p = 0; p < nPoints; ++p) {
            const double th = kx * x[p] + ky * y[p] + kz * z[p];
            const double c = std::cos(th), sn = std::sin(th);
            ux[p] += ax * c + bx * sn;
            uy[p] += ay * c + by * sn;
            uz[p] += az * c + bz * sn;
        }
    }
}

} // namespace coag
