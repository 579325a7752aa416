// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#include "coagulation/output/SizeDistribution.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace coag {

namespace {
const double nan = std::numeric_limits<double>::quiet_NaN();
const double pi = 3.14159265358979323846;
}

// ---------------------------------------------------------------------------- SizeBins

SizeBins SizeBins::logarithmic(double min, double max, std::size_t nBins)
{
    if (!(min > 0) || !(max > min) || !std::isfinite(max) || nBins < 1) {
        throw std::invalid_argument("log size bins need 0 < min < max (finite) and nBins >= 1");
    }
    SizeBins b;
    b.integer_ = false;
    b.logMin_ = std::log(min);
    b.logWidth_ = (std::log(max) - b.logMin_) / double(nBins);
    b.edges_.resize(nBins + 1);
    for (std::size_t i = 0; i <= nBins; ++i) {
        b.edges_[i] = std::exp(b.logMin_ + double(i) * b.logWidth_);
    }
    b.edges_.front() = min;
    b.edges_.back() = max;
    return b;
}


SizeBins SizeBins::integer(std::size_t K)
{
    if (K < 1) {
        throw std::invalid_argument("integer size bins need K >= 1");
    }
    SizeBins b;
    b.integer_ = true;
    b.edges_.resize(K + 1);
    for (std::size_t i = 0; i <= K; ++i) {
        b.edges_[i] = double(i) + 0.5;
    }
    return b;
}


double SizeBins::centre(std::size_t i) const
{
    return integer_ ? double(i + 1) : std::sqrt(edges_[i] * edges_[i + 1]);
}


std::size_t SizeBins::index(double m) const
{
    if (!(m >= edges_.front())) {
        return underflow();
    }
    if (m >= edges_.back()) {
        return overflow();
    }
    std::size_t i;
    if (integer_) {
        i = std::size_t(std::floor(m - 0.5));
    } else {
        i = std::size_t(std::floor((std::log(m) - logMin_) / logWidth_));
    }
    // round-off at an edge: the edges decide
    i = std::min(i, size() - 1);
    while (i > 0 && m < edges_[i]) --i;
    while (i + 1 < size() && m >= edges_[i + 1]) ++i;
    return i;
}

// ------------------------------------------------------------------------ DerivedSizes

std::vector<std::string> DerivedSizes::names()
{
    return {"M0", "meanMass", "geometricMeanMass", "gsd", "medianMass", "d10", "d32", "d43"};
}


std::vector<double> DerivedSizes::values() const
{
    return {M0, meanMass, geometricMean, gsd, median, d10, d32, d43};
}

// -------------------------------------------------------------------------- sizeSample

SizeSample sizeSample(const std::vector<double>& masses, const std::vector<double>& weights,
                      double volume, const SizeBins& bins, double density, double massUnit)
{
    if (masses.size() != weights.size()) {
        throw std::invalid_argument("sizeSample: masses and weights differ in length");
    }
    if (!(volume > 0)) {
        throw std::invalid_argument("sizeSample: the volume must be positive");
    }
    SizeSample s;
    s.numberDensity.assign(bins.size(), 0.0);
    const std::size_t n = masses.size();
    double w0 = 0, w1 = 0, wl = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const double w = weights[i], m = masses[i];
        const std::size_t b = bins.index(m);
        if (b == bins.underflow()) s.underflow += w;
        else if (b == bins.overflow()) s.overflow += w;
        else s.numberDensity[b] += w;
        w0 += w;
        w1 += w * m;
        wl += w * std::log(m);
    }
    for (double& v : s.numberDensity) v /= volume;
    s.underflow /= volume;
    s.overflow /= volume;

    DerivedSizes& d = s.derived;
    d.M0 = w0 / volume;
    if (!(w0 > 0)) {
        d.meanMass = d.geometricMean = d.gsd = d.median = d.d10 = d.d32 = d.d43 = nan;
        return s;
    }
    d.meanMass = w1 / w0;
    const double lg = wl / w0;
    d.geometricMean = std::exp(lg);
    double wv = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const double dl = std::log(masses[i]) - lg;
        wv += weights[i] * dl * dl;
    }
    d.gsd = std::exp(std::sqrt(std::max(wv / w0, 0.0)));

    // median of the number distribution: the mass at which the cumulative weight, in
    // increasing mass, reaches half the total (midpoint where it is exactly half)
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return masses[a] < masses[b]; });
    const double half = 0.5 * w0;
    double cum = 0;
    d.median = masses[order.back()];
    for (std::size_t j = 0; j < n; ++j) {
        const std::size_t i = order[j];
        cum += weights[i];
        if (std::abs(cum - half) <= 1e-12 * w0 && j + 1 < n) {
            d.median = 0.5 * (masses[i] + masses[order[j + 1]]);
            break;
        }
        if (cum > half) {
            d.median = masses[i];
            break;
        }
    }

    if (density > 0) {
        double s1 = 0, s2 = 0, s3 = 0, s4 = 0;
        for (std::size_t i = 0; i < n; ++i) {
            const double dia = std::cbrt(6.0 * masses[i] * massUnit / (pi * density));
            const double w = weights[i];
            s1 += w * dia;
            s2 += w * dia * dia;
            s3 += w * dia * dia * dia;
            s4 += w * dia * dia * dia * dia;
        }
        d.d10 = s1 / w0;
        d.d32 = s3 / s2;
        d.d43 = s4 / s3;
    } else {
        d.d10 = d.d32 = d.d43 = nan;
    }
    return s;
}

} // namespace coag
