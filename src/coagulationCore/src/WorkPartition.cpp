// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#include "coagulation/WorkPartition.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace coag {

namespace {

//- Parts the greedy pass needs with bottleneck B (B >= every weight)
std::size_t partsNeeded(const std::vector<double>& w, double B)
{
    std::size_t parts = 1;
    double sum = 0.0;
    for (const double x : w) {
        if (sum + x > B) {
            ++parts;
            sum = x;
        } else {
            sum += x;
        }
    }
    return parts;
}

} // namespace

std::vector<std::size_t> partitionContiguous(const std::vector<double>& w, std::size_t k)
{
    const std::size_t n = w.size();
    if (k < 1 || k > n) {
        std::ostringstream os;
        os << "coag::partitionContiguous: " << k << " parts of " << n
           << " items (need 1 <= parts <= items)";
        throw std::invalid_argument(os.str());
    }
    double total = 0.0, largest = 0.0;
    for (const double x : w) {
        if (!(x >= 0.0) || !std::isfinite(x)) {
            throw std::invalid_argument(
                "coag::partitionContiguous: weights must be finite and >= 0");
        }
        total += x;
        largest = std::max(largest, x);
    }
    if (!std::isfinite(total)) {
        throw std::invalid_argument("coag::partitionContiguous: the weights' sum overflows");
    }

    // Smallest feasible bottleneck: lo infeasible (or the lower bound), hi feasible
    double lo = std::max(largest, total / static_cast<double>(k));
    double hi = total;
    if (partsNeeded(w, lo) <= k) {
        hi = lo;
    } else {
        for (int it = 0; it < 200 && hi - lo > 1e-13 * hi; ++it) {
            const double mid = 0.5 * (lo + hi);
            if (partsNeeded(w, mid) <= k) hi = mid;
            else lo = mid;
        }
    }

    // The greedy pass at hi, no part left empty
    std::vector<std::size_t> b(1, 0);
    double sum = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t partsLeft = k - (b.size() - 1);  // including the open one
        const std::size_t itemsLeft = n - i;
        const bool open = i > b.back();                     // the open part has items
        if (open && partsLeft > 1 && (sum + w[i] > hi || itemsLeft == partsLeft - 1)) {
            b.push_back(i);
            sum = 0.0;
        }
        sum += w[i];
    }
    b.push_back(n);
    return b;
}

double largestPart(const std::vector<double>& w, const std::vector<std::size_t>& bounds)
{
    double largest = 0.0;
    for (std::size_t p = 0; p + 1 < bounds.size(); ++p) {
        double s = 0.0;
        for (std::size_t i = bounds[p]; i < bounds[p + 1]; ++i) s += w[i];
        largest = std::max(largest, s);
    }
    return largest;
}

} // namespace coag
