// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_SUMTREE_HPP
#define COAGULATION_SUMTREE_HPP

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <vector>

namespace coag {

//- Multi-column sum tree with fan-out 8, stored in one flat, 64-byte aligned array.
//
//  Level 0 holds the leaf values; every node of every level holds, per column, 8 slot values
//  contiguously (one cache line per column: node block = nColumns * 8 doubles), and slot s
//  of node k on level l+1 is the sum of node 8k+s on level l. The depth is
//  ceil(log8(capacity)) (6 levels for 1e5 leaves, 7 for 1e6), so sampling touches 6-7 cache
//  lines instead of the 17-20 of a binary tree, and the in-node choice counts prefix sums
//  without data-dependent branches (no mispredictions).
//
//  Node sums are always recomputed from the children with one fixed association
//  ((v0+v1)+(v2+v3))+((v4+v5)+(v6+v7)), never updated incrementally, so the tree is exactly
//  consistent (no drift) and sampling can never end in a zero-valued leaf. Values must be
//  >= 0 and finite.
class SumTree {
public:
    static constexpr std::size_t fanOut = 8;

    SumTree() = default;
    SumTree(const SumTree&) = delete;
    SumTree& operator=(const SumTree&) = delete;
    SumTree(SumTree&&) noexcept = default;
    SumTree& operator=(SumTree&&) noexcept = default;

    //- Discard everything; all values zero; capacity() >= capacity. Reuses the allocation.
    void reset(std::size_t nColumns, std::size_t capacity);

    std::size_t capacity() const { return capacity_; }
    std::size_t columns() const { return ncol_; }
    std::size_t levels() const { return levelOffset_.size(); }

    //- Leaf value (j < capacity()).
    double value(std::size_t j, std::size_t c) const { return base_[leafIndex(j, c)]; }
    //- Set a leaf value; takes effect in the sums after update(j) or rebuild().
    void set(std::size_t j, std::size_t c, double v) { base_[leafIndex(j, c)] = v; }

    //- Recompute every internal sum from the leaves: O(capacity).
    void rebuild();

    //- Recompute the ancestors of leaf j (all columns): O(levels * columns).
    void update(std::size_t j)
    {
        double v[maxColumns];
        for (std::size_t c = 0; c < ncol_; ++c) v[c] = value(j, c);
        assign(j, v);
    }

    //- Set every column of leaf j (values[c], c < columns()) and recompute its ancestors:
    //  the same tree as set() of each column then a recomputation of every ancestor from its
    //  children by nodeSum(), bit for bit. Going up, each level's new sum is carried in a
    //  register and the old node is read before its changed slot is written, so no load
    //  waits on a store of the level below (a vectorised read of a line with a pending
    //  narrower store cannot be forwarded); the loads of all levels depend on j alone and
    //  are issued together, so their cache misses overlap.
    void assign(std::size_t j, const double* values)
    {
        switch (ncol_) {
        case 1: assignColumns<1>(j, values); break;
        case 2: assignColumns<2>(j, values); break;
        case 3: assignColumns<3>(j, values); break;
        case 4: assignColumns<4>(j, values); break;
        default: assignColumns<0>(j, values);
        }
    }

    //- The most columns a tree holds (reset() refuses more): a kernel's majorant has a few
    //  basis functions, each a column, and SWA weights the second factors (at most 2 per basis)
    static constexpr std::size_t maxColumns = 16;

    //- Sum of column c over all leaves.
    double total(std::size_t c) const { return totals_[c]; }

    //- Leaf j with probability value(j,c)/total(c), for u uniform in [0, total(c)).
    //  In each node the slot is found by counting the prefix sums <= u (no data-dependent
    //  branches); in a tree too big for the core's caches the children of the lower nodes are
    //  prefetched while that is computed.
    //  A zero-valued slot is never chosen, and if round-off puts u at or above a node's sum
    //  the last positive slot is taken, so the result is always a leaf with a positive value.
    //  sample(c, u, leafData, leafBytes): the same leaf; in a tree too big for the caches it
    //  also prefetches the records of the 8 candidate leaves once their node is known
    //  (`leafData`: one `leafBytes`-sized record per leaf), so that the caller's load of the
    //  chosen leaf's record overlaps the last level.
    std::size_t sample(std::size_t c, double u) const { return descend<false>(c, u, nullptr, 0); }
    std::size_t sample(std::size_t c, double u, const void* leafData, std::size_t leafBytes) const
    {
        return prefetch_ ? descend<true>(c, u, leafData, leafBytes)
                         : descend<false>(c, u, nullptr, 0);
    }

