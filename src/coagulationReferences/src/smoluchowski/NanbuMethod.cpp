// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#include "coagulationReferences/smoluchowski/NanbuMethod.hpp"
#include "coagulationReferences/smoluchowski/SmoluchowskiReference.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>
#include <stdexcept>

namespace coag {

namespace {

double K(const CoagulationKernel& kernel, std::size_t i, std::size_t j)
{
    return kernel(ParticleType{static_cast<double>(i)}, ParticleType{static_cast<double>(j)});
}

std::int64_t binomial(std::int64_t n, double p, Rng& rng)
{
    if (n <= 0 || p <= 0.0) return 0;
    if (p >= 1.0) return n;
    std::binomial_distribution<std::int64_t> d(n, p);
    return d(rng.engine());
}

} // namespace

NanbuSmoluchowski::NanbuSmoluchowski(const CoagulationKernel& kernel,
                                     const std::vector<std::int64_t>& initialCounts, double c0,
                                     const NanbuParameters& params)
    : kernel_(kernel), params_(params), N_(initialCounts), c_(c0)
{
    if (!(params_.alpha > 0.0 && params_.alpha <= 1.0)) {
        std::ostringstream os;
        os << "coag::NanbuSmoluchowski: alpha must be in (0,1], got " << params_.alpha;
        throw std::invalid_argument(os.str());
    }
    if (!(c0 > 0.0) || !std::isfinite(c0)) {
        throw std::invalid_argument("coag::NanbuSmoluchowski: normalizing constant c0 must be > 0");
    }
    if (params_.maxSize == 0 || initialCounts.size() > params_.maxSize) {
        throw std::invalid_argument("coag::NanbuSmoluchowski: need 1 <= initial sizes <= maxSize");
    }
    L0_ = 0;
    for (std::size_t l = 0; l < N_.size(); ++l) {
        if (N_[l] < 0) {
            throw std::invalid_argument("coag::NanbuSmoluchowski: counts must be >= 0");
        }
        N0_ += N_[l];
        if (N_[l] > 0) L0_ = l + 1;
    }
    if (N0_ <= 0) {
        throw std::invalid_argument("coag::NanbuSmoluchowski: no particles in the initial state");
    }
    N_.resize(L0_);
}

NanbuSmoluchowski NanbuSmoluchowski::fromDensity(const CoagulationKernel& kernel,
                                                 const std::vector<double>& initialDensity,
                                                 std::int64_t N, const NanbuParameters& params)
{
    double total = 0.0;
    for (double v : initialDensity) {
        if (!(v >= 0.0) || !std::isfinite(v)) {
            throw std::invalid_argument("coag::NanbuSmoluchowski::fromDensity: densities must be "
                                        "finite and >= 0");
        }
        total += v;
    }
    if (!(total > 0.0) || N <= 0) {
        throw std::invalid_argument("coag::NanbuSmoluchowski::fromDensity: need a positive "
                                    "density and N > 0");
    }
    const double c0 = static_cast<double>(N) / total;
    std::vector<std::int64_t> counts(initialDensity.size());
    for (std::size_t l = 0; l < counts.size(); ++l) {
        counts[l] = static_cast<std::int64_t>(std::llround(c0 * initialDensity[l]));
    }
    return NanbuSmoluchowski(kernel, counts, c0, params);
}

std::int64_t NanbuSmoluchowski::count(std::size_t l) const
{
    return (l >= 1 && l <= N_.size()) ? N_[l - 1] : 0;
}

std::vector<double> NanbuSmoluchowski::densities() const
{
    std::vector<double> d(N_.size());
    for (std::size_t l = 0; l < N_.size(); ++l) d[l] = static_cast<double>(N_[l]) / c_;
    return d;
}

std::int64_t NanbuSmoluchowski::totalCount() const
{
    std::int64_t s = 0;
    for (std::int64_t v : N_) s += v;
    return s;
}

std::size_t NanbuSmoluchowski::largestSize() const
{
    for (std::size_t l = N_.size(); l > 0; --l) {
        if (N_[l - 1] > 0) return l;
    }
    return 0;
}

double NanbuSmoluchowski::step(Rng& rng)
{
    occupied_.clear();
    for (std::size_t l = 1; l <= N_.size(); ++l) {
        if (N_[l - 1] > 0) occupied_.push_back(l);
    }
    if (occupied_.empty()) {
        throw std::runtime_error("coag::NanbuSmoluchowski::step: the particle system is empty");
    }

    // (2.12): Delta = alpha / max_{i <= min(2^k L0, maxSize)} sum_j N_j/c K_ij.
    // Occupied sizes never exceed 2^k L0 (2.26) or maxSize, so rate_ covers them.
    const std::size_t range = cappedDoublingRange(L0_, k_, params_.maxSize);
    rate_.assign(range + 1, 0.0);
    double maxRate = 0.0;
    for (std::size_t i = 1; i <= range; ++i) {
        double s = 0.0;
        for (std::size_t m : occupied_) s += static_cast<double>(N_[m - 1]) * K(kernel_, i, m);
        rate_[i] = s;
        maxRate = std::max(maxRate, s);
    }
    if (!(maxRate > 0.0)) {
        throw std::runtime_error("coag::NanbuSmoluchowski::step: zero coagulation rate");
    }
    const double delta = params_.alpha * c_ / maxRate;

    // (2.15)-(2.18)
    const std::size_t largest = occupied_.back();
    Np_.assign(std::min(2 * largest, params_.maxSize), 0);
    std::copy(N_.begin(), N_.end(), Np_.begin());
    for (std::size_t l : occupied_) {
        const double P = 0.5 * delta * rate_[l] / c_;
        std::int64_t remaining = binomial(N_[l - 1], P, rng);
        if (remaining == 0) continue;
        stats_.reactions += static_cast<std::uint64_t>(remaining);
        // Partner sizes: multinomial(remaining; N_m K_lm / sum_j N_j K_lj) as sequential
        // conditional binomials.
        double restWeight = rate_[l];
        for (std::size_t idx = 0; idx < occupied_.size() && remaining > 0; ++idx) {
            const std::size_t m = occupied_[idx];
            const double w = static_cast<double>(N_[m - 1]) * K(kernel_, l, m);
            const bool lastSize = idx + 1 == occupied_.size();
            const double q = (lastSize || !(restWeight > w)) ? 1.0 : w / restWeight;
            restWeight -= w;
            const std::int64_t k = binomial(remaining, q, rng);
            if (k == 0) continue;
            remaining -= k;
            Np_[l - 1] -= k;
            Np_[m - 1] -= k;
            if (l + m <= params_.maxSize) {
                Np_[l + m - 1] += k;
            } else {
                stats_.overflowParticles += static_cast<std::uint64_t>(k);
            }
        }
    }

    // (2.19) truncation, (2.20)-(2.22) doubling.
    std::int64_t total = 0;
    for (std::int64_t& v : Np_) {
        if (v < 0) {
            ++stats_.truncatedComponents;
            stats_.truncatedParticles += static_cast<std::uint64_t>(-v);
            v = 0;
        }
        total += v;
    }
    if (2 * total <= N0_) {
        for (std::int64_t& v : Np_) v *= 2;
        c_ *= 2.0;
        ++stats_.doublings;
    }
    while (!Np_.empty() && Np_.back() == 0) Np_.pop_back();
    N_.swap(Np_);

    t_ += delta;
    ++k_;
    ++stats_.steps;
    return delta;
}

} // namespace coag
