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
//  a part's share stays with the part it starts in. On the additive duct, with
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

//- w[0..n) dealt to k parts as unions of contiguous runs, at most maxRuns * k runs in all:
//  returns the part of every item (each part non-empty, k in [1, n]).
//
//  Why: a contiguous cut cannot split a heavy item, so the largest share is at least the
//  heaviest tail it can end with. On the additive duct the last two of 50 cells
//  hold 27 and 18 % of the work, and no cut of the row into 2 leaves less than 55 % on one
//  rank; the same cells dealt as 6 runs, 3 to each rank, leave 50.3 %. The price is
//  processor boundaries: runs - 1 of them along the row instead of k - 1.
//
//  Method: for m = 1 .. maxRuns (while m k <= n), the exact linear partition into m k runs
//  (partitionContiguous), the runs dealt largest first to the least loaded part (the lowest
//  index on ties): LPT, within 4/3 of the best dealing of those runs. The m with the smallest
//  largest share wins, the smallest m on ties, so maxRuns = 1 is the contiguous cut (run p
//  is part p) and a larger maxRuns is never worse. No part is left empty: a dealing leaves
//  one empty only when fewer than k runs carry work, each then alone in its part, and the
//  cut can isolate those runs as well, so such a dealing never wins strictly. Throws std::invalid_argument for maxRuns = 0 and as
//  partitionContiguous.
std::vector<std::size_t> partitionRuns(const std::vector<double>& w, std::size_t k,
                                       std::size_t maxRuns);

//- The largest part sum of an assignment (part[i] < k for every item i)
double largestShare(const std::vector<double>& w, const std::vector<std::size_t>& part,
                    std::size_t k);

} // namespace coag

#endif
