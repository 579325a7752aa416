// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#include "coagulationReferences/pseudoTurbulence/PseudoTurbulence.hpp"

#include "coagulation/random/CounterStream.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace coag {

namespace {

constexpr double twoPi = 6.283185307179586476925286766559;

void cross(const double a[3], const double b[3], double c[3])
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

} // namespace

void sinCosBatch(std::size_t n, const double* theta, double* sinOut, double* cosOut)
{
    // Cody-Waite: z = theta - q pi/2 with pi/2 in three parts (Cephes' DP1..DP3, doubled;
    // the first two have 23 and 21 significant bits, so q * part is exact for q < 2^30),
    // |z| <= pi/4; then Cephes' minimax polynomials for sin and cos on [-pi/4, pi/4] and the
    // quadrant q mod 4 by bit masks: no branch and no libm call, so the loop vectorises.
    constexpr double P1 = 2 * 7.85398125648498535156E-1, P2 = 2 * 3.77489470793079817668E-8,
                     P3 = 2 * 2.69515142907905952645E-15;
    constexpr double twoOverPi = 0.63661977236758134308;
    constexpr double magic = 6755399441055744.0;   // 1.5 * 2^52: adding it rounds to an integer
    for (std::size_t i = 0; i < n; ++i) {
        const double t = theta[i];
        const double qm = t * twoOverPi + magic;
        const double q = qm - magic;
        std::uint64_t qi;
        std::memcpy(&qi, &qm, sizeof qi);   // the low bits of qm's mantissa hold q (mod 2^51)
        const double z = ((t - q * P1) - q * P2) - q * P3;
        const double zz = z * z;
        const double sp = z + z * zz *
            (((((1.58962301576546568060E-10 * zz - 2.50507477628578072866E-8) * zz
                + 2.75573136213857245213E-6) * zz - 1.98412698295895385996E-4) * zz
              + 8.33333333332211858878E-3) * zz - 1.66666666666666307295E-1);
        const double cp = 1.0 - 0.5 * zz + zz * zz *
            (((((-1.13585365213876817300E-11 * zz + 2.08757008419747316778E-9) * zz
                - 2.75573141792967388112E-7) * zz + 2.48015872888517045348E-5) * zz
              - 1.38888888888730564116E-3) * zz + 4.16666666666665929218E-2);
        // quadrant 0: (s, c), 1: (c, -s), 2: (-s, -c), 3: (-c, s): the swap and the signs
        // as 64-bit masks (integer and/or/xor only: SSE2 has no 64-bit compare)
        std::uint64_t sb, cb;
        std::memcpy(&sb, &sp, sizeof sb);
        std::memcpy(&cb, &cp, sizeof cb);
        const std::uint64_t odd = 0 - (qi & 1);   // all ones in odd quadrants
        const std::uint64_t sr = (cb & odd) | (sb & ~odd), cr = (sb & odd) | (cb & ~odd);
        const std::uint64_t so = sr ^ ((qi & 2) << 62), co = cr ^ (((qi + 1) & 2) << 62);
        std::memcpy(&sinOut[i], &so, sizeof so);
        std::memcpy(&cosOut[i], &co, sizeof co);
    }
    for (std::size_t i = 0; i < n; ++i) {
        if (!(std::abs(theta[i]) < limitSinCosBatch)) {   // rare: out of range or not finite
            sinOut[i] = std::sin(theta[i]);
            cosOut[i] = std::cos(theta[i]);
        }
    }
}

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

    CounterStream s(mix64(seed));
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
    // phases of a chunk of harmonics, their sin/cos as one vector batch, then the sums
    constexpr std::size_t chunk = 256;
    double th[chunk], sn[chunk], cs[chunk];
    double u0 = 0, u1 = 0, u2 = 0;
    const std::size_t N = k_.size();
    for (std::size_t j0 = 0; j0 < N; j0 += chunk) {
        const std::size_t m = std::min(chunk, N - j0);
        for (std::size_t j = 0; j < m; ++j)
            th[j] = kx_[j0 + j] * x[0] + ky_[j0 + j] * x[1] + kz_[j0 + j] * x[2];
        sinCosBatch(m, th, sn, cs);
        for (std::size_t j = 0; j < m; ++j) {
            u0 += ax_[j0 + j] * cs[j] + bx_[j0 + j] * sn[j];
            u1 += ay_[j0 + j] * cs[j] + by_[j0 + j] * sn[j];
            u2 += az_[j0 + j] * cs[j] + bz_[j0 + j] * sn[j];
        }
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
    constexpr std::size_t chunk = 256;
    double th[chunk], sn[chunk], cs[chunk];
    const std::size_t N = k_.size();
    for (std::size_t j0 = 0; j0 < N; j0 += chunk) {
        const std::size_t m = std::min(chunk, N - j0);
        for (std::size_t j = 0; j < m; ++j)
            th[j] = kx_[j0 + j] * x[0] + ky_[j0 + j] * x[1] + kz_[j0 + j] * x[2];
        sinCosBatch(m, th, sn, cs);
        for (std::size_t jj = 0; jj < m; ++jj) {
            const std::size_t j = j0 + jj;
            const double kv[3] = {kx_[j], ky_[j], kz_[j]};
            const double a[3] = {ax_[j], ay_[j], az_[j]};
            const double b[3] = {bx_[j], by_[j], bz_[j]};
            const double c = cs[jj], sv = sn[jj];
            for (int i = 0; i < 3; ++i) {
                u[i] += a[i] * c + b[i] * sv;
                const double d = -a[i] * sv + b[i] * c;   // d/dtheta of component i
                for (int l = 0; l < 3; ++l) grad[i][l] += d * kv[l];
            }
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
    // points in chunks that stay in L1 with their phases, sines and cosines
    constexpr std::size_t chunk = 256;
    double th[chunk], sn[chunk], cs[chunk];
    for (std::size_t p0 = 0; p0 < nPoints; p0 += chunk) {
        const std::size_t m = std::min(chunk, nPoints - p0);
        const double *xc = x + p0, *yc = y + p0, *zc = z + p0;
        double *uxc = ux + p0, *uyc = uy + p0, *uzc = uz + p0;
        for (std::size_t j = 0; j < N; ++j) {
            const double kx = kx_[j], ky = ky_[j], kz = kz_[j];
            const double ax = ax_[j], ay = ay_[j], az = az_[j];
            const double bx = bx_[j], by = by_[j], bz = bz_[j];
            for (std::size_t p = 0; p < m; ++p) th[p] = kx * xc[p] + ky * yc[p] + kz * zc[p];
            sinCosBatch(m, th, sn, cs);
            for (std::size_t p = 0; p < m; ++p) {
                uxc[p] += ax * cs[p] + bx * sn[p];
                uyc[p] += ay * cs[p] + by * sn[p];
                uzc[p] += az * cs[p] + bz * sn[p];
            }
        }
    }
}

} // namespace coag
