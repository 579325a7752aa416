// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_QUANTIZEDSUMTREE_HPP
#define COAGULATION_QUANTIZEDSUMTREE_HPP

#include "coagulation/population/LargeArray.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <type_traits>
#include <vector>

namespace coag {

//- Multi-column sum tree over integer majorants of the values: fan-out 8, one flat, 64-byte
//  aligned array.
//
//  Quantisation (the majorant). Column c has a scale 2^e_c; a value v >= 0 is held as the
//  integer q = ceil(v 2^-e_c) (q = 1 for any v > 0 below the scale), so Q = q 2^e_c >= v.
//  Drawing leaf j with probability q_j / sum q therefore proposes from a majorant of the
//  values, and a caller that accepts the draw with probability v_j / Q_j (or, for a pair, the
//  kernel over the pair's product of Q's) keeps the law of a draw exactly proportional to v:
//  thinning. quantised() gives Q for any value without touching the tree, bit for bit the Q
//  that assign() stores. B = the bits a leaf may use: 62 - ceil(log2 capacity), at most 52,
//  so that sums stay below 2^62 and Q is an exact double. A column takes its scale from its
//  largest value at build (finishBuild) with headroomBits = 8 bits to spare: q <= 2^(B-8).
//  Each Q exceeds its v by less than one unit 2^e, below 2^-(B-9) of that largest value, so
//  the extra (fictitious) proposal rate, at most n 2^e / sum Q, is below 2^-(B-9) times the
//  ratio of the largest value to the mean: 2^-33 up to 2^20 leaves when they are alike. A value
//  whose q would pass 2^B coarsens the column: every q becomes ceil(q / 2^k) =
//  ceil(v 2^-(e+k)), still the quantisation of v at the new scale, O(capacity), at most once
//  per 8 bits of growth. A column whose total is zero takes its scale afresh from its next
//  value. The scales are normal doubles (2^-960 .. 2^960, else std::domain_error), so q 2^e
//  is exact; values may span about 2^-910 .. 2^1000.
//
//  Exact integer sums. Level 0 holds the q's; slot s of node k on level l+1 is the sum of
//  node 8k+s on level l, per column 8 slots in one cache line (node block = nColumns * 8
//  words). A change adds q_new - q_old to one slot per level (the adds of all levels and
//  columns are independent, so they overlap), instead of recomputing a floating-point sum of
//  8 children per level. The sums are exact, so they equal the sums of the leaves whatever
//  the order of the changes; a draw u uniform on {0, ..., total-1} counts the prefix sums
//  <= u in each node (no data-dependent branches) and always ends in a leaf with q > 0.
class QuantizedSumTree {
public:
    static constexpr std::size_t fanOut = 8;
    //- The most columns a tree holds (reset() refuses more): a kernel's majorant has a few
    //  basis functions, each a column, and SWA weights the second factors (at most 2 per basis)
    static constexpr std::size_t maxColumns = 16;
    //- Bits of headroom above the largest value when a column takes its scale
    static constexpr int headroomBits = 8;

    QuantizedSumTree() = default;
    QuantizedSumTree(const QuantizedSumTree&) = delete;
    QuantizedSumTree& operator=(const QuantizedSumTree&) = delete;
    QuantizedSumTree(QuantizedSumTree&&) noexcept = default;
    QuantizedSumTree& operator=(QuantizedSumTree&&) noexcept = default;

    //- Discard everything: all values zero, capacity() >= capacity, every column's scale
    //  unset (taken from its first positive value). Reuses the allocation.
    void reset(std::size_t nColumns, std::size_t capacity);

    std::size_t capacity() const { return capacity_; }
    std::size_t columns() const { return ncol_; }
    std::size_t levels() const { return levelOffset_.size(); }

    //- Build in O(n): stage(j, c, v) for every leaf j < n and column c (v >= 0, finite; held
    //  as its bits until then), then finishBuild(n), which gives each column the scale of its
    //  largest value (headroomBits bits above it), quantises the leaves and sums them.
    void stage(std::size_t j, std::size_t c, double v)
    {
        std::memcpy(&base_[leafIndex(j, c)], &v, sizeof v);
    }
    void finishBuild(std::size_t n);

