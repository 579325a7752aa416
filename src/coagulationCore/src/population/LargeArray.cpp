// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#include "coagulation/population/LargeArray.hpp"

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace coag {
namespace largeArray {

namespace {

constexpr std::size_t hugePageAlignment = std::size_t(2) << 20;

std::size_t alignmentFor(std::size_t bytes)
{
    return bytes >= hugePageBytes ? hugePageAlignment : 64;
}

} // namespace

std::size_t roundedBytes(std::size_t bytes)
{
    const std::size_t align = alignmentFor(bytes);
    if (bytes > std::numeric_limits<std::size_t>::max() - align) throw std::bad_alloc();
    return bytes == 0 ? align : (bytes + align - 1) / align * align;
}

void* allocate(std::size_t bytes)
{
    const std::size_t rounded = roundedBytes(bytes);
    const std::size_t align = alignmentFor(bytes);  // as roundedBytes() took it
    void* p = std::aligned_alloc(align, rounded);
    if (!p) throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    if (align == hugePageAlignment) madvise(p, rounded, MADV_HUGEPAGE);  // a hint only
#endif
    return p;
}

} // namespace largeArray
} // namespace coag
