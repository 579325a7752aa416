// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#include "coagulationReferences/smoluchowski/SectionalSmoluchowski.hpp"

#include "coagulationReferences/smoluchowski/SmoluchowskiReference.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace coag {

std::size_t SectionalGrid::section(double x) const
{
    if (edges.empty() || x < edges.front()) {
        throw std::out_of_range("coag::SectionalGrid::section: mass below the grid");
    }
    const auto it = std::upper_bound(edges.begin(), edges.end(), x);
    return static_cast<std::size_t>(it - edges.begin()) - 1;
}

SectionalGrid geometricGrid(double xmin, double xmax, unsigned perDoubling)
{
    if (!(xmin > 0.0) || !(xmax > xmin) || !std::isfinite(xmax) || perDoubling == 0) {
        throw std::invalid_argument(
            "coag::geometricGrid: need 0 < xmin < xmax (finite) and perDoubling >= 1");
    }
    const double r = std::pow(2.0, 1.0 / perDoubling);
    const double h = std::sqrt(r);
    SectionalGrid g;
    for (std::size_t i = 0;; ++i) {
        const double x = xmin * std::pow(r, static_cast<double>(i));
        g.pivots.push_back(x);
        g.edges.push_back(x / h);
        if (x >= xmax * (1.0 - 1e-12)) break;  // a pivot at xmax despite round-off
    }
    g.edges.push_back(g.pivots.back() * h);
    return g;
}

SectionalGrid discreteGeometricGrid(double xmax, unsigned perDoubling)
{
    if (!(xmax > 1.0) || !std::isfinite(xmax) || perDoubling == 0) {
        throw std::invalid_argument(
            "coag::discreteGeometricGrid: need xmax > 1 (finite) and perDoubling >= 1");
    }
    const double r = std::pow(2.0, 1.0 / perDoubling);
    const std::size_t m = static_cast<std::size_t>(std::ceil(1.0 / (r - 1.0)));
    SectionalGrid g;
    for (std::size_t l = 1; l <= m; ++l) {
        g.edges.push_back(static_cast<double>(l) - 0.5);
        g.pivots.push_back(static_cast<double>(l));
    }
    double e = static_cast<double>(m) + 0.5;
    g.edges.push_back(e);
    while (e < xmax) {
        g.pivots.push_back(e * std::sqrt(r));
        e *= r;
        g.edges.push_back(e);
    }
    return g;
}

SectionalSmoluchowski::SectionalSmoluchowski(const CoagulationKernel& kernel, SectionalGrid grid)
    : grid_(std::move(grid))
{
    const std::size_t L = grid_.size();
    bool ok = L >= 2 && L <= maxDenseKernelSize && grid_.edges.size() == L + 1;
    for (std::size_t i = 0; ok && i < L; ++i) {
        ok = grid_.edges[i] > 0.0 && grid_.edges[i] <= grid_.pivots[i]
             && grid_.pivots[i] < grid_.edges[i + 1] && std::isfinite(grid_.edges[i + 1]);
    }
    if (!ok) {
        std::ostringstream os;
        os << "coag::SectionalSmoluchowski: need 2 to " << maxDenseKernelSize
           << " sections with edges[i] <= pivots[i] < edges[i+1], edges > 0; got " << L
           << " pivots and " << grid_.edges.size() << " edges";
        throw std::invalid_argument(os.str());
    }
    const Eigen::Index n = static_cast<Eigen::Index>(L);
    K_.resize(n, n);
    target_.assign(L * L, 0u);
    for (std::size_t j = 0; j < L; ++j) {
        for (std::size_t k = j; k < L; ++k) {
            const double v = kernel(ParticleType{grid_.pivots[j]}, ParticleType{grid_.pivots[k]});
            K_(Eigen::Index(j), Eigen::Index(k)) = v;
            K_(Eigen::Index(k), Eigen::Index(j)) = v;
            target_[j * L + k] =
                static_cast<unsigned>(grid_.section(grid_.pivots[j] + grid_.pivots[k]));
        }
    }
    B_.resize(n);
    V_.resize(n);
}

