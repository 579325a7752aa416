// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_PSEUDOTURBULENCE_HPP
#define COAGULATION_PSEUDOTURBULENCE_HPP

#include <cstddef>
#include <cstdint>
#include <vector>

namespace coag {

//- The randomized spectral model of Kolmogorov pseudo-turbulence of Kolodko, Sabelfeld and
//  Wagner (shared/papers/kolodko-sabelfeld-wagner_stochastic-smoluchowski-lagrangian.md,
//  §5.2, eqs 5.11-5.16), with the log-scale refinement the paper describes after (5.16).
//
//  Statistics (what a sample of the field reproduces in expectation):
//    (5.11)  Psi_jl(k) = E(k)/(4 pi k^2) (delta_jl - k_j k_l / k^2): isotropic, solenoidal.
//    (5.12)  E(k) = C1 epsilon^(2/3) k^(-5/3) on [k0, kmax], 0 outside; C1 = 1.4.
//    (5.13)  int E dk = 3/2 u0^2, i.e. u0^2 = C1 epsilon^(2/3) (k0^(-2/3) - kmax^(-2/3)),
//            and <|U|^2> = 3 u0^2.
//  Scales (the paper's convention, stated after 5.13): eta = 2 pi / kmax, L = 2 pi / k0, so
//  k0 = 2 pi / L and kmax = 2 pi / eta (not 1/L and 1/eta); model Reynolds number
//  Re^ = (kmax/k0)^(4/3). From (epsilon, nu, L): eta = (nu^3/epsilon)^(1/4), the Kolmogorov
//  scale (the paper normalises lengths by it, x' = x/eta, L' = L/eta); from (u0, eta, L):
//  epsilon from (5.13).
//
//  Simulation formula (5.14), one sample of the field:
//    U(x) = sum_j sqrt(E_j) [ (xi_j x Omega_j) cos(theta_j) + (eta_j x Omega_j) sin(theta_j) ],
//    theta_j = k_j (Omega_j . x),
//  Omega_j independent isotropic unit vectors, xi_j and eta_j independent standard Gaussian
//  3-vectors, k_j drawn on the interval Delta_j with density E(k)/E_j, E_j = int_Delta_j E dk.
//  The amplitudes a_j = sqrt(E_j) xi_j x Omega_j and b_j = sqrt(E_j) eta_j x Omega_j are
//  orthogonal to the wave vector k_j Omega_j, so div U = sum_j k_j Omega_j . (-a_j sin + b_j cos)
//  is zero up to the round-off of the cross products (relative to sum_j k_j (|a_j| + |b_j|)).
//  Each harmonic contributes <|.|^2> = 2 E_j (|xi x Omega|^2 has mean 2), so
//  <|U|^2> = 2 sum E_j = 3 u0^2 by (5.13).
//  The model is frozen: theta_j has no time in it (the paper writes U_E(x, t) but its phase
//  is k_j (Omega_j, x) only), so U depends on x alone; a new sample is a new seed.
//
//  Partition (5.15): Delta = [k0, kmax) is cut into nPerInterval intervals of equal energy,
//    ktilde_(j+1) = [ k0^(-2/3) (1 - j/n) + (j/n) kmax^(-2/3) ]^(-3/2),
//  and k_j is drawn by inverting the energy within Delta_j (5.16):
//    k_j = [ ktilde_j^(-2/3) - gamma_j u0^2 / (n C1 epsilon^(2/3)) ]^(-3/2),
//  gamma_j uniform on (0,1). (The extracted text shows gamma_j in the denominator; the inverse
//  of the energy within Delta_j has it as a factor, as written here, and
//  u0^2 / (n C1 epsilon^(2/3)) = ktilde_j^(-2/3) - ktilde_(j+1)^(-2/3).)
//  Log-scale refinement (the paper's version of [10], after 5.16): [k0, kmax) is first cut
//  into n0 = logIntervals parts [khat_i, khat_(i+1)), khat_i = k0 Q^i, Q = (kmax/k0)^(1/n0);
//  each part is then partitioned as in (5.15) into nPerInterval harmonics of equal energy
//  (energy of the part / nPerInterval; the parts' energies differ). n0 = 1 is (5.15) itself.
//  Harmonics: n0 * nPerInterval.
//
//  Random numbers: one CounterStream (Dispersion.hpp) keyed by the seed (mixed), drawn per
//  harmonic in the order gamma, Omega (2 uniforms), xi (normal3: 4 draws), eta (4 draws); a
//  field is a pure function of (parameters, seed).
struct PseudoTurbulenceParameters {
    double epsilon = 1.0;     //- mean dissipation rate epsilon-bar [m^2/s^3]
    double k0 = 1.0;          //- smallest wave number 2 pi / L [1/m]
    double kmax = 1000.0;     //- largest wave number 2 pi / eta [1/m]
    double C1 = 1.4;          //- Kolmogorov-Obukhov constant of (5.12)
    int logIntervals = 1;     //- n0: log-uniform parts of [k0, kmax) (1: eq. 5.15 alone)
    int nPerInterval = 16;    //- n: energy-uniform harmonics per part (5.15)

