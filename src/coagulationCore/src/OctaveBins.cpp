// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#include "coagulation/OctaveBins.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace coag {

void OctaveBins::reset(std::size_t nColumns, std::size_t capacity)
{
    if (capacity >= std::size_t(0xffffffffu)) {
        throw std::length_error("coag::OctaveBins: more than 2^32 - 1 leaves");
    }
    ncol_ = nColumns;
    col_.resize(ncol_);
    for (Column& C : col_) {
        if (C.start.empty()) {
            C.start.assign(nBins + 1, 0);
            C.sum.assign(nBins, 0);
            C.binTotal.assign(nBins, 0.0);
        } else {
            for (std::size_t k = C.lo; k <= C.hi; ++k) {
                C.sum[k] = 0;
                C.binTotal[k] = 0.0;
            }
        }
        C.rec.resize(capacity);
        C.lo = 1;
        C.hi = 0;
        C.total = 0.0;
        C.dirty = false;
    }
    pos_.resize(capacity * ncol_);
    next_.resize(nBins);
    size_ = 0;
    capacity_ = capacity;
}

void OctaveBins::finishBuild(std::size_t n)
{
    size_ = n;
    for (std::size_t c = 0; c < ncol_; ++c) {
        Column& C = col_[c];
        if (n == 0) continue;
        // counts per bin (in next_), the occupied range
        std::size_t lo = nBins, hi = 0;
        for (std::size_t i = 0; i < n; ++i) {
            const std::size_t k = key(C.rec[i].value);
            lo = std::min(lo, k);
            hi = std::max(hi, k);
        }
        for (std::size_t k = lo; k <= hi; ++k) next_[k] = 0;
        for (std::size_t i = 0; i < n; ++i) ++next_[key(C.rec[i].value)];
        C.lo = lo;
        C.hi = hi;
        std::uint32_t s = 0;
        for (std::size_t k = lo; k <= hi; ++k) {
            C.start[k] = s;
            s += next_[k];
            next_[k] = C.start[k];
        }
        C.start[hi + 1] = s;
        // in place: each record swapped straight to the next free slot of its bin
        for (std::size_t k = lo; k <= hi; ++k) {
            while (next_[k] < C.start[k + 1]) {
                const std::size_t kk = key(C.rec[next_[k]].value);
                if (kk == k) {
                    ++next_[k];
                } else {
                    std::swap(C.rec[next_[k]], C.rec[next_[kk]]);
                    ++next_[kk];
                }
            }
        }
        for (std::size_t i = 0; i < n; ++i) {
            const Record& r = C.rec[i];
            pos(r.leaf, c) = static_cast<std::uint32_t>(i);
            C.sum[key(r.value)] += significand(r.value);
        }
        for (std::size_t k = lo; k <= hi; ++k) refresh(C, k);
    }
}

void OctaveBins::refresh(Column& C, std::size_t k)
{
    const std::size_t E = k >> 1;  // the biased exponent
    const int e = static_cast<int>(E > 1 ? E : 1) - 1075;
    // the integer rounded (a function of its value alone; the high part is nonzero only
    // past 2^64, i.e. above 2^11 values in one bin)
    const std::uint64_t high = static_cast<std::uint64_t>(C.sum[k] >> 64);
    const std::uint64_t low = static_cast<std::uint64_t>(C.sum[k]);
    const double s = high == 0 ? static_cast<double>(low)
                               : static_cast<double>(high) * 18446744073709551616.0
                                     + static_cast<double>(low);
    if (e >= -1022) {  // 2^e a normal double: the product is exact (or overflows to inf)
        const std::uint64_t b = static_cast<std::uint64_t>(e + 1023) << 52;
        double scale;
        std::memcpy(&scale, &b, sizeof scale);
        C.binTotal[k] = s * scale;
    } else {
        C.binTotal[k] = std::ldexp(s, e);
    }
    C.dirty = true;
}

void OctaveBins::append(const double* v)
{
    if (size_ >= capacity_) resizeCapacity(std::max<std::size_t>(16, 2 * capacity_));
    const std::size_t j = size_;
    for (std::size_t c = 0; c < ncol_; ++c) {
        Column& C = col_[c];
        const std::size_t k = key(v[c]);
        if (C.lo > C.hi) {  // empty column
            C.lo = C.hi = k;
            C.start[k] = C.start[k + 1] = 0;
        } else {
            include(C, k);
        }
        // the new record at the end of the top bin, then walked down to its own
        C.rec[j] = Record{v[c], static_cast<std::uint32_t>(j)};
        pos(j, c) = static_cast<std::uint32_t>(j);
        ++C.start[C.hi + 1];
        move(C, c, j, C.hi, k);
        C.sum[k] += significand(v[c]);
        refresh(C, k);
    }
    ++size_;
}

void OctaveBins::removeBySwap(std::size_t r, std::size_t last)
{
    if (size_ == 0 || last != size_ - 1 || r > last) {
        throw std::logic_error("coag::OctaveBins::removeBySwap: last must be the last leaf");
    }
    for (std::size_t c = 0; c < ncol_; ++c) {
        Column& C = col_[c];
        std::size_t p = pos(r, c);
        const std::size_t k = key(C.rec[p].value);
        C.sum[k] -= significand(C.rec[p].value);
        // walked up into the top bin, then swapped to the very end and dropped
        p = move(C, c, p, k, C.hi);
        swapRecords(C, c, p, last);
        --C.start[C.hi + 1];
        refresh(C, k);
        if (r != last) {
            const std::uint32_t q = pos(last, c);
            C.rec[q].leaf = static_cast<std::uint32_t>(r);
            pos(r, c) = q;
        }
    }
    --size_;
}

void OctaveBins::resizeCapacity(std::size_t capacity)
{
    if (capacity >= std::size_t(0xffffffffu)) {
        throw std::length_error("coag::OctaveBins: more than 2^32 - 1 leaves");
    }
    for (Column& C : col_) C.rec.resize(capacity);
    pos_.resize(capacity * ncol_);
    capacity_ = capacity;
}

std::size_t OctaveBins::memoryBytes() const
{
    std::size_t b = pos_.capacity() * sizeof(std::uint32_t);
    for (const Column& C : col_) b += C.rec.capacity() * sizeof(Record);
    return b;
}

} // namespace coag
