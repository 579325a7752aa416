// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#include "coagulation/SumTree.hpp"

#include <algorithm>
#include <cstdint>

namespace coag {

void SumTree::reset(std::size_t nColumns, std::size_t capacity)
{
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
    const std::size_t align = 64 / sizeof(double);
    storage_.assign(offset + align, 0.0);
    const std::uintptr_t addr = reinterpret_cast<std::uintptr_t>(storage_.data());
    const std::size_t shift = ((64 - addr % 64) % 64) / sizeof(double);
    base_ = storage_.data() + shift;
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