    //- Two independent draws at once: j1 = sample(c1, u1, ...), j2 = sample(c2, u2, ...), the
    //  same leaves, with the two walks interleaved level by level so that their cache misses
    //  overlap instead of following each other (in a tree too big for the caches a walk is a
    //  chain of dependent misses).
    void samplePair(std::size_t c1, double u1, std::size_t c2, double u2, const void* leafData,
                    std::size_t leafBytes, std::size_t& j1, std::size_t& j2) const
    {
        std::size_t n1 = 0, n2 = 0;
        if (prefetch_) {
            for (std::size_t l = levelOffset_.size(); l-- > 0;) {
                step<true>(l, c1, u1, n1, leafData, leafBytes);
                step<true>(l, c2, u2, n2, leafData, leafBytes);
            }
        } else {
            for (std::size_t l = levelOffset_.size(); l-- > 0;) {
                step<false>(l, c1, u1, n1, nullptr, 0);
                step<false>(l, c2, u2, n2, nullptr, 0);
            }
        }
        j1 = n1;
        j2 = n2;
    }

    //- Hint the cache about the lowest `depth` nodes on the path of leaf j.
    void prefetchPath(std::size_t j, std::size_t depth = 3) const
    {
#if defined(__GNUC__)
        if (!prefetch_) return;
        std::size_t idx = j;
        const std::size_t n = levelOffset_.size() < depth ? levelOffset_.size() : depth;
        for (std::size_t l = 0; l < n; ++l) {
            idx >>= 3;
            const double* p = base_ + levelOffset_[l] + idx * blockSize_;
            for (std::size_t c = 0; c < ncol_; ++c) __builtin_prefetch(p + c * fanOut);
        }
#else
        (void)j;
        (void)depth;
#endif
    }

    //- Change the capacity, keeping the leaf values that fit.
    void resizeCapacity(std::size_t capacity);

    //- Bytes held by the tree array.
    std::size_t memoryBytes() const { return storageDoubles_ * sizeof(double); }

private:
    template<bool PrefetchLeaves>
    std::size_t descend(std::size_t c, double u, const void* leafData, std::size_t leafBytes) const
    {
        std::size_t node = 0;
        for (std::size_t l = levelOffset_.size(); l-- > 0;) {
            step<PrefetchLeaves>(l, c, u, node, leafData, leafBytes);
        }
        return node;
    }

    //- One level of a descent: node on level l + 1 -> its child on level l, u reduced to it
    template<bool PrefetchLeaves>
#if defined(__GNUC__)
    __attribute__((always_inline))
#endif
    void step(std::size_t l, std::size_t c, double& u, std::size_t& node, const void* leafData,
              std::size_t leafBytes) const
    {
        (void)leafData;
        (void)leafBytes;
#if defined(__GNUC__)
        if (PrefetchLeaves && l == 0) {
            // Addresses as integers: the last node's candidates may lie past the array
            const std::uintptr_t first =
                reinterpret_cast<std::uintptr_t>(leafData) + node * fanOut * leafBytes;
            for (std::size_t b = 0; b < fanOut * leafBytes; b += 64) {
                __builtin_prefetch(reinterpret_cast<const void*>(first + b));
            }
        }
#endif
        const double* v = base_ + levelOffset_[l] + node * blockSize_ + c * fanOut;
#if defined(__GNUC__)
        if (prefetch_ && l > 0 && l <= 3) {
            const double* ch = base_ + levelOffset_[l - 1] + node * fanOut * blockSize_ + c * fanOut;
            for (std::size_t k = 0; k < fanOut; ++k) __builtin_prefetch(ch + k * blockSize_);
        }
#endif
        double p[fanOut + 1];
        p[0] = 0.0;
        p[1] = v[0];
        p[2] = v[0] + v[1];
        p[3] = p[2] + v[2];
        p[4] = p[2] + (v[2] + v[3]);
        p[5] = p[4] + v[4];
        p[6] = p[4] + (v[4] + v[5]);
        p[7] = p[6] + v[6];
        p[8] = p[6] + (v[6] + v[7]);
        std::size_t s = std::size_t(p[1] <= u) + std::size_t(p[2] <= u) + std::size_t(p[3] <= u)
                        + std::size_t(p[4] <= u) + std::size_t(p[5] <= u)
                        + std::size_t(p[6] <= u) + std::size_t(p[7] <= u)
                        + std::size_t(p[8] <= u);
        if (s == fanOut) {  // round-off: u >= node sum
            s = fanOut - 1;
            while (s > 0 && !(v[s] > 0.0)) --s;
        }
        u -= p[s];
        node = node * fanOut + s;
    }

