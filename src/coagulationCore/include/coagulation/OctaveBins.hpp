// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_OCTAVEBINS_HPP
#define COAGULATION_OCTAVEBINS_HPP

#include "coagulation/Rng.hpp"

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

namespace coag {

//- Multi-column weighted sampler for large populations: the values of each column binned by
//  half-octave, with O(1) expected memory accesses per draw and per change, against the
//  sum tree's walk of log8 N levels (issue 19). MajorantSampler uses it for capacities from
//  setBinnedFrom() on; off by default, as on the development machine it was not faster than
//  the tree at N = 1e5 or 1e6 (a change first loads the leaf's positions, and the bin scans
//  and totals cost more than the tree's cache-resident top levels; README, Performance).
//
//  Bin k of a column holds the values whose top 12 bits (the biased IEEE exponent E and the
//  first significand bit h; k = 2E + h) are k: v in [1, 1.5) * 2^(E-1023) (h = 0) or
//  [1.5, 2) * 2^(E-1023) (h = 1); k = 0, 1: zero and the subnormal values. The bin's top
//  (the double whose bits are (k + 1) << 51) is above each of its values and at most 1.5
//  times any nonzero one of them.
//
//  A draw proportional to the values picks a bin with probability binTotal_k / total (a scan
//  over the occupied range, cache resident), then a member uniformly and accepts it with
//  probability v / top_k (>= 2/3 for nonzero values), else draws another member of the same
//  bin. Given the bin, the accepted member is proportional to its value, so the draw is
//  exactly proportional to v (QuantizedSumTree::sample: proportional to a majorant of v).
//  One 64-bit number per candidate: its low 32 bits the member (Lemire's unbiased
//  multiply-shift, redrawn in the rare rejected case), its high 32 bits a uniform on a grid
//  of top_k / 2^32 cells; a value inside the drawn cell (probability 2^-32) is decided by a
//  further uniform(), so the acceptance is exact to double precision like uniform() * top < v.
//  Candidates are drawn two at a time (for the two factors of a pair, two each), their
//  records prefetched, then tested in order, so the cache misses overlap.
//
//  Exact sums without drift: within bin k every value is an integer multiple of
//  2^(max(E,1)-1075) (its 53-bit significand), so the bin keeps the integer sum of the
//  significands (128 bits: exact for any count below 2^75) and adds and subtracts them
//  exactly on every change; binTotal_k is that integer times the power of two, rounded
//  (a function of the integer alone). The column total is the sum of the bin totals in a
//  fixed order, recomputed after a change. So, as in the QuantizedSumTree, the totals depend
//  only on the current values, not on their history, and a bin of total zero is never chosen.
//  Values must be >= 0 and finite.
//
//  Layout per column: one array of {value, leaf} records sorted by bin (a counting sort at
//  build; bin k at [start_k, start_{k+1})), and per leaf its position in each column
//  (leaf-major: a leaf's positions share one cache line). A value that changes bin walks its
//  record through the bins in between, one swap per boundary, O(bins moved): a few for a
//  coagulation. Bins outside the occupied range [lo, hi] are never read.
//
//  Invariant: leaves 0..size()-1 are present in every column, each exactly once; the record
//  at position pos(j, c) holds leaf j; sum_k is the exact integer sum of the significands in
//  bin k, binTotal_k its rounded value (0 outside [lo, hi]), total(c) the ordered sum of
//  binTotal over [lo, hi].
class OctaveBins {
public:
    static constexpr std::size_t nBins = 4096;  // 12-bit keys: exponent, first bit

    //- Discard everything: no leaves, room for `capacity` without reallocation.
    void reset(std::size_t nColumns, std::size_t capacity);

    std::size_t size() const { return size_; }
    std::size_t capacity() const { return capacity_; }
    std::size_t columns() const { return ncol_; }

    //- Build in O(n): stage(j, c, v) for every leaf j < n and column c, then finishBuild(n)
    //  (n <= capacity()).
    void stage(std::size_t j, std::size_t c, double v)
    {
        Record& r = col_[c].rec[j];
        r.value = v;
        r.leaf = static_cast<std::uint32_t>(j);
    }
    void finishBuild(std::size_t n);

    //- Leaf value
    double value(std::size_t j, std::size_t c) const { return col_[c].rec[pos(j, c)].value; }

    //- Change the value of leaf j < size() in column c (the sums follow at once).
    void set(std::size_t j, std::size_t c, double v)
    {
        Column& C = col_[c];
        std::uint32_t p = pos(j, c);
        Record& r = C.rec[p];
        const std::size_t kOld = key(r.value);
        const std::size_t kNew = key(v);
        C.sum[kOld] -= significand(r.value);
        C.sum[kNew] += significand(v);
        r.value = v;
        if (kNew != kOld) {
            include(C, kNew);
            move(C, c, p, kOld, kNew);
            refresh(C, kNew);
        }
        refresh(C, kOld);
    }

