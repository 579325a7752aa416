// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_COSTFIT_HPP
#define COAGULATION_COSTFIT_HPP

#include <array>
#include <cstddef>

namespace coag {

//- The cost of a cell step, fitted: least squares of the observed wall seconds t
//  over three regressors, t = c0 x0 + c1 x1 + c2 x2 (cellWork: x = events, particles, 1 for a
//  stepped cell), from the normal equations accumulated by add().
//
//  solve() scales the normal matrix N to a unit diagonal (S = D^-1 N D^-1, D = sqrt(diag N)),
//  so that its Cholesky pivots (Eigen's LLT) measure how far the regressors are from collinear (a pivot is
//  1 - R^2 of a regressor on the ones before it): a pivot below minPivot, a zero column or
//  at most 3 observations leave the fit undetermined rather than give numbers the data do not
//  hold. (On a processor holding three cells of the duct, events and particles moved together
//  over the steps; a fit through the unscaled inverse stopped that run with a floating-point
//  trap.) The standard errors are
//  sqrt(diag(s^2 N^-1)), s^2 the residuals' variance over n - 3 degrees of freedom: the
//  residuals taken as independent (a machine whose speed drifts between intervals moves the
//  coefficients more than that).
class CostFit {
public:
    static constexpr std::size_t nTerms = 3;
    //- The smallest Cholesky pivot of the scaled normal matrix for a determined fit
    static constexpr double minPivot = 1e-8;

    //- One observation; non-finite values are ignored (counted in skipped())
    void add(double x0, double x1, double x2, double t);
    void clear();
    std::size_t count() const { return n_; }
    std::size_t skipped() const { return skipped_; }

    struct Result {
        bool determined = false;
        std::array<double, nTerms> coef{};
        std::array<double, nTerms> stdErr{};
        std::array<std::array<double, nTerms>, nTerms> cov{};  // of the coefficients
    };
    Result solve() const;

    //- cellWork's costs in particles: p = moveSeconds + coef[1] (a move and a particle's
    //  share of the cell step), eventCost = coef[0] / p, visit = coef[2] / p, with
    //  first-order errors from the covariance (moveSeconds as measured). Undetermined where
    //  the fit is, or where p is not above minParticleShare of a move: a fit that puts a
    //  particle's share of the cell step near minus a move holds no ratio (on the duct's
    //  3-cell processor it put p at or below zero, and the ratios' errors overflowed into a
    //  floating-point trap at the end of the run).
    static constexpr double minParticleShare = 0.1;
    struct Relative {
        bool determined = false;
        double eventCost = 0.0;
        double eventCostErr = 0.0;
        double visit = 0.0;
        double visitErr = 0.0;
    };
    static Relative relative(const Result& r, double moveSeconds);

private:
    std::array<std::array<double, nTerms>, nTerms> normal_{};
    std::array<double, nTerms> rhs_{};
    double sumSquares_ = 0.0;
    std::size_t n_ = 0;
    std::size_t skipped_ = 0;
};

} // namespace coag

#endif
