// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#include "coagulation/SumTree.hpp"

#include <algorithm>
#include <cstdint>
#include <new>
#include <stdexcept>
#include <string>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace coag {

void SumTree::reset(std::size_t nColumns, std::size_t capacity)
{
    if (nColumns > maxColumns) {
        throw std::invalid_argument("coag::SumTree::reset: " + std::to_string(nColumns)
                                    + " columns, at most " + std::to_string(maxColumns));
    }
    ncol_ = nColumns;
    blockSize_ = ncol_ * fanOut;
    const std::size_t nodes0 = std::max<std::size_t>(1, (capacity + fanOut - 1) / fanOut);
    capacity_ = nodes0 * fanOut;
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
    if (offset > storageDoubles_) {
        const std::size_t bytes = offset * sizeof(double);
        const std::size_t align = bytes >= hugePageBytes ? std::size_t(2) << 20 : 64;
        const std::size_t rounded = (bytes + align - 1) / align * align;
        storage_.reset(static_cast<double*>(std::aligned_alloc(align, rounded)));
        if (!storage_) throw std::bad_alloc();
        storageDoubles_ = rounded / sizeof(double);
#if defined(__linux__) && defined(MADV_HUGEPAGE)
        if (align > 64) madvise(storage_.get(), rounded, MADV_HUGEPAGE);  // a hint only
#endif
    }
    base_ = storage_.get();
    std::fill(base_, base_ + offset, 0.0);
    totals_.assign(ncol_, 0.0);
    prefetch_ = offset * sizeof(double) > prefetchBytes;
}

void SumTree::rebuild()
{
    const std::size_t nLevels = levelOffset_.size();
    for (std::size_t l = 0; l + 1 < nLevels; ++l) {
        const double* child = base_ + levelOffset_[l];
        double* parent = base_ + levelOffset_[l + 1];
        std::fill(parent, parent + levelNodes_[l + 1] * blockSize_, 0.0);
        for (std::size_t node = 0; node < levelNodes_[l]; ++node) {
            double* p = parent + (node >> 3) * blockSize_ + (node & 7);
            const double* ch = child + node * blockSize_;
            for (std::size_t c = 0; c < ncol_; ++c) p[c * fanOut] = nodeSum(ch + c * fanOut);
        }
    }
    const double* root = base_ + levelOffset_[nLevels - 1];
    for (std::size_t c = 0; c < ncol_; ++c) totals_[c] = nodeSum(root + c * fanOut);
}

void SumTree::resizeCapacity(std::size_t capacity)
{
    SumTree t;
    t.reset(ncol_, capacity);
    const std::size_t keepNodes = std::min(capacity_, t.capacity_) / fanOut;
    std::copy(base_, base_ + keepNodes * blockSize_, t.base_);
    t.rebuild();
    *this = std::move(t);
}

} // namespace coag
