// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#include "coagulationReferences/smoluchowski/SmoluchowskiReference.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace coag {

Eigen::MatrixXd kernelMatrix(const CoagulationKernel& kernel, std::size_t L)
{
    if (L == 0 || L > maxDenseKernelSize) {
        std::ostringstream os;
        os << "coag::kernelMatrix: maximum size L must be in [1, " << maxDenseKernelSize
           << "], got " << L;
        throw std::invalid_argument(os.str());
    }
    const Eigen::Index n = static_cast<Eigen::Index>(L);
    Eigen::MatrixXd K(n, n);
    for (Eigen::Index j = 0; j < n; ++j) {
        for (Eigen::Index i = j; i < n; ++i) {
            const double v = kernel(ParticleType{static_cast<double>(i + 1)},
                                    ParticleType{static_cast<double>(j + 1)});
            K(i, j) = v;
            K(j, i) = v;
        }
    }
    return K;
}

std::size_t cappedDoublingRange(std::size_t L0, std::size_t k, std::size_t L)
{
    std::size_t r = L0;
    for (std::size_t i = 0; i < k && r < L; ++i) r *= 2;
    return std::min(r, L);
}

namespace {

//- gain_l = 1/2 sum_{i+j=l} K_ij n_i n_j for l = 1..L (index l-1); only sizes <= active.
void convolutionGain(const Eigen::MatrixXd& K, const Eigen::VectorXd& n, std::size_t active,
                     Eigen::VectorXd& gain)
{
    const std::size_t L = static_cast<std::size_t>(n.size());
    gain.setZero(n.size());
    const std::size_t lmax = std::min(L, 2 * active);
    for (std::size_t l = 2; l <= lmax; ++l) {
        double g = 0.0;
        const std::size_t ilo = l > active ? l - active : 1;
        for (std::size_t i = ilo; 2 * i < l; ++i) {
            const std::size_t j = l - i;
            g += K(static_cast<Eigen::Index>(i - 1), static_cast<Eigen::Index>(j - 1))
                 * n[static_cast<Eigen::Index>(i - 1)] * n[static_cast<Eigen::Index>(j - 1)];
        }
        if (l % 2 == 0) {
            const Eigen::Index h = static_cast<Eigen::Index>(l / 2 - 1);
            g += 0.5 * K(h, h) * n[h] * n[h];
        }
        gain[static_cast<Eigen::Index>(l - 1)] = g;
    }
}

std::size_t activeSize(const Eigen::VectorXd& n)
{
    for (Eigen::Index i = n.size(); i > 0; --i) {
        if (n[i - 1] != 0.0) return static_cast<std::size_t>(i);
    }
    return 0;
}

} // namespace

// ---------------------------------------------------------------- DiscreteSmoluchowski

DiscreteSmoluchowski::DiscreteSmoluchowski(const CoagulationKernel& kernel, std::size_t L,
                                           const Eigen::VectorXd& source)
    : L_(L), K_(coag::kernelMatrix(kernel, L)), F_(Eigen::VectorXd::Zero(static_cast<Eigen::Index>(L)))
{
    if (source.size() != 0) {
        if (static_cast<std::size_t>(source.size()) > L) {
            throw std::invalid_argument("coag::DiscreteSmoluchowski: source vector longer than L");
        }
        F_.head(source.size()) = source;
    }
}

void DiscreteSmoluchowski::setTolerances(double relTol, double absTol)
{
    if (!(relTol > 0.0) || !(absTol >= 0.0)) {
        throw std::invalid_argument("coag::DiscreteSmoluchowski::setTolerances: need relTol > 0, "
                                    "absTol >= 0");
    }
    relTol_ = relTol;
    absTol_ = absTol;
}

void DiscreteSmoluchowski::rhs(const Eigen::VectorXd& n, Eigen::VectorXd& out) const
{
    const std::size_t active = activeSize(n);
    Eigen::VectorXd gain;
    convolutionGain(K_, n, active, gain);
    if (active == 0) {
        out = F_;
        return;
    }
    const Eigen::Index a = static_cast<Eigen::Index>(active);
    const Eigen::VectorXd Kn = K_.leftCols(a) * n.head(a);
    out = F_ + gain - n.cwiseProduct(Kn);
}

