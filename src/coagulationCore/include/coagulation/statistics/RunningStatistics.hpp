// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_RUNNINGSTATISTICS_HPP
#define COAGULATION_RUNNINGSTATISTICS_HPP

#include <cstddef>

namespace coag {

//- Streaming mean/variance (Welford), mergeable (Chan, Golub & LeVeque).
class RunningStatistics {
public:
    void add(double x);
    std::size_t count() const { return n_; }
    double mean() const { return mean_; }
    //- Sample variance (n-1 denominator); 0 for fewer than two values.
    double variance() const;
    double standardDeviation() const;
    //- Standard error of the mean, sqrt(variance/n); 0 for fewer than two values.
    double standardError() const;
    //- 1.96 * standardError().
    double confidenceHalfWidth95() const;
    //- Combine with the statistics of another, disjoint, sample (Chan et al.).
    void merge(const RunningStatistics& other);
    //- Sum of squared deviations from the mean.
    double m2() const { return m2_; }
    //- Restore a state (e.g. from a restart file); throws std::invalid_argument for m2 < 0.
    void set(std::size_t n, double mean, double m2);

private:
    std::size_t n_ = 0;
    double mean_ = 0.0;
    double m2_ = 0.0;
};

} // namespace coag

#endif