    //- reset(nColumns, capacity), stage() of every column of every leaf j < n and
    //  finishBuild(n) in fewer passes, the same tree bit for bit (and the same first bad value
    //  reported): values(j, v) gives leaf j's columns v[0 .. nColumns-1]. The leaves below n
    //  are written once (not zeroed first), their largest values taken as they are staged:
    //  the build is a share of an event's cost where a step has about one event per particle
    //  (doc/performance.md).
    template <class Values>
    void build(std::size_t nColumns, std::size_t capacity, std::size_t n, Values&& values)
    {
        layout(nColumns, capacity);
        double largest[maxColumns] = {};
        bool good = false;
        forColumnCount([&](auto nc) { good = stageAll<nc>(n, values, largest); });
        // a value NaN, infinite or negative: finishBuild()'s scan reports the first one
        finishStaged(n, good ? largest : nullptr);
    }

    //- Recompute every internal sum from the leaves: O(capacity).
    void rebuild();

    //- The integer leaf q of j in column c, and its majorant Q = q 2^e_c.
    std::uint64_t leaf(std::size_t j, std::size_t c) const { return base_[leafIndex(j, c)]; }
    double value(std::size_t j, std::size_t c) const
    {
        return toDouble(leaf(j, c)) * scale_[c];
    }
    //- Q for value v in column c at the current scale: the value(j, c) that set(j, c, v) gives
    //  when it does not coarsen the column.
    double quantised(std::size_t c, double v) const
    {
        return toDouble(quantise(c, v)) * scale_[c];
    }
    int exponent(std::size_t c) const { return exponent_[c]; }

    //- Set every column of leaf j (values[c] >= 0, finite, c < columns()) and its ancestors:
    //  one exact add per level and column. A value that is NaN, infinite or negative throws
    //  std::domain_error (as does finishBuild()), and the tree keeps its old leaf.
    void assign(std::size_t j, const double* values)
    {
        for (std::size_t c = 0; c < ncol_; ++c) {
            const double v = values[c];
            // NaN, infinite and negative values go to fitScale, which refuses them
            if (!(v >= 0.0 && v <= limitValue_[c]) || (v > 0.0 && totals_[c] == 0)) {
                fitScale(c, v);
            }
        }
        forColumnCount([&](auto nc) { assignColumns<nc>(j, values); });
    }
    //- The leaf of `from` copied to `to` in every column (the same integers, no requantising),
    //  and `from` set to zero: a removal by swap.
    void moveLeaf(std::size_t from, std::size_t to);

    //- Integer sum of column c, and as a double: sum q 2^e_c (rounded to double).
    std::uint64_t totalInteger(std::size_t c) const { return totals_[c]; }
    double total(std::size_t c) const { return toDouble(totals_[c]) * scale_[c]; }

    //- Leaf j with probability q_j / totalInteger(c), for u in {0, ..., totalInteger(c) - 1}.
    //  sample(c, u, leafData, leafBytes): the same leaf; in a tree too big for the caches it
    //  also prefetches the records of the 8 candidate leaves once their node is known
    //  (`leafData`: one `leafBytes`-sized record per leaf), so that the caller's load of the
    //  chosen leaf's record overlaps the last level.
    std::size_t sample(std::size_t c, std::uint64_t u) const
    {
        std::size_t node = 0;
        walks<false, false>(c, u, node, c, u, node, nullptr, 0);
        return node;
    }
    std::size_t sample(std::size_t c, std::uint64_t u, const void* leafData,
                       std::size_t leafBytes) const
    {
        std::size_t node = 0;
        if (prefetch_) {
            walks<true, false>(c, u, node, c, u, node, leafData, leafBytes);
        } else {
            walks<false, false>(c, u, node, c, u, node, nullptr, 0);
        }
        return node;
    }