void SectionalSmoluchowski::distribute(std::size_t i, double count, double mean, double* out,
                                       double* lost) const
{
    const std::vector<double>& x = grid_.pivots;
    const std::size_t L = x.size();
    if (mean >= x[i]) {
        if (i + 1 < L) {
            // a x_i + (1 - a) x_{i+1} = mean
            const double a = (x[i + 1] - mean) / (x[i + 1] - x[i]);
            out[i] += a * count;
            out[i + 1] += (1.0 - a) * count;
        } else {
            out[i] += count;
            *lost += count * (mean - x[i]);
        }
    } else if (i > 0) {
        const double a = (mean - x[i - 1]) / (x[i] - x[i - 1]);
        out[i] += a * count;
        out[i - 1] += (1.0 - a) * count;
    } else {
        out[i] += count;
        *lost += count * (mean - x[i]);  // negative: mass gained by lifting to the first pivot
    }
}

Eigen::VectorXd SectionalSmoluchowski::fromSections(const std::vector<double>& number,
                                                    const std::vector<double>& mass) const
{
    const std::size_t L = size();
    if (number.size() != L || mass.size() != L) {
        throw std::invalid_argument("coag::SectionalSmoluchowski::fromSections: need L values");
    }
    Eigen::VectorXd N = Eigen::VectorXd::Zero(Eigen::Index(L));
    double ignored = 0.0;
    for (std::size_t i = 0; i < L; ++i) {
        if (number[i] > 0.0) distribute(i, number[i], mass[i] / number[i], N.data(), &ignored);
    }
    return N;
}

Eigen::VectorXd SectionalSmoluchowski::monodisperse(double N0, double x) const
{
    std::vector<double> number(size(), 0.0), mass(size(), 0.0);
    const std::size_t i = grid_.section(x);
    if (i >= size()) throw std::out_of_range("coag::SectionalSmoluchowski: mass beyond the grid");
    number[i] = N0;
    mass[i] = N0 * x;
    return fromSections(number, mass);
}

Eigen::VectorXd SectionalSmoluchowski::lognormal(double N0, double medianMass,
                                                 double lnSigmaMass) const
{
    // number in [a, b): N0 P(u(a), u(b)), P the standard normal probability between, u(x) =
    // ln(x/xg)/s; mass: N0 xg e^{s^2/2} P(u(a) - s, u(b) - s) (the mass-weighted lognormal).
    // P from erfc of the side away from the median, so tails keep their relative accuracy.
    const double s = lnSigmaMass;
    auto P = [](double ua, double ub) {
        const double r = 1.0 / std::sqrt(2.0);
        if (ua >= 0.0) return 0.5 * (std::erfc(ua * r) - std::erfc(ub * r));
        if (ub <= 0.0) return 0.5 * (std::erfc(-ub * r) - std::erfc(-ua * r));
        return 1.0 - 0.5 * (std::erfc(-ua * r) + std::erfc(ub * r));
    };
    const double meanMass = medianMass * std::exp(0.5 * s * s);
    std::vector<double> number(size()), mass(size());
    for (std::size_t i = 0; i < size(); ++i) {
        const double a = grid_.edges[i], b = grid_.edges[i + 1];
        const double ua = std::log(a / medianMass) / s, ub = std::log(b / medianMass) / s;
        number[i] = N0 * P(ua, ub);
        // the section's mean mass lies in [a, b); clamp what round-off could push outside
        mass[i] = std::clamp(N0 * meanMass * P(ua - s, ub - s), a * number[i], b * number[i]);
    }
    return fromSections(number, mass);
}

Eigen::VectorXd SectionalSmoluchowski::rhs(const Eigen::VectorXd& N, double* lostRate) const
{
    const Eigen::Index L = Eigen::Index(size());
    Eigen::VectorXd y(L + 1), out(L + 1);
    y.head(L) = N;
    y[L] = 0.0;
    rhsAugmented(y, out);
    if (lostRate) *lostRate = out[L];
    return out.head(L);
}

