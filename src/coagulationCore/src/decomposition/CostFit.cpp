// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#include "coagulation/decomposition/CostFit.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Core>

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
    using Matrix = Eigen::Matrix3d;
    using Vector = Eigen::Vector3d;
    Result r;
    if (n_ <= nTerms) return r;
    Matrix N;
    Vector b;
    for (std::size_t i = 0; i < nTerms; ++i) {
        for (std::size_t j = 0; j < nTerms; ++j) N(i, j) = normal_[i][j];
        b(i) = rhs_[i];
    }
    const Vector d = N.diagonal().cwiseSqrt();
    if (!d.allFinite() || !(d.array() > 0.0).all()) return r;
    // S = D^-1 N D^-1 (unit diagonal) and its Cholesky factor: the pivots, L_jj^2, are 1 - R^2
    // of each regressor on the ones before it
    const auto Dinv = d.cwiseInverse().asDiagonal();
    const Matrix S = Dinv * N * Dinv;
    const Eigen::LLT<Matrix> llt(S);
    const Vector pivots = llt.matrixLLT().diagonal().cwiseAbs2();
    if (llt.info() != Eigen::Success || !(pivots.array() >= minPivot).all()) return r;
    const Matrix Ninv = Dinv * llt.solve(Matrix::Identity()) * Dinv;
    const Vector coef = Ninv * b;
    const double s2 =
        std::max(sumSquares_ - coef.dot(b), 0.0) / static_cast<double>(n_ - nTerms);
    for (std::size_t i = 0; i < nTerms; ++i) {
        r.coef[i] = coef(i);
        for (std::size_t j = 0; j < nTerms; ++j) r.cov[i][j] = s2 * Ninv(i, j);
        r.stdErr[i] = std::sqrt(std::max(r.cov[i][i], 0.0));
    }
    r.determined = true;
    return r;
}

CostFit::Relative CostFit::relative(const Result& r, double moveSeconds)
{
    Relative q;
    if (!r.determined || !(moveSeconds > 0.0) || !std::isfinite(moveSeconds)) return q;
    const double p = moveSeconds + r.coef[1];
    if (!(p > minParticleShare * moveSeconds) || !std::isfinite(p)) return q;
    const double e = r.coef[0] / p;
    const double v = r.coef[2] / p;
    // d(c0/p) = dc0/p - c0 dc1/p^2 (and the same for c2): first order
    const double eVar = (r.cov[0][0] - 2.0 * e * r.cov[0][1] + e * e * r.cov[1][1]) / (p * p);
    const double vVar = (r.cov[2][2] - 2.0 * v * r.cov[2][1] + v * v * r.cov[1][1]) / (p * p);
    q.eventCost = e;
    q.visit = v;
    q.eventCostErr = std::sqrt(std::max(eVar, 0.0));
    q.visitErr = std::sqrt(std::max(vVar, 0.0));
    q.determined = std::isfinite(e) && std::isfinite(v) && std::isfinite(q.eventCostErr)
                   && std::isfinite(q.visitErr);
    return q;
}

} // namespace coag