    //- Two independent draws at once: j1 = sample(c1, u1, ...), j2 = sample(c2, u2, ...), the
    //  same leaves, with the two walks interleaved level by level so that their cache misses
    //  overlap instead of following each other.
    void samplePair(std::size_t c1, std::uint64_t u1, std::size_t c2, std::uint64_t u2,
                    const void* leafData, std::size_t leafBytes, std::size_t& j1,
                    std::size_t& j2) const
    {
        std::size_t n1 = 0, n2 = 0;
        if (prefetch_) {
            walks<true, true>(c1, u1, n1, c2, u2, n2, leafData, leafBytes);
        } else {
            walks<false, true>(c1, u1, n1, c2, u2, n2, nullptr, 0);
        }
        j1 = n1;
        j2 = n2;
    }

    //- Draws made ahead of time, for the event loop's software pipelining: the walks of a
    //  later draw made before the change that precedes it, kept (Draw, Partial) and finished
    //  exactly as the tree is then. Documented and defined in QuantizedSumTreeDrawsAhead.hpp.
    struct Draw {
        std::size_t leaf = 0;
        std::uint64_t start = 0;
        std::uint64_t version = 0;
    };
    struct Partial {
        std::size_t node = 0;
        std::uint64_t start = 0;
        std::uint64_t u = 0;
        std::uint64_t version = 0;
    };
    static constexpr std::size_t maxDrawSteps = 8;
    bool lookaheadPays() const;
    bool twoHalvesPay() const;
    void walkPair(std::size_t c1, std::uint64_t u1, std::size_t c2, std::uint64_t u2,
                  const void* leafData, std::size_t leafBytes, Draw& d1, Draw& d2) const;
    void walk(std::size_t c, std::uint64_t u, const void* leafData, std::size_t leafBytes,
              Draw& d) const;
    void walkPairToNode(std::size_t c1, std::uint64_t u1, std::size_t c2, std::uint64_t u2,
                        Partial& p1, Partial& p2) const;
    void walkToNode(std::size_t c, std::uint64_t u, Partial& p) const;
    bool finishToBlock(std::size_t c, const Partial& p, const void* leafData,
                       std::size_t leafBytes, Draw& d) const;
    bool drawNear(std::size_t c, const Draw& d, std::uint64_t u, std::size_t& j) const;

    //- Hint the cache about the lowest `depth` nodes on the path of leaf j.
    void prefetchPath(std::size_t j, std::size_t depth = 3) const
    {
#if defined(__GNUC__)
        if (!prefetch_) return;
        std::size_t idx = j;
        const std::size_t n = nLevels_ < depth ? nLevels_ : depth;
        for (std::size_t l = 0; l < n; ++l) {
            const std::uint64_t* p = levelBase_[l] + (idx >> 3) * blockSize_;
            for (std::size_t c = 0; c < ncol_; ++c) __builtin_prefetch(p + c * fanOut);
            idx >>= 3;
        }
#else
        (void)j;
        (void)depth;
#endif
    }

    //- Change the capacity, keeping the leaves that fit (and coarsening the columns if the
    //  larger capacity leaves a leaf fewer bits).
    void resizeCapacity(std::size_t capacity);

    //- Bytes held by the tree array.
    std::size_t memoryBytes() const { return storageWords_ * sizeof(std::uint64_t); }

private:
    //- ceil(v 2^-e_c), at least 1 for v > 0 (a quotient below the smallest normal double may
    //  round to 0; its ceiling is 1 either way). For v <= 2^(bits_ + e_c), as every caller
    //  ensures (assign() fits the scale first): for the quotient 0 <= t <= 2^52, t + 2^52 is
    //  t rounded to the nearest integer r (ties to even) plus 2^52, exactly, so r is its
    //  representation minus that of 2^52 (up to 2^52 itself, where the exponent steps by one
    //  and the difference is again r), and r < t asks for one more. (std::ceil is a library
    //  call or a 6-instruction sequence on baseline x86-64, the flags of both builds;
    //  measured: 7 % of an SWA event in the solver. The truncation and conversion back that
    //  this replaced are, by their latencies, about 4 cycles longer on the event loop's chain
    //  of dependences, which runs from one event's change of the leaves to the next event's
    //  walk; measured, 1-2 % fewer ns per event at N = 1e3 and 1e4, none at 1e5.)
    static constexpr double twoTo52 = 4503599627370496.0;
    static constexpr std::uint64_t twoTo52Bits = 0x4330000000000000;  // its representation
    std::uint64_t quantise(std::size_t c, double v) const
    {
        const double t = v * scaleInverse_[c];
        const double big = t + twoTo52;  // t rounded to the nearest integer r, in big's low bits
        std::uint64_t bits;
        std::memcpy(&bits, &big, sizeof bits);
        std::uint64_t r = bits - twoTo52Bits + std::uint64_t(big - twoTo52 < t);  // the ceiling
        if (r == 0) r = std::uint64_t(v != 0.0);  // rare: t underflowed (a huge scale, a tiny v)
        return r;
    }