    static double nodeSum(const double* v)
    {
        return ((v[0] + v[1]) + (v[2] + v[3])) + ((v[4] + v[5]) + (v[6] + v[7]));
    }

    //- nodeSum of v with slot s replaced by x (the same association, so the same value as
    //  writing x first), without reading v[s]
    static double nodeSumWith(const double* v, std::size_t s, double x)
    {
        const double a0 = s == 0 ? x : v[0], a1 = s == 1 ? x : v[1];
        const double a2 = s == 2 ? x : v[2], a3 = s == 3 ? x : v[3];
        const double a4 = s == 4 ? x : v[4], a5 = s == 5 ? x : v[5];
        const double a6 = s == 6 ? x : v[6], a7 = s == 7 ? x : v[7];
        return ((a0 + a1) + (a2 + a3)) + ((a4 + a5) + (a6 + a7));
    }

    //- assign() for NC columns, or for ncol_ (<= maxColumns) when NC is 0
    template<std::size_t NC>
    void assignColumns(std::size_t j, const double* values)
    {
        const std::size_t nc = NC > 0 ? NC : ncol_;
        double cur[NC > 0 ? NC : maxColumns];
        for (std::size_t c = 0; c < nc; ++c) cur[c] = values[c];
        std::size_t idx = j;
        const std::size_t nLevels = levelOffset_.size();
        for (std::size_t l = 0; l < nLevels; ++l) {
            double* block = base_ + levelOffset_[l] + (idx >> 3) * (nc * fanOut);
            const std::size_t slot = idx & 7;
            for (std::size_t c = 0; c < nc; ++c) {
                double* v = block + c * fanOut;
                const double sum = nodeSumWith(v, slot, cur[c]);
                v[slot] = cur[c];
                cur[c] = sum;
            }
            idx >>= 3;
        }
        for (std::size_t c = 0; c < nc; ++c) totals_[c] = cur[c];
    }
    std::size_t leafIndex(std::size_t j, std::size_t c) const
    {
        return (j >> 3) * blockSize_ + c * fanOut + (j & 7);
    }

    std::size_t ncol_ = 0;
    std::size_t blockSize_ = 0;  // ncol_ * fanOut
    std::size_t capacity_ = 0;
    std::vector<std::size_t> levelOffset_;  // in doubles from base_; level 0 = leaves
    std::vector<std::size_t> levelNodes_;
    std::vector<double> totals_;
    //- The array: 64-byte aligned; from hugePageBytes on 2 MiB aligned and advised to the
    //  kernel's transparent huge pages (Linux), since a big tree is walked at random and
    //  4 KiB pages then cost a TLB miss per level (measured: about 15 % of an SWA event at
    //  N = 1e6 on the issue-19 machine).
    struct FreeArray {
        void operator()(double* p) const { std::free(p); }
    };
    std::unique_ptr<double[], FreeArray> storage_;
    std::size_t storageDoubles_ = 0;
    static constexpr std::size_t hugePageBytes = 4 * 1024 * 1024;
    double* base_ = nullptr;  // == storage_.get()
    //- Prefetch only trees larger than a typical L2 cache: in a cache-resident tree (the few
    //  hundred particles of a mesh cell) the prefetches cost issue slots and save nothing
    //  (measured: 4 % fewer ns per SWA event at N = 800 without them).
    static constexpr std::size_t prefetchBytes = 512 * 1024;
    bool prefetch_ = false;
};

} // namespace coag

#endif
