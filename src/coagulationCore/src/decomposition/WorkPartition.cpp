// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#include "coagulation/decomposition/WorkPartition.hpp"

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

std::vector<std::size_t> partitionRuns(const std::vector<double>& w, std::size_t k,
                                       std::size_t maxRuns)
{
    if (maxRuns == 0) {
        throw std::invalid_argument("coag::partitionRuns: at most 0 runs per part");
    }
    const std::size_t n = w.size();
    std::vector<std::size_t> best;
    double bestLargest = 0.0;
    for (std::size_t m = 1; m <= maxRuns && (m == 1 || m * k <= n); ++m) {
        const std::vector<std::size_t> b = partitionContiguous(w, m * k);
        const std::size_t runs = b.size() - 1;
        std::vector<double> runSum(runs, 0.0);
        for (std::size_t r = 0; r < runs; ++r) {
            for (std::size_t i = b[r]; i < b[r + 1]; ++i) runSum[r] += w[i];
        }
        // LPT: the runs largest first (earlier first on ties) to the least loaded part
        std::vector<std::size_t> order(runs);
        for (std::size_t r = 0; r < runs; ++r) order[r] = r;
        std::stable_sort(order.begin(), order.end(),
                         [&](std::size_t a, std::size_t c) { return runSum[a] > runSum[c]; });
        std::vector<double> load(k, 0.0);
        std::vector<std::size_t> part(n, 0);
        for (const std::size_t r : order) {
            std::size_t p = r;  // one run per part: the cut, its parts in order
            if (m > 1) {
                p = 0;
                for (std::size_t q = 1; q < k; ++q) {
                    if (load[q] < load[p]) p = q;
                }
            }
            load[p] += runSum[r];
            for (std::size_t i = b[r]; i < b[r + 1]; ++i) part[i] = p;
        }
        const double largest = *std::max_element(load.begin(), load.end());
        if (best.empty() || largest < bestLargest) {
            best = std::move(part);
            bestLargest = largest;
        }
    }
    return best;
}

double largestShare(const std::vector<double>& w, const std::vector<std::size_t>& part,
                    std::size_t k)
{
    std::vector<double> load(k, 0.0);
    for (std::size_t i = 0; i < w.size(); ++i) load.at(part.at(i)) += w[i];
    return k == 0 ? 0.0 : *std::max_element(load.begin(), load.end());
}

} // namespace coag