    //- Add leaf size() with its values v[0..columns()), growing the capacity when full.
    void append(const double* v);

    //- Remove leaf r; leaf last = size() - 1 becomes leaf r (its values unchanged).
    void removeBySwap(std::size_t r, std::size_t last);

    //- Sum of column c over all leaves.
    double total(std::size_t c)
    {
        Column& C = col_[c];
        if (C.dirty) {
            double s = 0.0;
            for (std::size_t k = C.lo; k <= C.hi; ++k) s += C.binTotal[k];
            C.total = s;
            C.dirty = false;
        }
        return C.total;
    }

    //- Leaf j with probability value(j,c)/total(c), for u uniform in [0, total(c)) and the
    //  rng for the choice within the bin. Bins are scanned from the largest down; if
    //  round-off puts u at or above the total the last positive bin is taken.
    std::size_t sample(std::size_t c, double u, Rng& rng) const
    {
        const Bin b = bin(c, u);
        for (;;) {
            const Try t = draw(b, rng);
            const std::int64_t l = t.resolve(rng);
            if (l >= 0) return static_cast<std::size_t>(l);
        }
    }

    //- Two independent draws, j1 from column c1 for u1 and j2 from column c2 for u2, each
    //  with the law of sample(); their candidates' loads are in flight together.
    void samplePair(std::size_t c1, double u1, std::size_t c2, double u2, Rng& rng,
                    std::size_t& j1, std::size_t& j2) const
    {
        const Bin b1 = bin(c1, u1);
        const Bin b2 = bin(c2, u2);
        std::int64_t l1 = -1, l2 = -1;
        do {
            if (l1 < 0 && l2 < 0) {
                const Try t1 = draw(b1, rng);
                const Try t2 = draw(b2, rng);
                l1 = t1.resolve(rng);
                l2 = t2.resolve(rng);
            } else if (l1 < 0) {
                l1 = draw(b1, rng).resolve(rng);
            } else {
                l2 = draw(b2, rng).resolve(rng);
            }
        } while (l1 < 0 || l2 < 0);
        j1 = static_cast<std::size_t>(l1);
        j2 = static_cast<std::size_t>(l2);
    }

    //- Hint the cache about leaf j's records in every column (before a change of its values)
    void prefetchRecords(std::size_t j) const
    {
#if defined(__GNUC__)
        for (std::size_t c = 0; c < ncol_; ++c) __builtin_prefetch(&col_[c].rec[pos(j, c)]);
#else
        (void)j;
#endif
    }

    //- Hint the cache about leaf j's positions (before a change of its values).
    void prefetchLeaf(std::size_t j) const
    {
#if defined(__GNUC__)
        __builtin_prefetch(&pos_[j * ncol_]);
#else
        (void)j;
#endif
    }

    //- Bytes held by the records and positions (the per-bin tables not counted: fixed,
    //  independent of N).
    std::size_t memoryBytes() const;

private:
    struct Record {
        double value;
        std::uint32_t leaf;
    };
    __extension__ typedef unsigned __int128 uint128;
    struct Column {
        std::vector<Record> rec;            // capacity records, [0, size) sorted by bin
        std::vector<std::uint32_t> start;   // nBins + 1; valid on [lo, hi + 1]
        std::vector<uint128> sum;           // exact significand sums per bin
        std::vector<double> binTotal;       // their rounded values (0 outside [lo, hi])
        std::size_t lo = 1;                 // occupied range of bins; lo > hi: none
        std::size_t hi = 0;
        double total = 0.0;
        bool dirty = false;
    };

    //- The chosen bin of a draw: its records, their number (> 0) and the acceptance grid
    struct Bin {
        const Record* first;
        std::uint32_t count;
        double cell;  // top_k / 2^32
    };
    //- Two candidates of one bin, each with its cell on the acceptance grid
    struct Try {
        const Record* a;
        const Record* b;
        std::uint32_t ga;
        std::uint32_t gb;
        double cell;
        //- The first accepted leaf, -1 if neither; accepted: the uniform on cell g of the
        //  grid, g + U with U a further uniform, below value / cell
        static bool accept(const Record* r, std::uint32_t g, double cell, Rng& rng)
        {
            const double low = g * cell;  // exact: 32-bit integer times a power of two
            const double v = r->value;
            if (low + cell <= v) return true;
            if (low >= v) return false;
            return low + rng.uniform() * cell < v;  // v inside the cell: 2^-32
        }
        std::int64_t resolve(Rng& rng) const
        {
            if (accept(a, ga, cell, rng)) return a->leaf;
            if (accept(b, gb, cell, rng)) return b->leaf;
            return -1;
        }
    };