    //- f(nc) for the tree's column count: nc a std::integral_constant of it for 1 to 12
    //  columns, so that the steps are compiled with the node block's size a constant (the
    //  walks, assign() and the build), and of 0 above, where the steps read ncol_
    template <class F>
#if defined(__GNUC__)
    __attribute__((always_inline))
#endif
    void forColumnCount(F&& f) const
    {
        switch (ncol_) {
        case 1: f(std::integral_constant<std::size_t, 1>()); break;
        case 2: f(std::integral_constant<std::size_t, 2>()); break;
        case 3: f(std::integral_constant<std::size_t, 3>()); break;
        case 4: f(std::integral_constant<std::size_t, 4>()); break;
        case 5: f(std::integral_constant<std::size_t, 5>()); break;
        case 6: f(std::integral_constant<std::size_t, 6>()); break;
        case 7: f(std::integral_constant<std::size_t, 7>()); break;
        case 8: f(std::integral_constant<std::size_t, 8>()); break;
        case 9: f(std::integral_constant<std::size_t, 9>()); break;
        case 10: f(std::integral_constant<std::size_t, 10>()); break;
        case 11: f(std::integral_constant<std::size_t, 11>()); break;
        case 12: f(std::integral_constant<std::size_t, 12>()); break;
        default: f(std::integral_constant<std::size_t, 0>());
        }
    }

    //- An integer below 2^63 (every leaf, sum and total: at most 2^62) as a double, rounded as
    //  static_cast<double> rounds it; the signed conversion is one instruction on x86-64, the
    //  unsigned one a branch and several
    static double toDouble(std::uint64_t q) { return static_cast<double>(static_cast<std::int64_t>(q)); }

    //- build()'s staging for NC columns (ncol_ when NC is 0): every leaf j < n staged, each
    //  column's largest value; whether all are finite and >= 0
    template <std::size_t NC, class Values>
    bool stageAll(std::size_t n, Values& values, double* largest)
    {
        const std::size_t nc = NC > 0 ? NC : ncol_;
        double v[maxColumns] = {};
        double smallest[maxColumns] = {};
        double zero[maxColumns] = {};  // sums of v * 0: NaN once a value is NaN or infinite
        for (std::size_t j = 0; j < n; ++j) {
            values(j, v);
            std::uint64_t* leaf = base_ + (j >> 3) * (nc * fanOut) + (j & 7);
            for (std::size_t c = 0; c < nc; ++c) {
                std::memcpy(leaf + c * fanOut, &v[c], sizeof(double));
                largest[c] = v[c] > largest[c] ? v[c] : largest[c];
                smallest[c] = v[c] < smallest[c] ? v[c] : smallest[c];
                zero[c] += v[c] * 0.0;
            }
        }
        bool good = true;
        for (std::size_t c = 0; c < nc; ++c) good &= smallest[c] >= 0.0 && zero[c] == 0.0;
        return good;
    }

    //- reset() without the zeros: the levels, their addresses and the array's size
    void layout(std::size_t nColumns, std::size_t capacity);
    //- finishBuild(n) for leaves staged below n (those from n on are set to zero); with
    //  largestStaged, each column's largest value, found as they were staged and all of them
    //  finite and >= 0 (else null: finishBuild()'s scan finds them and reports the first bad)
    void finishStaged(std::size_t n, const double* largestStaged);
    //- rebuild() of the levels above `level` from it (level 0: all)
    void rebuildFrom(std::size_t level);

