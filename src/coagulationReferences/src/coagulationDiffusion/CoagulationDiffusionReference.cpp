// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#include "coagulationReferences/coagulationDiffusion/CoagulationDiffusionReference.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace coag {

namespace {

//- The interval of integer size l: q[s] <= l <= q[s+1] and the weights of its two nodes.
struct Bracket {
    std::size_t s;
    double w1, w2;  // phi_s(l), phi_{s+1}(l)
};

Bracket bracket(const std::vector<std::size_t>& q, std::size_t l)
{
    // first node > l, minus one; the last node belongs to the last interval
    std::size_t s = static_cast<std::size_t>(std::upper_bound(q.begin(), q.end(), l) - q.begin());
    s = std::min(s, q.size() - 1) - 1;
    const double h = static_cast<double>(q[s + 1] - q[s]);
    const double w2 = static_cast<double>(l - q[s]) / h;
    return Bracket{s, 1.0 - w2, w2};
}

constexpr std::ptrdiff_t blockSize = 256;

} // namespace

SizeCollocation::SizeCollocation(const CoagulationKernel& kernel, std::size_t maxSize,
                                 double gamma)
    : Lambda_(maxSize), gamma_(gamma)
{
    if (maxSize < 2) throw std::invalid_argument("SizeCollocation: maxSize must be >= 2");
    if (!(gamma > 1.0)) throw std::invalid_argument("SizeCollocation: gamma must be > 1");
    for (int p = 0;; ++p) {
        const double g = std::pow(gamma, p);
        const std::size_t r = static_cast<std::size_t>(std::llround(g));
        if (r >= maxSize) break;
        if (q_.empty() || r != q_.back()) q_.push_back(r);
    }
    q_.push_back(maxSize);
    const std::size_t N = q_.size();
    auto K = [&](std::size_t i, std::size_t j) {
        return kernel(ParticleType{static_cast<double>(i)}, ParticleType{static_cast<double>(j)});
    };

    // gain: A^p_mn accumulated densely per p, then stored symmetrised for m <= n
    Eigen::MatrixXd A(N, N);
    for (std::size_t p = 0; p < N; ++p) {
        const std::size_t l = q_[p];
        if (l < 2) continue;
        A.setZero();
        for (std::size_t i = 1; i < l; ++i) {
            const std::size_t j = l - i;
            const Bracket a = bracket(q_, i), b = bracket(q_, j);
            const double k = 0.5 * K(i, j);
            A(a.s, b.s) += k * a.w1 * b.w1;
            A(a.s, b.s + 1) += k * a.w1 * b.w2;
            A(a.s + 1, b.s) += k * a.w2 * b.w1;
            A(a.s + 1, b.s + 1) += k * a.w2 * b.w2;
        }
        for (std::size_t m = 0; m < N; ++m) {
            for (std::size_t n = m; n < N; ++n) {
                const double v = m == n ? A(m, n) : A(m, n) + A(n, m);
                if (v == 0.0) continue;
                gp_.push_back(static_cast<int>(p));
                gm_.push_back(static_cast<int>(m));
                gn_.push_back(static_cast<int>(n));
                ga_.push_back(v);
            }
        }
    }

    // loss: L_pn = sum_{i=1}^{Lambda} K(q_p, i) phi_n(i)
    LT_ = Eigen::MatrixXd::Zero(N, N);
    for (std::size_t p = 0; p < N; ++p) {
        for (std::size_t i = 1; i <= maxSize; ++i) {
            const Bracket b = bracket(q_, i);
            const double k = K(q_[p], i);
            LT_(b.s, p) += k * b.w1;
            LT_(b.s + 1, p) += k * b.w2;
        }
    }
}

double SizeCollocation::interpolate(const double* y, std::ptrdiff_t stride, std::size_t l) const
{
    if (l < 1 || l > Lambda_) return 0.0;
    const Bracket b = bracket(q_, l);
    return b.w1 * y[stride * static_cast<std::ptrdiff_t>(b.s)]
           + b.w2 * y[stride * static_cast<std::ptrdiff_t>(b.s + 1)];
}

void SizeCollocation::rates(const double* Y, std::ptrdiff_t ld, std::ptrdiff_t nPoints,
                            double* out, std::ptrdiff_t ldOut) const
{
    const Eigen::Index N = static_cast<Eigen::Index>(q_.size());
    using Strided = Eigen::Map<const Eigen::MatrixXd, 0, Eigen::OuterStride<>>;
    using StridedOut = Eigen::Map<Eigen::MatrixXd, 0, Eigen::OuterStride<>>;
    const Strided y(Y, nPoints, N, Eigen::OuterStride<>(ld));
    StridedOut r(out, nPoints, N, Eigen::OuterStride<>(ldOut));
    // loss: r(k, p) = -y(k, p) sum_n L_pn y(k, n)
    r.noalias() = y * LT_;
    r.array() *= -y.array();
    // gain: r(k, p) += a y(k, m) y(k, n), the point index innermost
    const std::size_t E = ga_.size();
    for (std::size_t e = 0; e < E; ++e) {
        const double a = ga_[e];
        const double* __restrict ym = Y + ld * gm_[e];
        const double* __restrict yn = Y + ld * gn_[e];
        double* __restrict rp = out + ldOut * gp_[e];
        for (std::ptrdiff_t k = 0; k < nPoints; ++k) rp[k] += a * ym[k] * yn[k];
    }
}

