// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#include "coagulation/sampling/QuantizedSumTree.hpp"

#include <algorithm>
#include <new>
#include <sstream>
#include <stdexcept>
#include <string>

namespace coag {

void QuantizedSumTree::reset(std::size_t nColumns, std::size_t capacity)
{
    layout(nColumns, capacity);
    std::fill(base_, base_ + levelOffset_.back() + blockSize_, std::uint64_t(0));
}

void QuantizedSumTree::layout(std::size_t nColumns, std::size_t capacity)
{
    if (nColumns > maxColumns) {
        throw std::invalid_argument("coag::QuantizedSumTree::reset: " + std::to_string(nColumns)
                                    + " columns, at most " + std::to_string(maxColumns));
    }
    ncol_ = nColumns;
    version_ += 2;
    blockSize_ = ncol_ * fanOut;
    const std::size_t nodes0 = std::max<std::size_t>(1, (capacity + fanOut - 1) / fanOut);
    capacity_ = nodes0 * fanOut;
    if (capacity_ > (std::size_t(1) << 40)) {
        throw std::invalid_argument("coag::QuantizedSumTree::reset: capacity "
                                    + std::to_string(capacity) + " above 2^40");
    }
    // total <= capacity * 2^bits_ <= 2^62
    int logCapacity = 0;
    while ((std::size_t(1) << logCapacity) < capacity_) ++logCapacity;
    bits_ = std::min(52, 62 - logCapacity);

    levelOffset_.clear();
    levelNodes_.clear();
    std::size_t offset = 0, nodes = nodes0;
    for (;;) {
        levelOffset_.push_back(offset);
        levelNodes_.push_back(nodes);
        offset += nodes * blockSize_;
        if (nodes == 1) break;
        nodes = (nodes + fanOut - 1) / fanOut;
    }
    if (offset > storageWords_) {
        const std::size_t bytes = largeArray::roundedBytes(offset * sizeof(std::uint64_t));
        storage_.reset(static_cast<std::uint64_t*>(largeArray::allocate(bytes)));
        storageWords_ = bytes / sizeof(std::uint64_t);
    }
    base_ = storage_.get();
    nLevels_ = levelOffset_.size();
    for (std::size_t l = 0; l < nLevels_; ++l) levelBase_[l] = base_ + levelOffset_[l];
    std::fill_n(totals_, maxColumns, std::uint64_t(0));
    for (std::size_t c = 0; c < ncol_; ++c) setExponent(c, 0);
    prefetch_ = offset * sizeof(std::uint64_t) > prefetchBytes;
}

int QuantizedSumTree::exponentFor(double largest) const
{
    if (!(largest > 0.0)) return 0;
    int e2 = 0;
    std::frexp(largest, &e2);  // largest < 2^e2
    return e2 - (bits_ - headroomBits);
}

void QuantizedSumTree::setExponent(std::size_t c, int e)
{
    if (e < -960 || e > 960) {
        throw std::domain_error("coag::QuantizedSumTree: a value of order 2^"
                                + std::to_string(e + bits_ - headroomBits)
                                + " is outside the sampler's range 2^-900 .. 2^1000");
    }
    exponent_[c] = e;
    scale_[c] = std::ldexp(1.0, e);
    scaleInverse_[c] = std::ldexp(1.0, -e);
    limitValue_[c] = std::ldexp(1.0, bits_ + e);
}

void QuantizedSumTree::throwBadValue(std::size_t c, double v)
{
    std::ostringstream os;
    os << "coag::QuantizedSumTree: value " << v << " in column " << c
       << " (a particle's weight times a kernel basis function) is not finite and >= 0";
    throw std::domain_error(os.str());
}

void QuantizedSumTree::fitScale(std::size_t c, double v)
{
    if (!(v >= 0.0) || !std::isfinite(v)) throwBadValue(c, v);
    const int e = exponentFor(v);
    if (totals_[c] == 0) {
        setExponent(c, e);  // every leaf is zero: any scale holds them
    } else if (e > exponent_[c]) {
        coarsen(c, e - exponent_[c]);
    }
}

void QuantizedSumTree::coarsen(std::size_t c, int k)
{
    // ceil(q / 2^k) = ceil(v 2^-(e+k)) for q = ceil(v 2^-e): the quantisation at the new scale
    // (q <= 2^52: no overflow below k = 62; from there every positive q becomes 1)
    const std::uint64_t add = k < 62 ? (std::uint64_t(1) << k) - 1 : 0;
    std::uint64_t* leaves = base_ + c * fanOut;
    for (std::size_t node = 0; node < levelNodes_[0]; ++node) {
        std::uint64_t* q = leaves + node * blockSize_;
        for (std::size_t s = 0; s < fanOut; ++s) {
            q[s] = k < 62 ? (q[s] + add) >> k : std::uint64_t(q[s] > 0);
        }
    }
    setExponent(c, exponent_[c] + k);
    rebuild();
}

void QuantizedSumTree::finishBuild(std::size_t n)
{
    finishStaged(n, nullptr);
}

void QuantizedSumTree::finishStaged(std::size_t n, const double* largestStaged)
{
    // Leaf j of column c is word j % 8 of that column's line in block j / 8: the leaves are
    // read block by block, in the order of j (so the first bad value is the one reported),
    // with no index arithmetic per leaf
    const std::size_t fullBlocks = n / fanOut;
    const std::size_t tail = n % fanOut;
    // the leaves from n on are zero (build() staged only those below n)
    if (tail > 0) {
        std::uint64_t* block = base_ + fullBlocks * blockSize_;
        for (std::size_t c = 0; c < ncol_; ++c) {
            std::fill(block + c * fanOut + tail, block + (c + 1) * fanOut, std::uint64_t(0));
        }
    }
    const std::size_t firstEmpty = fullBlocks + (tail > 0 ? 1 : 0);
    std::fill(base_ + firstEmpty * blockSize_, base_ + levelNodes_[0] * blockSize_,
              std::uint64_t(0));
    for (std::size_t c = 0; c < ncol_; ++c) {
        std::uint64_t* const leaves = base_ + c * fanOut;
        double largest = 0.0;
        if (largestStaged) {
            largest = largestStaged[c];
        } else {
            auto scan = [&](const std::uint64_t* q, std::size_t m) {
                for (std::size_t s = 0; s < m; ++s) {
                    double v;
                    std::memcpy(&v, q + s, sizeof v);
                    if (!(v >= 0.0) || !std::isfinite(v)) throwBadValue(c, v);
                    largest = std::max(largest, v);
                }
            };
            for (std::size_t b = 0; b < fullBlocks; ++b) scan(leaves + b * blockSize_, fanOut);
            if (tail > 0) scan(leaves + fullBlocks * blockSize_, tail);
        }
        setExponent(c, exponentFor(largest));
    }
    // The leaves quantised block by block, each block's sums written to the level above as
    // they are made (rebuild() then sums the levels from there up)
    std::uint64_t* const above = nLevels_ > 1 ? levelBase_[1] : nullptr;
    if (above) std::fill(above, above + levelNodes_[1] * blockSize_, std::uint64_t(0));
    for (std::size_t b = 0; b < firstEmpty; ++b) {
        std::uint64_t* block = base_ + b * blockSize_;
        for (std::size_t c = 0; c < ncol_; ++c) {
            std::uint64_t* q = block + c * fanOut;
            std::uint64_t sum = 0;
            for (std::size_t s = 0; s < fanOut; ++s) {
                double v;
                std::memcpy(&v, q + s, sizeof v);
                q[s] = quantise(c, v);  // the zeros past n stay 0
                sum += q[s];
            }
            if (above) above[(b >> 3) * blockSize_ + c * fanOut + (b & 7)] = sum;
        }
    }
    rebuildFrom(above ? 1 : 0);
}

void QuantizedSumTree::rebuild()
{
    rebuildFrom(0);
}

void QuantizedSumTree::rebuildFrom(std::size_t level)
{
    version_ += 2;
    const std::size_t nLevels = levelOffset_.size();
    for (std::size_t l = level; l + 1 < nLevels; ++l) {
        const std::uint64_t* child = base_ + levelOffset_[l];
        std::uint64_t* parent = base_ + levelOffset_[l + 1];
        std::fill(parent, parent + levelNodes_[l + 1] * blockSize_, std::uint64_t(0));
        for (std::size_t node = 0; node < levelNodes_[l]; ++node) {
            std::uint64_t* p = parent + (node >> 3) * blockSize_ + (node & 7);
            const std::uint64_t* ch = child + node * blockSize_;
            for (std::size_t c = 0; c < ncol_; ++c) {
                const std::uint64_t* v = ch + c * fanOut;
                p[c * fanOut] = v[0] + v[1] + v[2] + v[3] + v[4] + v[5] + v[6] + v[7];
            }
        }
    }
    const std::uint64_t* root = base_ + levelOffset_[nLevels - 1];
    for (std::size_t c = 0; c < ncol_; ++c) {
        const std::uint64_t* v = root + c * fanOut;
        totals_[c] = v[0] + v[1] + v[2] + v[3] + v[4] + v[5] + v[6] + v[7];
    }
}

void QuantizedSumTree::moveLeaf(std::size_t from, std::size_t to)
{
    // the same integers at the same scale, moved as exact deltas (modulo 2^64) without
    // requantising
    std::uint64_t delta[maxColumns];
    if (from != to) {
        for (std::size_t c = 0; c < ncol_; ++c) delta[c] = leaf(from, c) - leaf(to, c);
        addToPath<0>(to, delta);
    }
    for (std::size_t c = 0; c < ncol_; ++c) delta[c] = 0 - leaf(from, c);
    addToPath<0>(from, delta);
}

void QuantizedSumTree::resizeCapacity(std::size_t capacity)
{
    QuantizedSumTree t;
    t.reset(ncol_, capacity);
    for (std::size_t c = 0; c < ncol_; ++c) t.setExponent(c, exponent_[c]);
    const std::size_t keepNodes = std::min(capacity_, t.capacity_) / fanOut;
    std::copy(base_, base_ + keepNodes * blockSize_, t.base_);
    t.rebuild();
    // a larger capacity leaves a leaf fewer bits: coarsen the columns whose leaves no longer fit
    for (std::size_t c = 0; c < ncol_; ++c) {
        if (t.bits_ < bits_) t.coarsen(c, bits_ - t.bits_);
    }
    t.version_ = version_ + 2;
    *this = std::move(t);
}

} // namespace coag