    //- The exponent that puts `largest` headroomBits below the leaf limit 2^bits_
    int exponentFor(double largest) const;
    //- Column c's scale: coarsened (or, when its total is zero, chosen afresh) so that v fits;
    //  std::domain_error for v NaN, infinite or negative
    void fitScale(std::size_t c, double v);
    [[noreturn]] static void throwBadValue(std::size_t c, double v);
    //- Column c coarsened by k bits: every leaf q -> ceil(q / 2^k), sums rebuilt
    void coarsen(std::size_t c, int k);
    void setExponent(std::size_t c, int e);

    //- The walks of sample(), walk(), walkToNode() (Two false: one walk, c2, u2 and n2
    //  ignored) and of samplePair(), walkPair(), walkPairToNode() (Two: two walks interleaved
    //  level by level); with Fetch the prefetches of big trees. node ends at the leaf (Stop
    //  1: at the block, the leaf-level node; Stop 2: at the node of level 1), u at u minus
    //  the prefix below it.
    //  Dispatched to steps compiled for the column count (the node block's size a constant,
    //  as in assign()) and with the levels' prefetches in separate loops: measured, a step
    //  with the runtime block size and every level's prefetch tests took about 60
    //  instructions and spilled the two walks' registers.
    template<bool Fetch, bool Two, int Stop = 0>
#if defined(__GNUC__)
    __attribute__((always_inline))
#endif
    void walks(std::size_t c1, std::uint64_t& u1, std::size_t& n1, std::size_t c2,
               std::uint64_t& u2, std::size_t& n2, const void* leafData,
               std::size_t leafBytes) const
    {
        forColumnCount([&](auto nc) {
            walksFor<nc, Fetch, Two, Stop>(c1, u1, n1, c2, u2, n2, leafData, leafBytes);
        });
    }

    //- walks() for NC columns (ncol_ when NC is 0). With Fetch: the children of the node on
    //  levels 3 to 1 prefetched, and at the leaves the candidates' records and the leaf block's
    //  other columns
    template<std::size_t NC, bool Fetch, bool Two, int Stop>
    void walksFor(std::size_t c1, std::uint64_t& u1, std::size_t& n1, std::size_t c2,
                  std::uint64_t& u2, std::size_t& n2, const void* leafData,
                  std::size_t leafBytes) const
    {
        // In locals: through the references, which may alias the tree's words, every step
        // stored and reloaded them (store forwarding on the walk's chain of dependences)
        std::uint64_t r1 = u1, r2 = Two ? u2 : 0;
        std::size_t k1 = n1, k2 = Two ? n2 : 0;
        std::size_t l = nLevels_;
        if (Fetch && Stop > 0) {
            // the walks of draws made ahead, to a block (Stop 1) or a level-1 node (Stop 2):
            // no children prefetched, the node where they stop prefetched instead
            for (; l > std::size_t(Stop); --l) {
                step<NC, false>(l - 1, c1, r1, k1);
                if (Two) step<NC, false>(l - 1, c2, r2, k2);
            }
            if (Stop == 1) {
                fetchLeafData<NC, true>(c1, k1, leafData, leafBytes);
                if (Two) fetchLeafData<NC, true>(c2, k2, leafData, leafBytes);
            } else {
#if defined(__GNUC__)
                const std::size_t bs = NC > 0 ? NC * fanOut : blockSize_;
                __builtin_prefetch(levelBase_[Stop - 1] + k1 * bs + c1 * fanOut);
                if (Two) __builtin_prefetch(levelBase_[Stop - 1] + k2 * bs + c2 * fanOut);
#endif
            }
        } else if (Fetch) {
            for (; l > childFetchLevels + 1; --l) {
                step<NC, false>(l - 1, c1, r1, k1);
                if (Two) step<NC, false>(l - 1, c2, r2, k2);
            }
            for (; l > 1; --l) {
                step<NC, true>(l - 1, c1, r1, k1);
                if (Two) step<NC, true>(l - 1, c2, r2, k2);
            }
            fetchLeafData<NC, false>(c1, k1, leafData, leafBytes);
            step<NC, false>(0, c1, r1, k1);
            if (Two) {
                fetchLeafData<NC, false>(c2, k2, leafData, leafBytes);
                step<NC, false>(0, c2, r2, k2);
            }
        } else {
            for (; l > 0; --l) {
                step<NC, false>(l - 1, c1, r1, k1);
                if (Two) step<NC, false>(l - 1, c2, r2, k2);
            }
        }
        u1 = r1;
        n1 = k1;
        if (Two) {
            u2 = r2;
            n2 = k2;
        }
    }