Eigen::VectorXd DiscreteSmoluchowski::rhs(const Eigen::VectorXd& n) const
{
    if (static_cast<std::size_t>(n.size()) != L_) {
        throw std::invalid_argument("coag::DiscreteSmoluchowski::rhs: vector size must be L");
    }
    Eigen::VectorXd out;
    rhs(n, out);
    return out;
}

Eigen::VectorXd integrateDormandPrince(const OdeRhs& f, const Eigen::VectorXd& y0, double t0,
                                       double t1, double relTol, double absTol,
                                       std::size_t& accepted, std::size_t& rejected,
                                       const char* who)
{
    accepted = 0;
    rejected = 0;
    Eigen::VectorXd y = y0;
    if (t1 == t0) return y;

    // Dormand–Prince 5(4) tableau.
    constexpr double c2 = 1.0 / 5, c3 = 3.0 / 10, c4 = 4.0 / 5, c5 = 8.0 / 9;
    constexpr double a21 = 1.0 / 5;
    constexpr double a31 = 3.0 / 40, a32 = 9.0 / 40;
    constexpr double a41 = 44.0 / 45, a42 = -56.0 / 15, a43 = 32.0 / 9;
    constexpr double a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561,
                     a54 = -212.0 / 729;
    constexpr double a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247,
                     a64 = 49.0 / 176, a65 = -5103.0 / 18656;
    constexpr double b1 = 35.0 / 384, b3 = 500.0 / 1113, b4 = 125.0 / 192, b5 = -2187.0 / 6784,
                     b6 = 11.0 / 84;
    constexpr double e1 = 71.0 / 57600, e3 = -71.0 / 16695, e4 = 71.0 / 1920,
                     e5 = -17253.0 / 339200, e6 = 22.0 / 525, e7 = -1.0 / 40;
    (void)c2;
    (void)c3;
    (void)c4;
    (void)c5;  // autonomous system: the stage times are not needed

    const Eigen::Index n = y.size();
    Eigen::VectorXd k1(n), k2(n), k3(n), k4(n), k5(n), k6(n), k7(n), ys(n), ynew(n), err(n);
    f(y, k1);

    auto norm = [&](const Eigen::VectorXd& e, const Eigen::VectorXd& ya, const Eigen::VectorXd& yb) {
        double s = 0.0;
        for (Eigen::Index i = 0; i < n; ++i) {
            const double sc = absTol + relTol * std::max(std::abs(ya[i]), std::abs(yb[i]));
            const double r = sc > 0.0 ? e[i] / sc : (e[i] == 0.0 ? 0.0 : 1e300);
            s += r * r;
        }
        return std::sqrt(s / static_cast<double>(n));
    };

    // Initial step (Hairer, Norsett & Wanner, II.4).
    double h;
    {
        const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n);
        const double d0 = norm(y, y, zero);
        const double d1 = norm(k1, y, zero);
        h = (d0 < 1e-5 || d1 < 1e-5) ? 1e-6 : 0.01 * d0 / d1;
        h = std::min(h, t1 - t0);
    }

    double t = t0;
    const double hmin = 1e-14 * std::max(1.0, std::abs(t1));
    while (t < t1) {
        bool last = false;
        if (t + h >= t1) {
            h = t1 - t;
            last = true;
        }
        ys = y + h * a21 * k1;
        f(ys, k2);
        ys = y + h * (a31 * k1 + a32 * k2);
        f(ys, k3);
        ys = y + h * (a41 * k1 + a42 * k2 + a43 * k3);
        f(ys, k4);
        ys = y + h * (a51 * k1 + a52 * k2 + a53 * k3 + a54 * k4);
        f(ys, k5);
        ys = y + h * (a61 * k1 + a62 * k2 + a63 * k3 + a64 * k4 + a65 * k5);
        f(ys, k6);
        ynew = y + h * (b1 * k1 + b3 * k3 + b4 * k4 + b5 * k5 + b6 * k6);
        f(ynew, k7);
        err = h * (e1 * k1 + e3 * k3 + e4 * k4 + e5 * k5 + e6 * k6 + e7 * k7);
        const double en = norm(err, y, ynew);
        if (en <= 1.0) {
            ++accepted;
            t = last ? t1 : t + h;
            y.swap(ynew);
            k1.swap(k7);  // FSAL
            const double fac = en > 0.0 ? 0.9 * std::pow(en, -0.2) : 5.0;
            h *= std::min(5.0, std::max(0.2, fac));
        } else {
            ++rejected;
            h *= std::max(0.2, 0.9 * std::pow(en, -0.2));
        }
        if (h < hmin && t < t1) {
            throw std::runtime_error(std::string(who) + ": step size underflow");
        }
    }
    return y;
}