    Bin bin(std::size_t c, double u) const
    {
        const Column& C = col_[c];
        std::size_t chosen = C.hi;
        for (std::size_t k = C.hi;; --k) {
            const double t = C.binTotal[k];
            if (t > 0.0) {
                chosen = k;
                if (u < t) break;
                u -= t;
            }
            if (k == C.lo) break;
        }
        const std::size_t first = C.start[chosen];
        return Bin{C.rec.data() + first, C.start[chosen + 1] - C.start[chosen],
                   binTop(chosen) * (1.0 / 4294967296.0)};
    }

    //- A member of bin b (unbiased) and its grid cell, from one 64-bit number (more only
    //  when the multiply-shift would be biased)
    static const Record* candidate(const Bin& b, Rng& rng, std::uint32_t& g)
    {
        for (;;) {
            const std::uint64_t r = rng.engine()();
            const std::uint64_t m = (r & 0xffffffffu) * b.count;
            if (static_cast<std::uint32_t>(m) < b.count
                && static_cast<std::uint32_t>(m) < (0u - b.count) % b.count) {
                continue;
            }
            g = static_cast<std::uint32_t>(r >> 32);
            return b.first + (m >> 32);
        }
    }

    //- Two candidates of bin b (in this order), their records prefetched
    static Try draw(const Bin& b, Rng& rng)
    {
        Try t;
        t.a = candidate(b, rng, t.ga);
        t.b = candidate(b, rng, t.gb);
        t.cell = b.cell;
#if defined(__GNUC__)
        __builtin_prefetch(t.a);
        __builtin_prefetch(t.b);
#endif
        return t;
    }

    static std::uint64_t bits(double v)
    {
        std::uint64_t b;
        std::memcpy(&b, &v, sizeof b);
        return b;
    }
    static std::size_t key(double v) { return static_cast<std::size_t>(bits(v) >> 51) & 4095u; }
    static std::uint64_t significand(double v)
    {
        const std::uint64_t b = bits(v);
        const std::uint64_t frac = b & ((std::uint64_t(1) << 52) - 1);
        return (b >> 52) & 2047u ? frac | (std::uint64_t(1) << 52) : frac;
    }
    //- Above every value of bin k, at most 1.5 times any nonzero one: the double with bits
    //  (k + 1) << 51 (2^(E-1023) * 1.5 for h = 0, 2^(E-1022) for h = 1)
    static double binTop(std::size_t k)
    {
        const std::uint64_t b = static_cast<std::uint64_t>(k + 1) << 51;
        double v;
        std::memcpy(&v, &b, sizeof v);
        return v;
    }

    std::uint32_t& pos(std::size_t j, std::size_t c) { return pos_[j * ncol_ + c]; }
    std::uint32_t pos(std::size_t j, std::size_t c) const { return pos_[j * ncol_ + c]; }

    //- binTotal_k from the exact sum
    static void refresh(Column& C, std::size_t k);

    //- Widen [lo, hi] to bin k (the new bins empty)
    void include(Column& C, std::size_t k) const
    {
        if (k > C.hi) {
            for (std::size_t m = C.hi + 2; m <= k + 1; ++m) C.start[m] = C.start[C.hi + 1];
            C.hi = k;
        }
        if (k < C.lo) {
            for (std::size_t m = k; m < C.lo; ++m) C.start[m] = 0;
            C.lo = k;
        }
    }

    void swapRecords(Column& C, std::size_t c, std::size_t p, std::size_t q)
    {
        if (p == q) return;
        Record t = C.rec[p];
        C.rec[p] = C.rec[q];
        C.rec[q] = t;
        pos(C.rec[p].leaf, c) = static_cast<std::uint32_t>(p);
        pos(C.rec[q].leaf, c) = static_cast<std::uint32_t>(q);
    }

    //- The record at p, now in bin b, moved from bin a's range to bin b's (both in [lo, hi]);
    //  returns its new position.
    std::size_t move(Column& C, std::size_t c, std::size_t p, std::size_t a, std::size_t b)
    {
        for (std::size_t k = a; k < b; ++k) {  // up: to the last slot of bin k, then the
            const std::size_t last = C.start[k + 1] - 1;  // boundary moves down over it
            swapRecords(C, c, p, last);
            --C.start[k + 1];
            p = last;
        }
        for (std::size_t k = a; k > b; --k) {  // down: to the first slot of bin k, then the
            const std::size_t first = C.start[k];  // boundary moves up over it
            swapRecords(C, c, p, first);
            ++C.start[k];
            p = first;
        }
        return p;
    }

    void resizeCapacity(std::size_t capacity);

    std::size_t ncol_ = 0;
    std::size_t size_ = 0;
    std::size_t capacity_ = 0;
    std::vector<Column> col_;
    std::vector<std::uint32_t> pos_;  // [leaf * ncol_ + column]
    std::vector<std::uint32_t> next_; // build scratch, nBins
};

} // namespace coag

#endif
