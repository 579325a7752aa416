// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_CORRELATEDMEAN_HPP
#define COAGULATION_CORRELATEDMEAN_HPP

#include <cstddef>
#include <vector>

namespace coag {

//- Mean and 95 % interval of the mean of an ordered, equally spaced time series whose
//  samples are correlated: the C++ twin of coagulationPost.statistics.correlated_interval
//  (Sokal's automatic window, c = 5, at most N/4 lags, at least minWindow; tau_int at least
//  1/2; var(mean) = 2 tau_int gamma0/(N - 2M - 1); half-width t_{0.975, N/(2M+1)}
//  sqrt(var(mean)); n_eff = sd^2/var(mean)). Fewer than 4 samples: ci NaN, tauInt 1/2.
struct CorrelatedMean {
    std::size_t count = 0;
    double mean = 0, sd = 0, tauInt = 0.5, neff = 0, ci95 = 0;
    std::size_t window = 0;
};
CorrelatedMean correlatedMean(const std::vector<double>& series, std::size_t minWindow = 0,
                              double c = 5.0);

//- 0.975 quantile of Student's t with nu (real, at least 1) degrees of freedom: Newton on
//  the integral of the density (Simpson) from the Cornish-Fisher expansion; to 1e-8.
double studentT975(double nu);

} // namespace coag

#endif
