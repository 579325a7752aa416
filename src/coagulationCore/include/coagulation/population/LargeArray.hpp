// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_LARGEARRAY_HPP
#define COAGULATION_LARGEARRAY_HPP

#include <cstddef>
#include <cstdlib>
#include <limits>
#include <new>

namespace coag {

//- Memory for the arrays that one cell's event loop reads at random: the sum tree
//  (QuantizedSumTree) and the particle records (CellPopulation). From hugePageBytes on they
//  are 2 MiB aligned and advised to the kernel's transparent huge pages (Linux madvise; a
//  hint, which THP "madvise" or "always" honours), since a random access to a big array on
//  4 KiB pages costs a TLB miss (page walk) on top of its cache miss (what it saves:
//  doc/performance.md). Below it, 64-byte aligned (a cache line). The price: at most one 2 MiB page of memory more per array.
namespace largeArray {

//- From this size in bytes on, huge pages
constexpr std::size_t hugePageBytes = std::size_t(4) << 20;

//- The size allocate() gives for a request of `bytes`: rounded up to its alignment
std::size_t roundedBytes(std::size_t bytes);

//- roundedBytes(bytes) of storage (64-byte aligned; from hugePageBytes on as above),
//  std::bad_alloc when none; free it with deallocate()
void* allocate(std::size_t bytes);

inline void deallocate(void* p) noexcept { std::free(p); }

} // namespace largeArray

//- A std::allocator whose big allocations come from largeArray::allocate()
template <class T>
struct LargeArrayAllocator {
    using value_type = T;

    LargeArrayAllocator() noexcept = default;
    template <class U>
    LargeArrayAllocator(const LargeArrayAllocator<U>&) noexcept {}

    T* allocate(std::size_t n)
    {
        if (n > std::numeric_limits<std::size_t>::max() / sizeof(T)) throw std::bad_alloc();
        return static_cast<T*>(largeArray::allocate(n * sizeof(T)));
    }
    void deallocate(T* p, std::size_t) noexcept { largeArray::deallocate(p); }

    template <class U>
    bool operator==(const LargeArrayAllocator<U>&) const noexcept { return true; }
    template <class U>
    bool operator!=(const LargeArrayAllocator<U>&) const noexcept { return false; }
};

} // namespace coag

#endif