    //- The levels above the leaves whose steps prefetch the 8 children of their node
    static constexpr std::size_t childFetchLevels = 3;

    //- finishToBlock()'s step on level 1 and the prefetches of the block's lines and records
    template<std::size_t NC>
#if defined(__GNUC__)
    __attribute__((always_inline))
#endif
    void finishStep(std::size_t c, std::uint64_t& r, std::size_t& node, const void* leafData,
                    std::size_t leafBytes) const
    {
        step<NC, false>(1, c, r, node);
        fetchLeafData<NC, true>(c, node, leafData, leafBytes);
    }

    //- Before the last step from leaf-level node `node`: its 8 candidates' records (leafData:
    //  one leafBytes-sized record per leaf) and the leaf block's other columns, which the
    //  caller's acceptance reads (MajorantSampler::pairRateAt)
    template<std::size_t NC, bool ToBlock>
#if defined(__GNUC__)
    __attribute__((always_inline))
#endif
    void fetchLeafData(std::size_t c, std::size_t node, const void* leafData,
                       std::size_t leafBytes) const
    {
#if defined(__GNUC__)
        // Addresses as integers: the last node's candidates may lie past the array
        const std::uintptr_t first =
            reinterpret_cast<std::uintptr_t>(leafData) + node * fanOut * leafBytes;
        for (std::size_t b = 0; b < fanOut * leafBytes; b += 64) {
            __builtin_prefetch(reinterpret_cast<const void*>(first + b));
        }
        const std::size_t nc = NC > 0 ? NC : ncol_;
        const std::uint64_t* block = base_ + node * (nc * fanOut);
        for (std::size_t k = 0; k < nc; ++k) {
            if (ToBlock || k != c) __builtin_prefetch(block + k * fanOut);
        }
#else
        (void)c;
        (void)node;
        (void)leafData;
        (void)leafBytes;
#endif
    }

    //- One level of a walk in column c (NC columns, ncol_ when NC is 0); with ChildFetch the
    //  node's 8 children in the level below prefetched
    template<std::size_t NC, bool ChildFetch>
#if defined(__GNUC__)
    __attribute__((always_inline))
#endif
    void step(std::size_t l, std::size_t c, std::uint64_t& u, std::size_t& node) const
    {
        const std::size_t bs = NC > 0 ? NC * fanOut : blockSize_;
        const std::uint64_t* v = levelBase_[l] + node * bs + c * fanOut;
#if defined(__GNUC__)
        if (ChildFetch) {
            const std::uint64_t* ch = levelBase_[l - 1] + node * fanOut * bs + c * fanOut;
            for (std::size_t k = 0; k < fanOut; ++k) __builtin_prefetch(ch + k * bs);
        }
#endif
        // u < the node's sum (exact integers), so s < 8 and v[s] > u - p[s] >= 0
        const std::uint64_t p1 = v[0], p2 = p1 + v[1], p3 = p2 + v[2], p4 = p3 + v[3];
        const std::uint64_t p5 = p4 + v[4], p6 = p5 + v[5], p7 = p6 + v[6];
        const std::size_t s = std::size_t(p1 <= u) + std::size_t(p2 <= u) + std::size_t(p3 <= u)
                              + std::size_t(p4 <= u) + std::size_t(p5 <= u)
                              + std::size_t(p6 <= u) + std::size_t(p7 <= u);
        const std::uint64_t below[fanOut] = {0, p1, p2, p3, p4, p5, p6, p7};
        u -= below[s];
        node = node * fanOut + s;
    }