void SectionalSmoluchowski::rhsAugmented(const Eigen::VectorXd& y, Eigen::VectorXd& out) const
{
    const std::size_t L = size();
    const Eigen::Index n = Eigen::Index(L);
    const double* N = y.data();
    const double* x = grid_.pivots.data();
    out.resize(n + 1);
    // loss: N_i sum_k K_ik N_k
    out.head(n).noalias() = -(K_ * y.head(n)).cwiseProduct(y.head(n));
    B_.setZero();
    V_.setZero();
    double lost = 0.0;
    double* B = B_.data();
    double* V = V_.data();
    for (std::size_t j = 0; j < L; ++j) {
        if (N[j] == 0.0) continue;
        const double* Kj = K_.data() + j * L;  // column j = row j (symmetric)
        const unsigned* tj = target_.data() + j * L;
        {
            const double r = 0.5 * Kj[j] * N[j] * N[j];
            const unsigned c = tj[j];
            if (c < L) {
                B[c] += r;
                V[c] += r * 2.0 * x[j];
            } else {
                lost += r * 2.0 * x[j];
            }
        }
        for (std::size_t k = j + 1; k < L; ++k) {
            const double r = Kj[k] * N[j] * N[k];
            const unsigned c = tj[k];
            if (c < L) {
                B[c] += r;
                V[c] += r * (x[j] + x[k]);
            } else {
                lost += r * (x[j] + x[k]);
            }
        }
    }
    for (std::size_t i = 0; i < L; ++i) {
        if (B[i] > 0.0) distribute(i, B[i], V[i] / B[i], out.data(), &lost);
    }
    out[n] = lost;
}

Eigen::VectorXd SectionalSmoluchowski::integrate(const Eigen::VectorXd& N0, double t0, double t1)
{
    const Eigen::Index n = Eigen::Index(size());
    if (N0.size() != n) {
        throw std::invalid_argument("coag::SectionalSmoluchowski::integrate: need L values");
    }
    Eigen::VectorXd y(n + 1);
    y.head(n) = N0;
    y[n] = 0.0;
    const OdeRhs f = [this](const Eigen::VectorXd& z, Eigen::VectorXd& out) {
        rhsAugmented(z, out);
    };
    y = integrateDormandPrince(f, y, t0, t1, relTol_, absTol_, accepted_, rejected_,
                               "coag::SectionalSmoluchowski::integrate");
    lost_ += y[n];
    return y.head(n);
}

void SectionalSmoluchowski::setTolerances(double relTol, double absTol)
{
    if (!(relTol > 0.0) || !(absTol > 0.0)) {
        throw std::invalid_argument("coag::SectionalSmoluchowski: tolerances must be > 0");
    }
    relTol_ = relTol;
    absTol_ = absTol;
}

double SectionalSmoluchowski::moment(const Eigen::VectorXd& N, double k) const
{
    double m = 0.0;
    for (std::size_t i = 0; i < size(); ++i) m += N[Eigen::Index(i)] * std::pow(grid_.pivots[i], k);
    return m;
}

double SectionalSmoluchowski::numberBetween(const Eigen::VectorXd& N, double a, double b) const
{
    double s = 0.0;
    for (std::size_t i = 0; i < size(); ++i) {
        if (grid_.pivots[i] >= a && grid_.pivots[i] < b) s += N[Eigen::Index(i)];
    }
    return s;
}

double SectionalSmoluchowski::geometricStdDevDiameter(const Eigen::VectorXd& N) const
{
    double s0 = 0.0, s1 = 0.0, s2 = 0.0;
    for (std::size_t i = 0; i < size(); ++i) {
        const double w = N[Eigen::Index(i)], l = std::log(grid_.pivots[i]);
        s0 += w;
        s1 += w * l;
        s2 += w * l * l;
    }
    const double mean = s1 / s0;
    return std::exp(std::sqrt(std::max(0.0, s2 / s0 - mean * mean)) / 3.0);
}

} // namespace coag
