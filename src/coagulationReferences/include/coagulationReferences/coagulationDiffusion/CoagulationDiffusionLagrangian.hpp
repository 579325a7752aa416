// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_COAGULATIONDIFFUSIONLAGRANGIAN_HPP
#define COAGULATION_COAGULATIONDIFFUSIONLAGRANGIAN_HPP

#include "coagulation/kernels/CoagulationKernel.hpp"
#include "coagulation/random/Rng.hpp"
#include "coagulationReferences/smoluchowski/HomogeneousTable.hpp"

#include <Eigen/Dense>

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

//- The stochastic Lagrangian model of coagulation with diffusion (Sabelfeld–Kolodko):
//  trajectories (8) and (16), the direct (15) and adjoint (16)–(17) Monte Carlo estimators of
//  I_h(Omega, t) = int_Omega n^L(t, x) h(x) dx for monodisperse data n0_l(x) = delta_1l f(x)
//  (14), reusing one solve of the normalised homogeneous problem (18), and the effective source
//  F (20) with its bound F_R (22)–(23). Equation numbers are the paper's (see
//  ../shared/papers/README.md for the restatement).
namespace coag {

//- An axis-parallel box [lo, hi] in dim = 1, 2 or 3 dimensions.
struct Box {
    int dim = 2;
    std::array<double, 3> lo{{0, 0, 0}};
    std::array<double, 3> hi{{0, 0, 0}};

    //- The cube/square [-R, R]^dim centred at c (c = nullptr: the origin).
    static Box centred(int dim, double R, const double* c = nullptr);
    double volume() const;
    bool contains(const double* x) const;
    //- A point uniform in the box (dim uniforms).
    void uniform(Rng& rng, double* x) const;
};

//- Standard normals from an Rng by Box–Muller (coag::boxMuller): two uniforms give two normals, the second is
//  kept for the next call (the stream is a pure function of the seed).
class NormalSource {
public:
    explicit NormalSource(std::uint64_t seed) : rng_(seed) {}
    double normal();
    Rng& rng() { return rng_; }

private:
    Rng rng_;
    bool have_ = false;
    double spare_ = 0.0;
};

//- The table of u(tau) of the normalised homogeneous problem (18), du/dtau = K(u),
//  u_l(0) = delta_1l, solved ONCE on [0, tauMax] (sizes 1..maxSize, clusters beyond lost) and
//  kept for sizes 1..storedSizes on the graded mesh tau_k = tauMax (k/intervals)^2: the
//  kernel scaling of the one HomogeneousTable (smoluchowski/HomogeneousTable.hpp). With
//  monodisperse data n0_l = delta_1l f, the homogeneous solution from n0 is
//  rho_l(t; n0) = f u_l(f t) (after (18)): HomogeneousTable::solution(f, t, out).
HomogeneousTable table18(const CoagulationKernel& kernel, std::size_t maxSize, double tauMax,
                         std::size_t storedSizes, std::size_t intervals = 1000);

//- The diffusion process (8) dX = v(t, X) dt + sqrt(2D) dW in dim dimensions. v empty: v = 0,
//  and every path is one exact Gaussian step (variance 2 D t per coordinate, (19)). Otherwise
//  steps of at most dt with the stochastic Heun scheme (default; strong order 1 for this
//  additive noise, weak order 2) or Euler–Maruyama (strong order 1 for additive noise too).
//  Backward trajectories (16) use v* = v - (2D/mu) grad mu when mu and gradMu are given, else
//  v* = v (mu = 1, valid for div v = 0).
struct DiffusionProcess {
    using Field = std::function<void(double t, const double* x, double* out)>;
    int dim = 2;
    double D = 0.0;
    Field velocity;  // v(t, x); empty: v = 0
    enum class Scheme { EulerMaruyama, Heun } scheme = Scheme::Heun;
    double dt = 1e-2;
    std::function<double(double t, const double* x)> mu;  // optional, > 0
    Field gradMu;                                          // grad mu, with mu

