// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_COAGULATIONDIFFUSIONREFERENCE_HPP
#define COAGULATION_COAGULATIONDIFFUSIONREFERENCE_HPP

#include "coagulation/kernels/CoagulationKernel.hpp"

#include <Eigen/Dense>

#include <cstddef>
#include <vector>

//- The Eulerian reference of Sabelfeld–Kolodko §6: the 2-D coagulation–diffusion
//  equation
//      dn_l/dt = D Lap n_l + 1/2 sum_{i+j=l} K_ij n_i n_j - n_l sum_{i=1}^{Lambda} K_il n_i,
//  sizes l = 1..Lambda, v = 0, with a collocation (piecewise-linear) representation in size
//  (the paper's eqs 26–28) and explicit finite differences in space and time.
namespace coag {

//- Piecewise-linear collocation in size (eqs 26–28). Nodes: the distinct values of
//  round(gamma^p), p = 0, 1, ..., below Lambda, then Lambda itself. With hat functions phi_m
//  (phi_m(q_k) = delta_mk) the approximation is n_l = sum_m y_m phi_m(l), and eq. (27) evaluated
//  at the nodes is the quadratic form
//      dy_p/dt = sum_{m<=n} A^p_mn y_m y_n - y_p sum_n L_pn y_n,
//      A^p_mn = 1/2 sum_{i+j=q_p} K_ij [phi_m(i) phi_n(j) + phi_n(i) phi_m(j)] (m < n; m = n
//               without the symmetrisation), L_pn = sum_{i=1}^{Lambda} K(q_p, i) phi_n(i),
//  i.e. the exact Smoluchowski operator applied to the piecewise-linear interpolant and
//  evaluated at the nodes (the sums over integer sizes are done once, in the constructor).
class SizeCollocation {
public:
    SizeCollocation(const CoagulationKernel& kernel, std::size_t maxSize, double gamma);

    std::size_t maxSize() const { return Lambda_; }
    double gamma() const { return gamma_; }
    const std::vector<std::size_t>& nodes() const { return q_; }
    std::size_t nNodes() const { return q_.size(); }
    std::size_t nGainEntries() const { return gp_.size(); }

    //- n_l from the node values y (l in 1..Lambda; 0 outside).
    double interpolate(const double* y, std::ptrdiff_t stride, std::size_t l) const;

    //- Coagulation rates of nPoints independent points: Y(k + ld*m) is y_m at point k,
    //  out(k + ldOut*m) receives dy_m/dt. Loop order: point index innermost (vectorises).
    void rates(const double* Y, std::ptrdiff_t ld, std::ptrdiff_t nPoints, double* out,
               std::ptrdiff_t ldOut) const;

private:
    std::size_t Lambda_;
    double gamma_;
    std::vector<std::size_t> q_;
    // gain entries (p, m, n, a), sorted by p
    std::vector<int> gp_, gm_, gn_;
    std::vector<double> ga_;
    Eigen::MatrixXd LT_;  // L^T: LT_(n, p) = L_pn
};

//- The 2-D solver on the square [-W, W]^2 for data symmetric in x and in y (the paper's square
//  initial condition), computed on the quadrant [0, W]^2 with mirror conditions on the axes.
//  Grid nodes x_i = i dx, i = 0..M, M = round(W/dx). Outer boundary: ZeroValue (n = 0 on
//  x = W and y = W) or ZeroFlux (mirror about x = W). Space: the 5-point Laplacian. Time:
//  forward Euler (the paper's explicit scheme, first order) or Heun's explicit second-order
//  Runge–Kutta (the default: y* = y + dt F(y), y' = (y + y* + dt F(y*)) / 2); both are stable
//  for r = D dt / dx^2 <= 1/4 (checked) and K n dt small (not checked; K11 n0 dt = 0.0125 here).
struct CoagulationDiffusionOptions {
    std::size_t maxSize = 14000;  // Lambda
    double gamma = 1.1;           // collocation ratio
    double diffusion = 8.88e-2;   // D, in units R^2 / T_c (x' = x/R, t' = t K11 n0)
    double n0 = 1.0;              // monomer density inside the initial square
    double R = 1.0;               // initial square [-R, R]^2
    double halfWidth = 2.0;       // W: the domain is [-W, W]^2 (paper: side 4R)
    double dx = 0.07;             // the paper's dx'
    //- The paper's dt' = 0.014 gives r = 0.2537 > 1/4 at D = 8.88e-2 (unstable checkerboard);
    //  0.0125 (r = 0.2265) is the default.
    double dt = 0.0125;
    enum class Boundary { ZeroValue, ZeroFlux } boundary = Boundary::ZeroValue;
    bool coagulation = true;      // false: pure diffusion
    enum class Scheme { Euler, Heun } scheme = Scheme::Heun;
};

class CoagulationDiffusion2D {
public:
    //- Initial data: n_1 = n0 times the fraction of the cell [x_i -+ dx/2] x [y_j -+ dx/2] that
    //  lies in [-R, R]^2 (cell averages: the total number is exact), n_l = 0 for l > 1.
    //  Throws std::invalid_argument for r > 1/4, dx <= 0, dt <= 0, W < dx.
    CoagulationDiffusion2D(const CoagulationKernel& kernel,
                           const CoagulationDiffusionOptions& options);

    void step();
    //- Steps until time() >= t - dt/2 (the last step is not shortened).
    void advanceTo(double t);

    double time() const { return t_; }
    std::size_t steps() const { return k_; }
    const SizeCollocation& sizes() const { return sizes_; }
    const CoagulationDiffusionOptions& options() const { return opt_; }
    std::size_t gridPoints() const { return M_; }  // nodes per axis in the quadrant

    //- n_l(t, x, y): bilinear in space (|x|, |y| by symmetry), linear in size; 0 outside.
    double density(std::size_t l, double x, double y) const;
    //- Node value y_p at grid node (i, j) of the quadrant.
    double nodeValue(std::size_t p, std::size_t i, std::size_t j) const;
    //- The total number of particles sum_l n_l over the whole square (trapezoid rule in
    //  space over the four quadrants, interpolated sizes).
    double totalNumber() const;

private:
    std::ptrdiff_t index(std::size_t i, std::size_t j) const  // padded storage
    {
        return static_cast<std::ptrdiff_t>((j + 1) * S_ + i + 1);
    }
    void fillGhosts(Eigen::ArrayXXd& Y) const;
    //- out(k, p) = D Lap y_p + coagulation rate at padded points k0..k0+B-1 (B <= blockSize).
    void rhsBlock(const Eigen::ArrayXXd& Y, std::ptrdiff_t k0, std::ptrdiff_t B);

    CoagulationDiffusionOptions opt_;
    SizeCollocation sizes_;
    std::size_t M_;       // unknown nodes per axis (i = 0..M_-1)
    std::size_t S_;       // padded row length M_ + 2
    std::ptrdiff_t P_;    // padded points per size
    Eigen::ArrayXXd Y_, Ystar_, Ynew_, rate_;
    double t_ = 0.0;
    std::size_t k_ = 0;
};

namespace exact {
//- Pure diffusion of n0 on [-R, R]^2 in the plane: n0 prod_{c=x,y} 1/2 [erf((R - c)/(2 sqrt(D t)))
//  + erf((R + c)/(2 sqrt(D t)))] (the Gaussian of variance 2 D t per coordinate integrated over
//  the square; the README's N^D (29) with sigma' = sqrt(2 t') when t' = t D / R^2).
double diffusedSquare(double n0, double R, double D, double t, double x, double y);
} // namespace exact

} // namespace coag

#endif
