// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#include "coagulation/CostFit.hpp"

#include <algorithm>
#include <cmath>

namespace coag {

void CostFit::add(double x0, double x1, double x2, double t)
{
    const double x[nTerms] = {x0, x1, x2};
    if (!std::isfinite(x0) || !std::isfinite(x1) || !std::isfinite(x2) || !std::isfinite(t)) {
        ++skipped_;
        return;
    }
    for (std::size_t i = 0; i < nTerms; ++i) {
        for (std::size_t j = 0; j < nTerms; ++j) normal_[i][j] += x[i] * x[j];
        rhs_[i] += x[i] * t;
    }
    sumSquares_ += t * t;
    ++n_;
}

void CostFit::clear()
{
    *this = CostFit();
}

CostFit::Result CostFit::solve() const
{
    Result r;
    if (n_ <= nTerms) return r;
    double d[nTerms];
    for (std::size_t i = 0; i < nTerms; ++i) {
        d[i] = std::sqrt(normal_[i][i]);
        if (!(d[i] > 0.0) || !std::isfinite(d[i])) return r;
    }
    // Cholesky of the scaled matrix S = L L^T
    double L[nTerms][nTerms] = {};
    for (std::size_t j = 0; j < nTerms; ++j) {
        double pivot = normal_[j][j] / (d[j] * d[j]);
        for (std::size_t k = 0; k < j; ++k) pivot -= L[j][k] * L[j][k];
        if (!(pivot >= minPivot)) return r;
        L[j][j] = std::sqrt(pivot);
        for (std::size_t i = j + 1; i < nTerms; ++i) {
            double s = normal_[i][j] / (d[i] * d[j]);
            for (std::size_t k = 0; k < j; ++k) s -= L[i][k] * L[j][k];
            L[i][j] = s / L[j][j];
        }
    }
    // S^-1 column by column (L y = e, L^T z = y)
    double Sinv[nTerms][nTerms];
    for (std::size_t c = 0; c < nTerms; ++c) {
        double y[nTerms];
        for (std::size_t i = 0; i < nTerms; ++i) {
            double s = i == c ? 1.0 : 0.0;
            for (std::size_t k = 0; k < i; ++k) s -= L[i][k] * y[k];
            y[i] = s / L[i][i];
        }
        for (std::size_t i = nTerms; i-- > 0;) {
            double s = y[i];
            for (std::size_t k = i + 1; k < nTerms; ++k) s -= L[k][i] * Sinv[k][c];
            Sinv[i][c] = s / L[i][i];
        }
    }
    // N^-1 = D^-1 S^-1 D^-1; coefficients N^-1 rhs
    double Ninv[nTerms][nTerms];
    for (std::size_t i = 0; i < nTerms; ++i) {
        for (std::size_t j = 0; j < nTerms; ++j) Ninv[i][j] = Sinv[i][j] / (d[i] * d[j]);
    }
    double fitted = 0.0;  // coef . rhs, the fitted part of sum t^2
    for (std::size_t i = 0; i < nTerms; ++i) {
        double c = 0.0;
        for (std::size_t j = 0; j < nTerms; ++j) c += Ninv[i][j] * rhs_[j];
        r.coef[i] = c;
        fitted += c * rhs_[i];
    }
    const double s2 =
        std::max(sumSquares_ - fitted, 0.0) / static_cast<double>(n_ - nTerms);
    for (std::size_t i = 0; i < nTerms; ++i) {
        for (std::size_t j = 0; j < nTerms; ++j) r.cov[i][j] = s2 * Ninv[i][j];
        r.stdErr[i] = std::sqrt(std::max(r.cov[i][i], 0.0));
    }
    r.determined = true;
    return r;
}

} // namespace coag