    //- Forward path (8) from x at time t0 to time t1 >= t0 (x overwritten).
    void forward(double t0, double t1, double* x, NormalSource& g) const;
    //- Backward path (16) from X*(t) = x down to tau = 0 (x overwritten with X*(0)).
    void backward(double t, double* x, NormalSource& g) const;
    //- v*(t, x) = v - (2D/mu) grad mu (16).
    void adjointVelocity(double t, const double* x, double* out) const;
    //- mu(t, x) (1 without mu).
    double density(double t, const double* x) const { return mu ? mu(t, x) : 1.0; }
};

//- A sampling density on a box: draw and pdf. Empty: uniform on the box (the default).
struct Density {
    std::function<void(Rng& rng, double* x)> draw;
    std::function<double(const double* x)> pdf;
};

//- Monodisperse data (14): n0_l(x) = delta_1l f(x) on the box `support`, zero outside;
//  f empty: f = n0 (uniform).
struct MonodisperseData {
    Box support;
    double n0 = 1.0;
    std::function<double(const double* x)> f;
    double value(const double* x) const;
};

//- Per-size means and 95 % half-widths 1.96 s / sqrt(N) over N independent samples (every
//  sample has its own trajectory and its own random numbers, so the iid interval is correct).
struct Estimate {
    std::vector<double> mean, halfWidth;
    std::size_t samples = 0;
    double lower(std::size_t l) const { return mean[l - 1] - halfWidth[l - 1]; }
    double upper(std::size_t l) const { return mean[l - 1] + halfWidth[l - 1]; }
    bool covers(std::size_t l, double value) const
    {
        return value >= lower(l) && value <= upper(l);
    }
};

//- The effective source (20) with its 95 % interval (batch means, below).
struct EffectiveSource {
    double F = 0.0;
    double halfWidth = 0.0;
    std::size_t samples = 0;
};

class LagrangianEstimator {
public:
    //- Keeps a reference to the table (which must outlive the estimator) and copies the
    //  process and the data. The table must cover tau up to t sup f for every t asked
    //  (checked per sample: std::out_of_range).
    LagrangianEstimator(const HomogeneousTable& table, const DiffusionProcess& process,
                        const MonodisperseData& data);

    //- Direct estimator (15) of I_h(Omega, t), sizes 1..table.sizes(): xi drawn in the support
    //  with density r, X(t) by (8), score h(X(t))/r(xi) rho(t; n0(xi)) if X(t) in Omega.
    //  h empty: h = 1.
    Estimate direct(double t, const Box& omega, std::size_t N, std::uint64_t seed,
                    const std::function<double(const double*)>& h = {},
                    const Density& r = {}) const;
    //- Adjoint estimator (16)–(17): xi drawn in Omega with density s, the backward path to
    //  x0 = X*(0), score h(xi)/s(xi) mu(t, xi)/mu(0, x0) rho(t; n0(x0)) if x0 in the support.
    Estimate adjoint(double t, const Box& omega, std::size_t N, std::uint64_t seed,
                     const std::function<double(const double*)>& h = {},
                     const Density& s = {}) const;
    //- The adjoint estimator with s the point mass at x: n^L_l(t, x) itself (9).
    Estimate adjointPoint(double t, const double* x, std::size_t N, std::uint64_t seed) const;

    //- F(t, x) (20) for v = 0: xi Gaussian with mean x and variance 2Dt per coordinate,
    //  F = sum_{i,j <= sizes} K_ij |E[rho_i rho_j] - E[rho_i] E[rho_j]|. The N samples are cut
    //  into 25 batches; each batch gives F_b from its unbiased covariances (1/(n-1)), F is their
    //  mean and the 95 % interval t_24 sd(F_b)/sqrt(25) (batch means: no linearisation, which
    //  degenerates where P(1 - P) is stationary, P = 1/2 for uniform data). F_b is unbiased
    //  unless some covariance is near 0 relative to its error (|.| then biases it up).
    //  Throws std::logic_error if the process has a velocity, invalid_argument for N < 50.
    EffectiveSource effectiveSource(double t, const double* x, std::size_t N,
                                    std::uint64_t seed) const;

    const HomogeneousTable& table() const { return table_; }

private:
    void scoreRho(double f, double t, double weight, std::vector<double>& buf) const;

    const HomogeneousTable& table_;
    DiffusionProcess process_;
    MonodisperseData data_;
};

//- int_G p(x, t; x0) dx0 for v = 0 and G = [-R, R]^dim: prod_i f_i(t, x_i) (23),
//  f_i = 1/2 [erf((R - x_i)/(sigma sqrt 2)) + erf((R + x_i)/(sigma sqrt 2))], sigma = sqrt(2Dt).
double gaussianBoxMass(int dim, double R, double D, double t, const double* x);

//- F_R(t, x) = 3/2 n0^2 C P (1 - P), P the mass (23) (22).
double effectiveSourceBound(int dim, double n0, double C, double R, double D, double t,
                            const double* x);

//- The smallest C with K_ij <= C i j for i, j = 1..L (the constant of (2)).
double kernelBoundConstant(const CoagulationKernel& kernel, std::size_t L);

namespace exact {
//- Pure diffusion with constant velocity v (v = nullptr: 0) of uniform data n0 on the box
//  `support`: int_Omega n(t, x) dx = n0 prod_i int_{omega_i} int_{support_i} phi_sigma(x - y -
//  v_i t) dy dx with sigma^2 = 2Dt (the Gaussian integral of (19), (23)), in closed form by the
//  antiderivative z Phi(z/sigma) + sigma phi(z/sigma) of Phi(z/sigma).
double diffusedBoxIntegral(double n0, const Box& support, const Box& omega, double D, double t,
                           const double* v = nullptr);
//- The same density at a point x: n0 prod_i f_i with the box's own half-widths (23).
double diffusedBoxDensity(double n0, const Box& support, double D, double t, const double* x,
                          const double* v = nullptr);
} // namespace exact

} // namespace coag

#endif