    //- From epsilon-bar, nu and the integral scale L: eta = (nu^3/epsilon)^(1/4),
    //  kmax = 2 pi / eta, k0 = 2 pi / L.
    static PseudoTurbulenceParameters fromDissipation(double epsilon, double nu, double L,
                                                      int logIntervals, int nPerInterval,
                                                      double C1 = 1.4);
    //- From u0 (the rms of one component), eta and L: k0 = 2 pi / L, kmax = 2 pi / eta,
    //  epsilon from (5.13).
    static PseudoTurbulenceParameters fromScales(double u0, double eta, double L,
                                                 int logIntervals, int nPerInterval,
                                                 double C1 = 1.4);

    //- u0^2 = C1 epsilon^(2/3) (k0^(-2/3) - kmax^(-2/3)), eq. (5.13)
    double u0Squared() const;
    double u0() const;
    double eta() const;          //- 2 pi / kmax
    double L() const;            //- 2 pi / k0
    //- E(k), eq. (5.12)
    double spectrum(double k) const;
    //- int_a^b E(k) dk for k0 <= a <= b <= kmax
    double energyBetween(double a, double b) const;
    //- Throws std::invalid_argument unless 0 < k0 < kmax, epsilon > 0, C1 > 0, counts >= 1.
    void check() const;
};

//- sin and cos of n phases, written to vectorise (no libm call, no branch in the loop): the
//  batch evaluation's kernel. Agrees with std::sin/std::cos to about 1e-16 absolute for
//  |theta| < limitSinCosBatch (measured in the tests); larger or non-finite phases are handed
//  to std::sin/std::cos.
//  (|theta| < 6.7e7: q = round(theta 2/pi) < 2^25.4, and q times the first two parts of pi/2,
//  23 and 21 significant bits, is exact in a double.)
constexpr double limitSinCosBatch = 6.7e7;
void sinCosBatch(std::size_t n, const double* theta, double* sinOut, double* cosOut);

//- One sample of the field (5.14): see PseudoTurbulenceParameters.
class PseudoTurbulence {
public:
    PseudoTurbulence(const PseudoTurbulenceParameters& p, std::uint64_t seed);

    const PseudoTurbulenceParameters& parameters() const { return p_; }
    std::size_t harmonics() const { return k_.size(); }
    //- k_j, E_j, the wave vector k_j Omega_j and the amplitudes a_j, b_j of harmonic j
    double wavenumber(std::size_t j) const { return k_[j]; }
    double energy(std::size_t j) const { return E_[j]; }
    void waveVector(std::size_t j, double k[3]) const;
    void amplitudes(std::size_t j, double a[3], double b[3]) const;

    //- U(x), eq. (5.14)
    void velocity(const double x[3], double u[3]) const;
    //- U(x) and its gradient grad[i][l] = dU_i/dx_l (analytic:
    //  sum_j kvec_j,l (-a_j,i sin theta_j + b_j,i cos theta_j))
    void velocityGradient(const double x[3], double u[3], double grad[3][3]) const;
    //- div U(x) (the trace of the analytic gradient)
    double divergence(const double x[3]) const;
    //- U at nPoints points given as separate coordinate arrays (structure of arrays); the
    //  points go in chunks of 256, and per chunk the harmonic loop is outside and the point
    //  loops inside, on contiguous arrays with the harmonic's constants in registers: phases,
    //  sinCosBatch, accumulation, each a loop that vectorises. The results are overwritten.
    void velocities(std::size_t nPoints, const double* x, const double* y, const double* z,
                    double* ux, double* uy, double* uz) const;

private:
    PseudoTurbulenceParameters p_;
    // structure of arrays, one entry per harmonic
    std::vector<double> k_, E_;
    std::vector<double> kx_, ky_, kz_;   // k_j Omega_j
    std::vector<double> ax_, ay_, az_;   // sqrt(E_j) xi_j x Omega_j
    std::vector<double> bx_, by_, bz_;   // sqrt(E_j) eta_j x Omega_j
};

} // namespace coag

#endif