    //- assign() for NC columns, or for ncol_ (<= maxColumns) when NC is 0; the scales fit
    template<std::size_t NC>
    void assignColumns(std::size_t j, const double* values)
    {
        std::uint64_t delta[NC > 0 ? NC : maxColumns];
        const std::size_t nc = NC > 0 ? NC : ncol_;
        const std::uint64_t* leaves = base_ + (j >> 3) * (nc * fanOut) + (j & 7);
        for (std::size_t c = 0; c < nc; ++c) {
            delta[c] = quantise(c, values[c]) - leaves[c * fanOut];  // modulo 2^64: exact adds
        }
        addToPath<NC>(j, delta);
    }

    //- delta[c] (modulo 2^64) added to leaf j, its ancestors and the totals, for NC columns
    //  (ncol_ when NC is 0)
    template<std::size_t NC>
    void addToPath(std::size_t j, const std::uint64_t* delta)
    {
        const std::size_t nc = NC > 0 ? NC : ncol_;
        std::size_t idx = j;
        for (std::size_t l = 0; l < nLevels_; ++l) {
            std::uint64_t* block = levelBase_[l] + (idx >> 3) * (nc * fanOut) + (idx & 7);
            for (std::size_t c = 0; c < nc; ++c) block[c * fanOut] += delta[c];
            idx >>= 3;
        }
        for (std::size_t c = 0; c < nc; ++c) {
            totals_[c] += delta[c];
            lastDelta_[c] = delta[c];
        }
        lastLeaf_ = j;
        ++version_;
    }

    std::size_t leafIndex(std::size_t j, std::size_t c) const
    {
        return (j >> 3) * blockSize_ + c * fanOut + (j & 7);
    }

    std::size_t ncol_ = 0;
    std::size_t blockSize_ = 0;  // ncol_ * fanOut
    std::size_t capacity_ = 0;
    int bits_ = 52;              // a leaf q is at most 2^bits_
    std::vector<std::size_t> levelOffset_;  // in words from base_; level 0 = leaves
    //- base_ + levelOffset_[l], and the count of levels: the walks' and changes' addresses
    //  without the vector's indirection (a capacity <= 2^40 has at most 15 levels)
    static constexpr std::size_t maxLevels = 16;
    std::uint64_t* levelBase_[maxLevels] = {};
    std::size_t nLevels_ = 0;
    std::vector<std::size_t> levelNodes_;
    //- Per column (fixed arrays, not vectors: read on every event without an indirection)
    std::uint64_t totals_[maxColumns] = {};
    int exponent_[maxColumns] = {};        // the scale 2^e
    double scale_[maxColumns] = {};        // 2^e (a normal double: setExponent)
    double scaleInverse_[maxColumns] = {}; // 2^-e
    double limitValue_[maxColumns] = {};   // the largest value that fits, 2^(bits_+e)
    //- The array (LargeArray.hpp: 64-byte aligned, on huge pages when big, since a big tree
    //  is walked at random and 4 KiB pages then cost a TLB miss per level)
    struct FreeArray {
        void operator()(std::uint64_t* p) const { largeArray::deallocate(p); }
    };
    std::unique_ptr<std::uint64_t[], FreeArray> storage_;
    std::size_t storageWords_ = 0;
    std::uint64_t* base_ = nullptr;  // == storage_.get()
    //- Prefetch only trees larger than a typical L2 cache: in a cache-resident tree (the few
    //  hundred particles of a mesh cell) the prefetches cost issue slots and save nothing
    //  (measured: 4 % fewer ns per SWA event at N = 800 without them).
    static constexpr std::size_t prefetchBytes = 512 * 1024;
    bool prefetch_ = false;
    //- lookaheadPays() from this size of the tree array
    static constexpr std::size_t lookaheadBytes = 1280 * 1024;
    //- twoHalvesPay() from this size of the tree array
    static constexpr std::size_t twoHalvesBytes = 6 * 1024 * 1024;

    //- Changes counted for drawNear(): one per addToPath(), whose leaf and deltas are kept;
    //  two for any other change of leaves or scales (reset, rebuild, resizeCapacity), which
    //  no Draw made before it survives
    std::uint64_t version_ = 0;
    std::size_t lastLeaf_ = 0;
    std::uint64_t lastDelta_[maxColumns] = {};
};

} // namespace coag

#include "coagulation/sampling/QuantizedSumTreeDrawsAhead.hpp"

#endif
