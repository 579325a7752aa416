// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_LAGRANGIANCOAGULATION_HPP
#define COAGULATION_LAGRANGIANCOAGULATION_HPP

#include "coagulationReferences/smoluchowski/HomogeneousTable.hpp"
#include "coagulationReferences/pseudoTurbulence/Trajectory.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

//- The Lagrangian (trajectory) representation of the inhomogeneous Smoluchowski equation in an
//  incompressible flow (Kolodko, Sabelfeld and Wagner §3-5): the solution at (t, x) is the
//  homogeneous solution started from the source at the trajectory's origin,
//      n^E(t, x) = Phi(S^I(X*(t, x)); t)                                            (3.3), (4.3)
//  and for monomer sources, by (2.33), with one table of the normalised problem (2.32):
//      n^E_l(t, x) = S^I(x0) f_l(S^I(x0) K_11 t),  x0 = X*(t, x)                          (4.4)
//  Units here: densities in units of a reference density S, so s0 = S^I(x0)/S is
//  dimensionless, and `rate` = S K_11 in inverse time units: the table is read at the scaled
//  time rate * s0 * t. The paper's §5 writes f_l(beta t') in (5.17)-(5.25) with t' = t / tau_eta,
//  i.e. rate = beta = V_1 S in Kolmogorov time units (so the tutorials use rate = beta).
namespace coag {

//- A ball {|x - centre| <= radius}: the source support D and the domains Omega_r of §5.1.
struct Sphere {
    std::array<double, 3> centre{{0.0, 0.0, 0.0}};
    double radius = 1.0;
    double volume() const;
    bool contains(const double x[3]) const;
    //- A point uniform in the ball (radius * u^(1/3), isotropic direction): 3 uniforms.
    template <class Stream>
    void sample(Stream& rng, double x[3]) const;
};

//- The initial conditions (5.4) in units of S, supported in the ball D (centre c, radius R):
//  uniform S^I = S, linear S^I = (1 - |x - c|/R) S; 0 outside D.
struct InitialSource {
    enum class Profile { Uniform, Linear };
    Profile profile = Profile::Uniform;
    Sphere D;
    double value(const double x[3]) const;
};

//- The scores of one trajectory: n_l (l = 1..nSizes), sum over all tabulated sizes and
//  sum_l l n_l of the homogeneous solution from the trajectory's origin (4.4).
struct Score {
    std::vector<double> sizes;
    double total = 0.0;
    double mass = 0.0;
};

//- The homogeneous solution Phi(S^I(x0); t) of (3.7), (4.4) read from the table.
class LagrangianSolution {
public:
    LagrangianSolution(const HomogeneousTable& table, const InitialSource& source,
                       double rate, std::size_t nSizes);
    const InitialSource& source() const { return source_; }
    std::size_t nSizes() const { return nSizes_; }
    double rate() const { return rate_; }
    const HomogeneousTable& table() const { return table_; }
    //- n(t) started from n_1 = s0, n_l = 0 (l >= 2): s0 f_l(s0 * rate * t)   (2.33), (4.4)
    void homogeneous(double s0, double t, Score& out) const;
    //- the same with s0 = S^I(x0)
    void fromOrigin(const double x0[3], double t, Score& out) const;

private:
    const HomogeneousTable& table_;
    InitialSource source_;
    double rate_;
    std::size_t nSizes_;
};

//- Adjoint algorithm at a point (4.2)-(4.4): the backward trajectory from x, then the
//  homogeneous solution from its origin.
Score adjointPoint(const VelocityField& v, const TrajectoryOptions& o, const LagrangianSolution& sol,
                   double t, const double x[3]);

//- A Monte Carlo estimate of the integrals over a domain of n_l (l = 1..nSizes), sum_l n_l and
//  sum_l l n_l: the means of the scores and their standard errors (sample sd / sqrt(N)).
struct IntegralEstimate {
    std::vector<double> sizes, sizesSe;
    double total = 0.0, totalSe = 0.0;
    double mass = 0.0, massSe = 0.0;
    std::size_t samples = 0;
    std::size_t hits = 0;   //- samples with a nonzero score
};

//- Adjoint estimator of int_Omega n^E(t, x) dx (§4.2, after (4.4)): xi uniform in Omega
//  (density 1/|Omega|), score |Omega| n^E(t, xi) with n^E from the backward trajectory. Random
//  numbers: CounterStream(seed).
IntegralEstimate adjointIntegral(const VelocityField& v, const TrajectoryOptions& o,
                                 const LagrangianSolution& sol, double t, const Sphere& omega,
                                 std::size_t nPoints, std::uint64_t seed);

//- Direct estimator of int_Omega n^E(t, x) dx for several domains at once (Proposition 3.1,
//  (3.14)): x0 uniform in D, the forward trajectory X(t, x0), score
//  |D| Phi(S^I(x0); t) chi(X(t, x0) in Omega_k) for every domain k (one set of trajectories).
std::vector<IntegralEstimate> directIntegrals(const VelocityField& v, const TrajectoryOptions& o,
                                              const LagrangianSolution& sol, double t,
                                              const std::vector<Sphere>& omegas,
                                              std::size_t nPoints, std::uint64_t seed);

//- The point-source algorithm (§4.1): a source at x* emitting monomers at the rate
//  (density) S^P(t) (in units of S); the trajectory (4.1) from x* on the mesh tau_i = i T/M,
//  and at each x_i = X(tau_i, x*)
//      n_l(T, x_i) = S^P(T - tau_i) f_l(S^P(T - tau_i) * rate * tau_i)         (3.12), §4.1
//  (clusters emitted at T - tau_i that have coagulated for tau_i). `rate` as in
//  LagrangianSolution (S K_11).
struct PointSourceSample {
    double tau = 0.0;
    std::array<double, 3> x{{0.0, 0.0, 0.0}};
    Score n;
};
std::vector<PointSourceSample> pointSource(const VelocityField& v, const TrajectoryOptions& o,
                                           const HomogeneousTable& table, double rate,
                                           std::size_t nSizes, const double xStar[3], double T,
                                           const std::function<double(double)>& SP);

//- The functionals (5.5)-(5.8) of one set of integrals over Omega_r:
//  In_l = int n_l, In = int sum n_l, Ms = int sum l n_l / In, Sp_l = In_l / In.
struct SphereFunctionals {
    double In = 0.0, Ms = 0.0;
    std::vector<double> In_l, Sp;
    //- {In, Ms, In_1..In_n, Sp_1..Sp_n}: the vector the realisation statistics average
    std::vector<double> flatten() const;
    static SphereFunctionals unflatten(const std::vector<double>& v);
};
SphereFunctionals functionals(const IntegralEstimate& e);

//- The deterministic case (5.3) (mean velocity 0, no transport) for a ball Omega_r concentric
//  with D: the integrals of the homogeneous solution over Omega_r by radial Gauss-Legendre
//  quadrature (64 panels of 8 nodes on [0, min(r, R)]); for the uniform source this is
//  (5.18), (5.20) and for the linear one (5.22)-(5.25) before their change of variable.
SphereFunctionals deterministicFunctionals(const LagrangianSolution& sol, double t, double r);

//- Mean and 95 % half-width over independent realisations (4.5) (Remark 5.1: over the random
//  velocity, with one table): the realisations are independent and identically distributed, so
//  the interval is the Student t one, mean +- t_{0.975, R-1} sd / sqrt(R).
class RealisationStatistics {
public:
    void add(const std::vector<double>& values);
    std::size_t count() const { return n_; }
    std::vector<double> mean() const;
    std::vector<double> halfWidth95() const;

private:
    std::size_t n_ = 0;
    std::vector<double> mean_, m2_;
};

//- The functionals of the expectations (4.5), the paper's <In_l>, <In>, <Ms>, <Sp> (§5): <n^E>
//  is averaged over the velocity realisations first ((4.5), (5.17), (5.19)), then
//      <Ms> = <int sum l n_l> / <In>,   <Sp_l> = <In_l> / <In>                (5.7), (5.8)
//  (ratios of means over all realisations, those with no cluster in Omega_r included). The
//  mean over realisations of each realisation's ratio is not this: it is undefined where
//  Omega_r holds no cluster, and with a few Monte Carlo points per realisation it is a biased
//  ratio estimator (one hit scores (S^I)^(l-1), not the In-weighted mean). Half-widths: Student
//  t over the realisations, ratios Q = <A>/<B> by the delta method,
//  t_{0.975, R-1} sd(A_i - Q B_i) / (sqrt(R) <B>).
class ExpectationFunctionals {
public:
    void add(const IntegralEstimate& e);
    std::size_t count() const { return rows_.size(); }
    SphereFunctionals mean() const;
    SphereFunctionals halfWidth95() const;

private:
    std::vector<std::vector<double>> rows_;   //- {In, mass, In_1..In_n} per realisation
    std::vector<double> means() const;
};

template <class Stream>
void Sphere::sample(Stream& rng, double x[3]) const
{
    const double u = rng.uniform(), w = rng.uniform(), p = rng.uniform();
    const double rho = radius * std::cbrt(u);
    const double ct = 2.0 * w - 1.0, st = std::sqrt(std::max(0.0, 1.0 - ct * ct));
    const double phi = 6.283185307179586476925286766559 * p;
    x[0] = centre[0] + rho * st * std::cos(phi);
    x[1] = centre[1] + rho * st * std::sin(phi);
    x[2] = centre[2] + rho * ct;
}

} // namespace coag

#endif
