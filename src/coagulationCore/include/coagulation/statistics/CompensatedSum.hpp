// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_COMPENSATEDSUM_HPP
#define COAGULATION_COMPENSATEDSUM_HPP

#include <cmath>

namespace coag {

//- A sum with Neumaier's compensation of the rounding errors: good to about one rounding
//  of the result whatever the number of terms. A plain sum of N equal terms (a monodisperse
//  population's mass) rounds the same way for long runs of additions, an error up to N/2
//  roundings: 1e-11 of the sum for 2.5e5 particles, more than the balances allow.
class CompensatedSum {
public:
    void add(double x)
    {
        const double t = sum_ + x;
        // The low-order bits lost in t, from the smaller of the two
        compensation_ += std::abs(sum_) >= std::abs(x) ? (sum_ - t) + x : (x - t) + sum_;
        sum_ = t;
    }

    double value() const { return sum_ + compensation_; }

private:
    double sum_ = 0.0;
    double compensation_ = 0.0;
};

} // namespace coag

#endif
