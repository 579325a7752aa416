// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_WORKPARTITION_HPP
#define COAGULATION_WORKPARTITION_HPP

#include <cstddef>
#include <vector>

namespace coag {

//- The linear partition problem: w[0..n) cut into k contiguous, non-empty parts so that the
//  largest part sum is as small as possible. Returns the k + 1 boundaries b (b[0] = 0,
//  b[k] = n; part p is [b[p], b[p+1])).
//
//  Why not the cumulative-weight split of OpenFOAM's simple/hierarchical decomposition: that
//  one gives item i to part floor(k * (sum before i) / total), so a heavy item that straddles
//  a part's share stays with the part it starts in. On the additive duct of issue 19, with
//  events counted at half a particle (the last three of 50 cells holding 12, 17 and 24 % of
//  the work), it left 59 % on one of 2 ranks where 52 % was possible.
//
//  Method: the smallest bottleneck B for which the greedy pass (close a part when the next
//  item would take it above B) needs at most k parts, by bisection between max(w) and
//  sum(w) to a relative 1e-13 (at most 200 passes, O(n) each); then the greedy pass at the
//  feasible end, closing a part early where the items left only just fill the parts left,
//  so that none is empty. Weights must be finite and >= 0; k in [1, n]. Throws
//  std::invalid_argument otherwise.
std::vector<std::size_t> partitionContiguous(const std::vector<double>& w, std::size_t k);

//- The largest part sum of a partition given by its boundaries
double largestPart(const std::vector<double>& w, const std::vector<std::size_t>& bounds);

} // namespace coag

#endif
