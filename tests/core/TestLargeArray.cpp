// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
// The big arrays of the event loop (LargeArray.hpp): sizes, alignment, the huge-page advice
// (Linux), and the particle records of a cell kept through a vector's growth.
#include "coagulation/population/CellPopulation.hpp"
#include "coagulation/population/LargeArray.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <limits>
#include <new>
#include <sstream>
#include <string>

using namespace coag;

namespace {

constexpr std::size_t MiB = std::size_t(1) << 20;

std::uintptr_t address(const void* p) { return reinterpret_cast<std::uintptr_t>(p); }

//- The "THPeligible" entry of the mapping in /proc/self/smaps that holds p: 1 or 0, or -1
//  where the file or the entry is missing
int thpEligible(const void* p)
{
    std::ifstream smaps("/proc/self/smaps");
    std::string line;
    bool inside = false;
    while (std::getline(smaps, line)) {
        unsigned long long lo = 0, hi = 0;
        if (std::sscanf(line.c_str(), "%llx-%llx ", &lo, &hi) == 2
            && line.find(':') > line.find('-')) {
            inside = lo <= address(p) && address(p) < hi;
            continue;
        }
        if (inside && line.rfind("THPeligible:", 0) == 0) {
            return std::stoi(line.substr(12));
        }
    }
    return -1;
}

//- The kernel's transparent huge page mode: "always", "madvise", "never" or "" (none)
std::string thpMode()
{
    std::ifstream f("/sys/kernel/mm/transparent_hugepage/enabled");
    std::string all;
    std::getline(f, all);
    const auto a = all.find('['), b = all.find(']');
    return a == std::string::npos || b == std::string::npos ? "" : all.substr(a + 1, b - a - 1);
}

} // namespace

TEST(LargeArray, SizesAndAlignments)
{
    for (std::size_t bytes : {std::size_t(0), std::size_t(1), std::size_t(63), std::size_t(64),
                              std::size_t(65), 4 * MiB - 1, 4 * MiB, 4 * MiB + 1, 9 * MiB}) {
        const std::size_t align = bytes >= largeArray::hugePageBytes ? 2 * MiB : 64;
        const std::size_t rounded = largeArray::roundedBytes(bytes);
        EXPECT_GE(rounded, bytes) << bytes;
        EXPECT_GT(rounded, 0u) << bytes;
        EXPECT_EQ(rounded % align, 0u) << bytes;
        EXPECT_LT(rounded - bytes, align + (bytes == 0 ? 1 : 0)) << bytes;
        auto* p = static_cast<unsigned char*>(largeArray::allocate(bytes));
        ASSERT_NE(p, nullptr);
        EXPECT_EQ(address(p) % align, 0u) << bytes;
        p[0] = 1;
        p[rounded - 1] = 2;  // the whole rounded size is usable
        EXPECT_EQ(p[0] + p[rounded - 1], 3);
        largeArray::deallocate(p);
    }
    EXPECT_THROW(largeArray::roundedBytes(std::numeric_limits<std::size_t>::max()),
                 std::bad_alloc);
    EXPECT_THROW(LargeArrayAllocator<double>().allocate(std::numeric_limits<std::size_t>::max() / 4),
                 std::bad_alloc);
}

TEST(LargeArray, BigArraysAreAdvisedToHugePages)
{
    const std::string mode = thpMode();
    if (mode != "madvise" && mode != "always") GTEST_SKIP() << "no transparent huge pages";
    void* big = largeArray::allocate(8 * MiB);
    const int eligible = thpEligible(big);
    largeArray::deallocate(big);
    if (eligible < 0) GTEST_SKIP() << "no THPeligible in /proc/self/smaps";
    // In "madvise" mode only the advice makes the mapping eligible (in "always" mode every
    // anonymous mapping is, and this test cannot tell)
    EXPECT_EQ(eligible, 1) << "THP mode " << mode;
}

TEST(LargeArray, ParticleRecordsKeptThroughGrowth)
{
    CellPopulation pop;
    const std::size_t n = 300000;  // 7.2 MB: on huge pages
    for (std::size_t j = 0; j < n; ++j) {
        pop.particles.push_back(Particle{ParticleType{1.0 + double(j)}, 0.5 * double(j),
                                         static_cast<std::int64_t>(j)});
    }
    EXPECT_EQ(address(pop.particles.data()) % (2 * MiB), 0u);
    for (std::size_t j = 0; j < n; ++j) {
        ASSERT_EQ(pop.particles[j].type.mass, 1.0 + double(j));
        ASSERT_EQ(pop.particles[j].weight, 0.5 * double(j));
        ASSERT_EQ(pop.particles[j].tag, static_cast<std::int64_t>(j));
    }
    ParticleVector copy = pop.particles;
    pop.particles.clear();
    pop.particles.shrink_to_fit();
    ASSERT_EQ(copy.size(), n);
    EXPECT_EQ(copy[n - 1].tag, static_cast<std::int64_t>(n - 1));
}
