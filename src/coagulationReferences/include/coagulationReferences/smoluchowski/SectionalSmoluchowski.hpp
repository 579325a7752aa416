// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_SECTIONALSMOLUCHOWSKI_HPP
#define COAGULATION_SECTIONALSMOLUCHOWSKI_HPP

#include "coagulation/kernels/CoagulationKernel.hpp"

#include <Eigen/Dense>

#include <cstddef>
#include <vector>

//- A deterministic reference for continuous size distributions: the Smoluchowski equation
//      dn(x)/dt = 1/2 int_0^x K(x-y, y) n(x-y) n(y) dy - n(x) int_0^inf K(x, y) n(y) dy
//  on a grid of mass sections by the cell-average technique (Kumar, Kumar, Warnecke, Tsotsas
//  & Moerl 2006, Chem. Eng. Sci. 61:3327; 2007, Chem. Eng. Sci. 62:4769).
namespace coag {

//- Sections [edges[i], edges[i+1]) of the mass axis, with one pivot in each (edges[i] <=
//  pivots[i] < edges[i+1]); the number density of section i is carried at its pivot.
struct SectionalGrid {
    std::vector<double> edges;   //!< L + 1, increasing
    std::vector<double> pivots;  //!< L

    std::size_t size() const { return pivots.size(); }
    //- The section holding mass x: L for x >= edges[L]; throws std::out_of_range for
    //  x < edges[0].
    std::size_t section(double x) const;
};

//- Pivots xmin r^i with r = 2^(1/perDoubling) up to the first pivot >= xmax, edges at the
//  geometric means of neighbouring pivots (and xmin r^(-1/2), last r^(1/2)). Throws
//  std::invalid_argument unless 0 < xmin < xmax and perDoubling >= 1.
SectionalGrid geometricGrid(double xmin, double xmax, unsigned perDoubling);

//- The masses 1, 2, ..., m as sections [l - 1/2, l + 1/2) of their own (pivot l), with
//  m = ceil(1/(r - 1)) where the integers are as dense as the geometric sections, then
//  geometric sections of ratio r = 2^(1/perDoubling) from m + 1/2 up to the first edge
//  >= xmax, pivots at the geometric means of their edges. From a monodisperse start of unit
//  masses the small sizes are then the discrete equation's, exactly.
SectionalGrid discreteGeometricGrid(double xmax, unsigned perDoubling);

//- The cell-average technique: in section i the number N_i of particles at pivot x_i.
//  Every pair (j <= k) of sections makes aggregates of mass x_j + x_k at the rate
//  (1 - delta_jk/2) K(x_j, x_k) N_j N_k; the aggregates landing in section i are counted
//  (B_i) with their mass (V_i), and their mean mass vbar_i = V_i / B_i is shared between the
//  two pivots that bracket it, x_i and x_{i+1} (vbar_i >= x_i) or x_{i-1} and x_i, so that
//  number and mass are both kept (Kumar et al. 2006, eqs. 18-23). Loss: N_i sum_k K_ik N_k.
//  M0's and M1's rates are those of the continuous equation for the pivots' distribution;
//  the error in the other moments and the size distribution is of second order in the
//  section width on smooth grids (Kumar & Warnecke 2008, Numer. Math. 110:539).
//  Aggregates beyond the last edge, and the excess mass of those averaging above the last
//  pivot, are booked as lost mass, so that M1 + lost mass is conserved to round-off.
//  The kernel is tabulated on the pivots (L^2 evaluations); a right hand side costs
//  L(L+1)/2 pair terms. Integrated by integrateDormandPrince.
class SectionalSmoluchowski {
public:
    //- Throws std::invalid_argument for a grid of fewer than 2 or more than
    //  maxDenseKernelSize sections, or edges and pivots that are not ordered as above.
    SectionalSmoluchowski(const CoagulationKernel& kernel, SectionalGrid grid);

    const SectionalGrid& grid() const { return grid_; }
    std::size_t size() const { return grid_.size(); }

    //- The pivots' numbers for sections holding number[i] particles of total mass mass[i]
    //  (each section's mean mass shared between the two bracketing pivots, as a birth is),
    //  so that M0 and M1 are those given. Mass averaging below the first pivot is put on it.
    Eigen::VectorXd fromSections(const std::vector<double>& number,
                                 const std::vector<double>& mass) const;
    //- N0 particles of mass x (put on the two bracketing pivots; exact when x is one).
    Eigen::VectorXd monodisperse(double N0, double x) const;
    //- N0 particles with ln(mass) normal of median medianMass and standard deviation
    //  lnSigmaMass (in diameter: CMD = d(medianMass), ln sigma_g = lnSigmaMass / 3), each
    //  section's number and mass integrated exactly (erfc) and put on the pivots by
    //  fromSections; what lies outside [edges[0], edges[L]) is dropped.
    Eigen::VectorXd lognormal(double N0, double medianMass, double lnSigmaMass) const;

    //- dN/dt at N (size L); lostRate gets the rate at which mass leaves the grid.
    Eigen::VectorXd rhs(const Eigen::VectorXd& N, double* lostRate = nullptr) const;

    //- N(t1) from N(t0) = N0, t1 >= t0. The mass lost on the way is added to lostMass().
    //  Throws std::runtime_error if the step size underflows.
    Eigen::VectorXd integrate(const Eigen::VectorXd& N0, double t0, double t1);

    //- Error control per component, |err_i| <= absTol + relTol |N_i| (RMS norm);
    //  defaults 1e-8 and 1e-16 (for numbers of order one: scale absTol with N0). The step
    //  counts are those of the last integrate call.
    void setTolerances(double relTol, double absTol);
    double lostMass() const { return lost_; }
    std::size_t acceptedSteps() const { return accepted_; }
    std::size_t rejectedSteps() const { return rejected_; }

    //- sum_i N_i x_i^k
    double moment(const Eigen::VectorXd& N, double k) const;
    //- The number in the sections whose pivots lie in [a, b).
    double numberBetween(const Eigen::VectorXd& N, double a, double b) const;
    //- The geometric standard deviation of the number distribution by diameter (spheres,
    //  d ~ x^(1/3)): exp(sd(ln x) / 3).
    double geometricStdDevDiameter(const Eigen::VectorXd& N) const;

private:
    //- Put `count` particles of mean mass `mean`, counted in section i, on the bracketing
    //  pivots (keeping number and mass); mass beyond the last pivot goes to *lost.
    void distribute(std::size_t i, double count, double mean, double* out, double* lost) const;
    void rhsAugmented(const Eigen::VectorXd& y, Eigen::VectorXd& out) const;

    SectionalGrid grid_;
    Eigen::MatrixXd K_;
    std::vector<unsigned> target_;  //!< section of x_j + x_k, index j L + k (k >= j)
    double relTol_ = 1e-8;
    double absTol_ = 1e-16;
    double lost_ = 0.0;
    std::size_t accepted_ = 0;
    std::size_t rejected_ = 0;
    mutable Eigen::VectorXd B_, V_;
};

} // namespace coag

#endif
