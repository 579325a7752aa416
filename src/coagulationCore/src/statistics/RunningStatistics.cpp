// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#include "coagulation/statistics/RunningStatistics.hpp"

#include <cmath>
#include <stdexcept>

namespace coag {

void RunningStatistics::add(double x)
{
    ++n_;
    const double delta = x - mean_;
    mean_ += delta / static_cast<double>(n_);
    m2_ += delta * (x - mean_);
}

double RunningStatistics::variance() const
{
    return n_ < 2 ? 0.0 : m2_ / static_cast<double>(n_ - 1);
}

double RunningStatistics::standardDeviation() const { return std::sqrt(variance()); }

double RunningStatistics::standardError() const
{
    return n_ < 2 ? 0.0 : std::sqrt(variance() / static_cast<double>(n_));
}

double RunningStatistics::confidenceHalfWidth95() const { return 1.96 * standardError(); }

void RunningStatistics::merge(const RunningStatistics& o)
{
    if (o.n_ == 0) return;
    if (n_ == 0) {
        *this = o;
        return;
    }
    const double na = static_cast<double>(n_);
    const double nb = static_cast<double>(o.n_);
    const double n = na + nb;
    const double delta = o.mean_ - mean_;
    mean_ += delta * nb / n;
    m2_ += o.m2_ + delta * delta * na * nb / n;
    n_ += o.n_;
}

void RunningStatistics::set(std::size_t n, double mean, double m2)
{
    if (!(m2 >= 0.0)) {
        throw std::invalid_argument("coag::RunningStatistics::set: m2 must be >= 0");
    }
    n_ = n;
    mean_ = n == 0 ? 0.0 : mean;
    m2_ = n == 0 ? 0.0 : m2;
}

} // namespace coag