CoagulationDiffusion2D::CoagulationDiffusion2D(const CoagulationKernel& kernel,
                                               const CoagulationDiffusionOptions& options)
    : opt_(options), sizes_(kernel, options.maxSize, options.gamma)
{
    const double dx = opt_.dx, dt = opt_.dt, D = opt_.diffusion;
    if (!(dx > 0) || !(dt > 0) || !(D >= 0) || !(opt_.R > 0) || !(opt_.halfWidth >= dx))
        throw std::invalid_argument("CoagulationDiffusion2D: need dx, dt, R > 0, D >= 0, W >= dx");
    const double r = D * dt / (dx * dx);
    if (r > 0.25) {
        std::ostringstream os;
        os << "CoagulationDiffusion2D: D dt / dx^2 = " << r
           << " > 1/4, the explicit 5-point scheme is unstable";
        throw std::invalid_argument(os.str());
    }
    const std::size_t M = static_cast<std::size_t>(std::llround(opt_.halfWidth / dx));
    M_ = opt_.boundary == CoagulationDiffusionOptions::Boundary::ZeroValue ? M : M + 1;
    S_ = M_ + 2;
    P_ = static_cast<std::ptrdiff_t>(S_ * S_);
    const Eigen::Index N = static_cast<Eigen::Index>(sizes_.nNodes());
    Y_ = Eigen::ArrayXXd::Zero(P_, N);
    Ynew_ = Eigen::ArrayXXd::Zero(P_, N);
    rate_ = Eigen::ArrayXXd::Zero(blockSize, N);
    // cell-average of the indicator of [-R, R] about node c: overlap of [c - dx/2, c + dx/2]
    auto frac = [&](double c) {
        const double lo = std::max(c - 0.5 * dx, -opt_.R), hi = std::min(c + 0.5 * dx, opt_.R);
        return std::max(hi - lo, 0.0) / dx;
    };
    for (std::size_t j = 0; j < M_; ++j)
        for (std::size_t i = 0; i < M_; ++i)
            Y_(index(i, j), 0) = opt_.n0 * frac(static_cast<double>(i) * dx)
                                 * frac(static_cast<double>(j) * dx);
    fillGhosts(Y_);
}

void CoagulationDiffusion2D::fillGhosts(Eigen::ArrayXXd& Y) const
{
    const bool flux = opt_.boundary == CoagulationDiffusionOptions::Boundary::ZeroFlux;
    const std::ptrdiff_t S = static_cast<std::ptrdiff_t>(S_), M = static_cast<std::ptrdiff_t>(M_);
    for (Eigen::Index p = 0; p < Y.cols(); ++p) {
        double* f = Y.col(p).data();
        for (std::ptrdiff_t j = 1; j <= M; ++j) {
            double* row = f + j * S;        // row[1 + i] is node i
            row[0] = M > 1 ? row[2] : row[1];   // mirror about x = 0
            row[M + 1] = flux ? row[M - 1] : 0.0;
        }
        std::copy(f + 2 * S, f + 3 * S, f);  // mirror about y = 0 (ghost row = row j = 1)
        if (flux) std::copy(f + (M - 1) * S, f + M * S, f + (M + 1) * S);
        else std::fill(f + (M + 1) * S, f + (M + 2) * S, 0.0);
    }
}

void CoagulationDiffusion2D::rhsBlock(const Eigen::ArrayXXd& Y, std::ptrdiff_t k0,
                                      std::ptrdiff_t B)
{
    const double c = opt_.diffusion / (opt_.dx * opt_.dx);
    const std::ptrdiff_t S = static_cast<std::ptrdiff_t>(S_);
    if (opt_.coagulation) sizes_.rates(Y.data() + k0, P_, B, rate_.data(), blockSize);
    else rate_.setZero();
    for (Eigen::Index p = 0; p < Y.cols(); ++p) {
        const double* __restrict f = Y.col(p).data() + k0;
        double* __restrict g = rate_.col(p).data();
        for (std::ptrdiff_t k = 0; k < B; ++k)
            g[k] += c * (f[k - 1] + f[k + 1] + f[k - S] + f[k + S] - 4.0 * f[k]);
    }
}