Eigen::VectorXd DiscreteSmoluchowski::integrate(const Eigen::VectorXd& n0, double t0,
                                                double t1) const
{
    if (static_cast<std::size_t>(n0.size()) != L_) {
        throw std::invalid_argument("coag::DiscreteSmoluchowski::integrate: vector size must be L");
    }
    if (!(t1 >= t0)) {
        throw std::invalid_argument("coag::DiscreteSmoluchowski::integrate: need t1 >= t0");
    }
    return integrateDormandPrince(
        [this](const Eigen::VectorXd& n, Eigen::VectorXd& out) { rhs(n, out); }, n0, t0, t1,
        relTol_, absTol_, accepted_, rejected_, "coag::DiscreteSmoluchowski::integrate");
}

// ---------------------------------------------------------- FiniteDifferenceSmoluchowski

FiniteDifferenceSmoluchowski::FiniteDifferenceSmoluchowski(const CoagulationKernel& kernel,
                                                           const std::vector<double>& initialDensity,
                                                           double alpha, std::size_t maxSize)
    : L_(maxSize), alpha_(alpha)
{
    if (!(alpha > 0.0 && alpha <= 1.0)) {
        std::ostringstream os;
        os << "coag::FiniteDifferenceSmoluchowski: alpha must be in (0,1], got " << alpha;
        throw std::invalid_argument(os.str());
    }
    if (initialDensity.empty() || initialDensity.size() > maxSize) {
        throw std::invalid_argument("coag::FiniteDifferenceSmoluchowski: initial density must "
                                    "have 1..maxSize entries");
    }
    double total = 0.0;
    L0_ = 0;
    for (std::size_t l = 0; l < initialDensity.size(); ++l) {
        if (!(initialDensity[l] >= 0.0) || !std::isfinite(initialDensity[l])) {
            throw std::invalid_argument("coag::FiniteDifferenceSmoluchowski: initial density "
                                        "must be finite and >= 0");
        }
        total += initialDensity[l];
        if (initialDensity[l] > 0.0) L0_ = l + 1;
    }
    if (!(total > 0.0)) {
        throw std::invalid_argument("coag::FiniteDifferenceSmoluchowski: initial density is zero");
    }
    K_ = coag::kernelMatrix(kernel, L_);
    n_ = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(L_));
    for (std::size_t l = 0; l < initialDensity.size(); ++l) {
        n_[static_cast<Eigen::Index>(l)] = initialDensity[l];
    }
}

double FiniteDifferenceSmoluchowski::density(std::size_t l) const
{
    if (l < 1 || l > L_) return 0.0;
    return n_[static_cast<Eigen::Index>(l - 1)];
}

double FiniteDifferenceSmoluchowski::step()
{
    const std::size_t active = std::max<std::size_t>(1, activeSize(n_));
    const Eigen::Index a = static_cast<Eigen::Index>(active);
    Kn_ = K_.leftCols(a) * n_.head(a);
    const std::size_t range = cappedDoublingRange(L0_, k_, L_);
    const double maxRate = Kn_.head(static_cast<Eigen::Index>(range)).maxCoeff();
    if (!(maxRate > 0.0)) {
        throw std::runtime_error("coag::FiniteDifferenceSmoluchowski::step: zero coagulation rate");
    }
    const double delta = alpha_ / maxRate;
    convolutionGain(K_, n_, active, gain_);
    n_ += delta * (gain_ - n_.cwiseProduct(Kn_));
    t_ += delta;
    ++k_;
    return delta;
}

} // namespace coag
