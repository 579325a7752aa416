// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_SMOLUCHOWSKIREFERENCE_HPP
#define COAGULATION_SMOLUCHOWSKIREFERENCE_HPP

#include "coagulation/kernels/CoagulationKernel.hpp"

#include <Eigen/Dense>

#include <cstddef>
#include <functional>
#include <vector>

//- Deterministic references for the discrete Smoluchowski equation (sizes l = 1, 2, ...,
//  vector index l-1; the kernel is evaluated on ParticleType{mass = l}).
namespace coag {

//- The right hand side of an autonomous ODE system y' = f(y): out = f(y).
using OdeRhs = std::function<void(const Eigen::VectorXd&, Eigen::VectorXd&)>;

//- y(t1) from y(t0) = y0 by the adaptive embedded Dormand–Prince 5(4) Runge–Kutta pair (FSAL,
//  local extrapolation, error per component scaled by absTol + relTol*max(|y|, |ynew|), RMS
//  norm, step factor 0.9 err^{-1/5} in [0.2, 5], the first step after Hairer, Norsett &
//  Wanner II.4). Counts the accepted and rejected steps; throws std::runtime_error, naming
//  who, if the step size underflows.
Eigen::VectorXd integrateDormandPrince(const OdeRhs& f, const Eigen::VectorXd& y0, double t0,
                                       double t1, double relTol, double absTol,
                                       std::size_t& accepted, std::size_t& rejected,
                                       const char* who);

//- Dense kernel matrix K(i+1, j+1), i, j < L. Throws std::invalid_argument for L == 0 or
//  L > maxDenseKernelSize (the matrix takes 8 L^2 bytes).
constexpr std::size_t maxDenseKernelSize = 4096;
Eigen::MatrixXd kernelMatrix(const CoagulationKernel& kernel, std::size_t L);

//- The truncated discrete Smoluchowski system for sizes 1..L with a constant source F:
//      dn_l/dt = F_l + 1/2 sum_{i+j=l} K_ij n_i n_j - n_l sum_{i<=L} K_il n_i,
//  (clusters that would be larger than L are lost), integrated by the adaptive embedded
//  Dormand–Prince 5(4) Runge–Kutta pair (FSAL, local extrapolation, error per component
//  scaled by absTol + relTol*|n_l|, RMS norm, step factor 0.9 err^{-1/5} in [0.2, 5]).
//  Each right hand side costs O(L^2).
class DiscreteSmoluchowski {
public:
    DiscreteSmoluchowski(const CoagulationKernel& kernel, std::size_t L,
                         const Eigen::VectorXd& source = Eigen::VectorXd());

    std::size_t maxSize() const { return L_; }
    const Eigen::MatrixXd& kernelMatrix() const { return K_; }

    //- Right hand side at n (size L).
    Eigen::VectorXd rhs(const Eigen::VectorXd& n) const;

    //- Integrate from (t0, n0) to t1 >= t0. Error control per component with
    //  |err_l| <= absTol + relTol*|n_l| (RMS norm). Throws std::runtime_error if the step
    //  size underflows.
    Eigen::VectorXd integrate(const Eigen::VectorXd& n0, double t0, double t1) const;

    void setTolerances(double relTol, double absTol);
    std::size_t acceptedSteps() const { return accepted_; }
    std::size_t rejectedSteps() const { return rejected_; }

private:
    void rhs(const Eigen::VectorXd& n, Eigen::VectorXd& out) const;

    std::size_t L_;
    Eigen::MatrixXd K_;
    Eigen::VectorXd F_;
    double relTol_ = 1e-10;
    double absTol_ = 1e-14;
    mutable std::size_t accepted_ = 0;
    mutable std::size_t rejected_ = 0;
};

//- Kolodko–Sabelfeld–Wagner finite-difference scheme (2.27)–(2.30), the deterministic limit
//  of the Nanbu method:
//      nhat_l(t_{k+1}) = nhat_l(t_k) + Delta_k ( 1/2 sum_{i+j=l} K_ij nhat_i nhat_j
//                                                - nhat_l sum_i K_il nhat_i ),
//      Delta_k = alpha / max_{1 <= i <= min(2^k L0, L)} sum_j K_ij nhat_j(t_k),
//  L0 the largest initially occupied size, sizes truncated at L = maxSize (the paper's
//  2^k L0 range is capped at L; clusters beyond L are lost). Requires alpha in (0,1].
class FiniteDifferenceSmoluchowski {
public:
    FiniteDifferenceSmoluchowski(const CoagulationKernel& kernel,
                                 const std::vector<double>& initialDensity,  // index l-1
                                 double alpha, std::size_t maxSize);

    //- One step; returns Delta_k.
    double step();

    double time() const { return t_; }
    std::size_t stepIndex() const { return k_; }
    double alpha() const { return alpha_; }
    std::size_t maxSize() const { return L_; }
    //- nhat_l(t_k) for l >= 1 (0 beyond maxSize).
    double density(std::size_t l) const;
    const Eigen::VectorXd& densities() const { return n_; }

private:
    std::size_t L_;
    double alpha_;
    std::size_t L0_ = 1;
    Eigen::MatrixXd K_;
    Eigen::VectorXd n_;
    Eigen::VectorXd Kn_;
    Eigen::VectorXd gain_;
    double t_ = 0.0;
    std::size_t k_ = 0;
};

//- min(2^k L0, L) without overflow: the size range of the time-step maximum (2.12)/(2.29).
std::size_t cappedDoublingRange(std::size_t L0, std::size_t k, std::size_t L);

} // namespace coag

#endif
