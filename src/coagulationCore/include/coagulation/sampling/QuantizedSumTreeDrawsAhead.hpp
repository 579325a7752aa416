// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_QUANTIZEDSUMTREEDRAWSAHEAD_HPP
#define COAGULATION_QUANTIZEDSUMTREEDRAWSAHEAD_HPP

// The draws made ahead of QuantizedSumTree (included by QuantizedSumTree.hpp, not on its own):
// the event loop's software pipelining (MajorantSampler::lookAhead and lookTwoAhead,
// JumpProcess's modes). A walk for a random integer predicted before the change that
// precedes the real draw is kept and finished exactly as the tree is after that change, so
// that the walk's cache misses overlap other work; the draws are the tree's ordinary draws,
// bit for bit.

#include <cstddef>
#include <cstdint>

namespace coag {

// QuantizedSumTree::Draw: a walk made ahead down to its block of 8 leaves, kept as the
// block's first leaf, where that leaf's interval [start, start + q) of the column's integers
// began, and the tree's version then. drawNear() turns it into the real draw with the walk's
// last step.

//- Whether draws made ahead pay in this tree: it is bigger than 1.25 MiB, well past half
//  the L2 cache of a core. In smaller trees the walk misses little and the extra
//  instructions cost more than they hide (the threshold's measurement:
//  doc/performance.md).
inline bool QuantizedSumTree::lookaheadPays() const
{
    return memoryBytes() >= lookaheadBytes;
}

//- Whether draws made ahead in two halves (walkToNode(), finishToBlock()) pay more than
//  in one piece (walk(), walkPair()): the tree is bigger than 6 MiB, its level 1 about
//  three quarters of a MiB. While level 1 stays in the L2 cache the second half's words
//  and state cost more than they hide (the threshold's measurement: doc/performance.md).
//  At least 2 levels, so that level 1 exists.
inline bool QuantizedSumTree::twoHalvesPay() const
{
    return memoryBytes() >= twoHalvesBytes && levels() >= 2;
}

//- The walks of samplePair() for u1 and u2 down to their blocks, kept as Draws: no
//  children prefetched on the way, the blocks' lines (every column) and their candidates'
//  records prefetched at the end, not loaded (the proposal's drawNear() loads them)
inline void QuantizedSumTree::walkPair(std::size_t c1, std::uint64_t u1, std::size_t c2,
                                       std::uint64_t u2, const void* leafData,
                                       std::size_t leafBytes, Draw& d1, Draw& d2) const
{
    std::uint64_t r1 = u1, r2 = u2;
    std::size_t n1 = 0, n2 = 0;
    walks<true, true, 1>(c1, r1, n1, c2, r2, n2, leafData, leafBytes);
    // the walks subtracted the prefix below their blocks of leaves
    d1 = Draw{n1 * fanOut, u1 - r1, version_};
    d2 = Draw{n2 * fanOut, u2 - r2, version_};
}
//- walkPair() for one walk: sample()'s for u down to its block, kept as a Draw
inline void QuantizedSumTree::walk(std::size_t c, std::uint64_t u, const void* leafData,
                                   std::size_t leafBytes, Draw& d) const
{
    std::uint64_t r = u;
    std::size_t node = 0;
    walks<true, false, 1>(c, r, node, c, r, node, leafData, leafBytes);
    d = Draw{node * fanOut, u - r, version_};
}

//- Draws made two changes ahead, in two halves (MajorantSampler::lookTwoAhead): the walk
//  for u down to a node of level 1 (64 leaves), whose line it prefetches, kept as a
//  Partial: the node, where its first leaf's interval began, u and the tree's version;
//  then, one change later, finishToBlock() takes the walk's step on level 1 as the tree
//  is then (the line now in the cache) and gives the Draw of its block, as walk() would
//  for u, its lines and the candidates' records prefetched. So neither half waits on a
//  cache miss: the walk made ahead in one piece waited on level 1 in a tree whose level 1
//  is bigger than the L2 cache (doc/performance.md). For a tree of at
//  least 2 levels (levels()), so that level 1 exists.
inline void QuantizedSumTree::walkPairToNode(std::size_t c1, std::uint64_t u1, std::size_t c2,
                                             std::uint64_t u2, Partial& p1, Partial& p2) const
{
    std::uint64_t r1 = u1, r2 = u2;
    std::size_t n1 = 0, n2 = 0;
    walks<true, true, 2>(c1, r1, n1, c2, r2, n2, nullptr, 0);
    p1 = Partial{n1, u1 - r1, u1, version_};
    p2 = Partial{n2, u2 - r2, u2, version_};
}
inline void QuantizedSumTree::walkToNode(std::size_t c, std::uint64_t u, Partial& p) const
{
    std::uint64_t r = u;
    std::size_t node = 0;
    walks<true, false, 2>(c, r, node, c, r, node, nullptr, 0);
    p = Partial{node, u - r, u, version_};
}
//- The Draw of p's walk finished to its block, when the tree is as it was at p or changed
//  since by one assign() (p's start moved by the change's delta when the changed leaf
//  lies before p's node); false otherwise. A u outside the node (the change moved it)
//  gives the Draw of the node's last block, still exact for drawNear(), or false where
//  the last node of the level has no such block.
inline bool QuantizedSumTree::finishToBlock(std::size_t c, const Partial& p,
                                            const void* leafData, std::size_t leafBytes,
                                            Draw& d) const
{
    std::uint64_t start = p.start;
    if (p.version != version_) {
        if (p.version + 1 != version_) return false;
        start += lastDelta_[c]
                 & (std::uint64_t(0) - std::uint64_t(lastLeaf_ < p.node * fanOut * fanOut));
    }
    std::uint64_t r = p.u - start;
    std::size_t node = p.node;
    forColumnCount([&](auto nc) { finishStep<nc>(c, r, node, leafData, leafBytes); });
    if (node * fanOut >= capacity_) return false;  // past the last block
    d = Draw{node * fanOut, p.u - r, version_};
    return true;
}

//- sample(c, u) from a Draw d made earlier by walk() or walkPair(), without a walk: true
//  and j = the leaf whose interval holds u, when the tree is as it was at d or changed
//  since by one assign() and that leaf is in d's block of 8 leaves or at most
//  maxDrawSteps intervals from its ends; false (j untouched) otherwise. d's start (where
//  the block's first interval began) moves by the change's delta when the changed leaf
//  lies before it; the last step of a walk then finds u in the block from its leaves as
//  they are now, and a u outside the block steps over the neighbouring intervals. Exact:
//  the intervals of the leaves partition {0, ..., total - 1} in the order of j, and a
//  walk ends in the leaf whose interval holds u.
//  (The draws made ahead end at the block, not the leaf: the walk made ahead then loads
//  no leaf line, which it only prefetches, so that its cache miss does not hold up the
//  work after it.)
inline bool QuantizedSumTree::drawNear(std::size_t c, const Draw& d, std::uint64_t u,
                                       std::size_t& j) const
{
    std::uint64_t start = d.start;
    if (d.version != version_) {
        if (d.version + 1 != version_) return false;
        // modulo 2^64: exact; masked, not branched on (the changed leaf lies before the
        // draw's about half the time, at random: measured, a mispredicted branch a draw)
        start += lastDelta_[c] & (std::uint64_t(0) - std::uint64_t(lastLeaf_ < d.leaf));
    }
    // the walk's last step in d's block; u outside the block (below: r wraps to above
    // 2^63; above: past the block's sum) ends in its last leaf with r >= that leaf's q
    std::uint64_t r = u - start;
    std::size_t k = d.leaf / fanOut;
    forColumnCount([&](auto nc) { step<nc, false>(0, c, r, k); });
    if (r < leaf(k, c)) {
        j = k;
        return true;
    }
    if (u < start) {
        k = d.leaf;  // from the block's first interval, to the left
    } else {
        start = u - r;  // from its last interval (k), to the right
    }
    for (std::size_t steps = 0;; ++steps) {
        if (u < start) {
            if (k == 0 || steps == maxDrawSteps) return false;
            --k;
            start -= leaf(k, c);
        } else {
            const std::uint64_t q = leaf(k, c);
            if (u - start < q) break;
            if (k + 1 >= capacity_ || steps == maxDrawSteps) return false;
            start += q;
            ++k;
        }
    }
    j = k;
    return true;
}

} // namespace coag

#endif