void CoagulationDiffusion2D::step()
{
    const double dt = opt_.dt;
    const std::ptrdiff_t S = static_cast<std::ptrdiff_t>(S_);
    const Eigen::Index N = Y_.cols();
    const std::ptrdiff_t kEnd = P_ - S;  // rows j = 0..M-1 (ghost columns are refilled)
    const bool heun = opt_.scheme == CoagulationDiffusionOptions::Scheme::Heun;
    Eigen::ArrayXXd& first = heun ? Ystar_ : Ynew_;
    if (heun && Ystar_.rows() != P_) Ystar_ = Eigen::ArrayXXd::Zero(P_, N);
    for (std::ptrdiff_t k0 = S; k0 < kEnd; k0 += blockSize) {
        const std::ptrdiff_t B = std::min(blockSize, kEnd - k0);
        rhsBlock(Y_, k0, B);
        for (Eigen::Index p = 0; p < N; ++p) {
            const double* __restrict f = Y_.col(p).data() + k0;
            const double* __restrict g = rate_.col(p).data();
            double* __restrict o = first.col(p).data() + k0;
            for (std::ptrdiff_t k = 0; k < B; ++k) o[k] = f[k] + dt * g[k];
        }
    }
    fillGhosts(first);
    if (heun) {
        for (std::ptrdiff_t k0 = S; k0 < kEnd; k0 += blockSize) {
            const std::ptrdiff_t B = std::min(blockSize, kEnd - k0);
            rhsBlock(Ystar_, k0, B);
            for (Eigen::Index p = 0; p < N; ++p) {
                const double* __restrict f = Y_.col(p).data() + k0;
                const double* __restrict h = Ystar_.col(p).data() + k0;
                const double* __restrict g = rate_.col(p).data();
                double* __restrict o = Ynew_.col(p).data() + k0;
                for (std::ptrdiff_t k = 0; k < B; ++k) o[k] = 0.5 * (f[k] + h[k] + dt * g[k]);
            }
        }
        fillGhosts(Ynew_);
    }
    Y_.swap(Ynew_);
    t_ += dt;
    ++k_;
}

void CoagulationDiffusion2D::advanceTo(double t)
{
    while (t_ < t - 0.5 * opt_.dt) step();
}

double CoagulationDiffusion2D::nodeValue(std::size_t p, std::size_t i, std::size_t j) const
{
    if (i >= M_ || j >= M_) return 0.0;  // the zero-value boundary node, or outside
    return Y_(index(i, j), static_cast<Eigen::Index>(p));
}

double CoagulationDiffusion2D::density(std::size_t l, double x, double y) const
{
    x = std::abs(x) / opt_.dx;
    y = std::abs(y) / opt_.dx;
    const std::size_t i = static_cast<std::size_t>(x), j = static_cast<std::size_t>(y);
    if (i + 1 > M_ + 1 || j + 1 > M_ + 1) return 0.0;
    const double fx = x - static_cast<double>(i), fy = y - static_cast<double>(j);
    auto v = [&](std::size_t a, std::size_t b) {
        if (a >= M_ || b >= M_) return 0.0;
        return sizes_.interpolate(Y_.data() + index(a, b), P_, l);
    };
    return (1 - fx) * (1 - fy) * v(i, j) + fx * (1 - fy) * v(i + 1, j)
           + (1 - fx) * fy * v(i, j + 1) + fx * fy * v(i + 1, j + 1);
}

double CoagulationDiffusion2D::totalNumber() const
{
    const std::size_t N = sizes_.nNodes();
    std::vector<double> w(N, 0.0);  // w_m = sum_l phi_m(l)
    for (std::size_t l = 1; l <= sizes_.maxSize(); ++l) {
        const Bracket b = bracket(sizes_.nodes(), l);
        w[b.s] += b.w1;
        w[b.s + 1] += b.w2;
    }
    const bool flux = opt_.boundary == CoagulationDiffusionOptions::Boundary::ZeroFlux;
    auto weight = [&](std::size_t i) {
        return (i == 0 || (flux && i + 1 == M_)) ? 0.5 : 1.0;
    };
    double s = 0.0;
    for (std::size_t j = 0; j < M_; ++j)
        for (std::size_t i = 0; i < M_; ++i) {
            double n = 0.0;
            for (std::size_t m = 0; m < N; ++m)
                n += w[m] * Y_(index(i, j), static_cast<Eigen::Index>(m));
            s += weight(i) * weight(j) * n;
        }
    return 4.0 * s * opt_.dx * opt_.dx;
}

namespace exact {

double diffusedSquare(double n0, double R, double D, double t, double x, double y)
{
    if (t <= 0) return (std::abs(x) < R && std::abs(y) < R) ? n0 : 0.0;
    const double s = 2.0 * std::sqrt(D * t);
    auto f = [&](double c) { return 0.5 * (std::erf((R - c) / s) + std::erf((R + c) / s)); };
    return n0 * f(x) * f(y);
}

} // namespace exact

} // namespace coag
