// core/base/recycled.hpp: mid-size blocks kept when given back, and taken again by the next
// block of their size class.
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "core/base/recycled.hpp"

namespace sprout {
namespace {

using recycled::kKeeps;

TEST(Recycled, ABlockGivenBackIsTheNextOneOfItsSize) {
    if (!kKeeps) GTEST_SKIP() << "nothing is kept under AddressSanitizer";
    const std::size_t before = recycled::keptBytes();
    if (before + (std::size_t(1) << 20) > recycled::kKept) GTEST_SKIP() << "the cache is full (an earlier test)";
    void* a = recycled::take(100'000);
    std::memset(a, 1, 100'000);  // all of it usable
    recycled::give(a, 100'000);
    EXPECT_GE(recycled::keptBytes(), before + 100'000);
    // Another size of the same class (at most a quarter above it) takes that very block.
    void* b = recycled::take(99'000);
    EXPECT_EQ(b, a);
    std::memset(b, 2, 99'000);
    recycled::give(b, 99'000);
}

TEST(Recycled, SmallAndHugeBlocksAreNotKept) {
    const std::size_t before = recycled::keptBytes();
    void* small = recycled::take(100);
    recycled::give(small, 100);
    void* huge = recycled::take(std::size_t(16) << 20);
    recycled::give(huge, std::size_t(16) << 20);
    EXPECT_EQ(recycled::keptBytes(), before);
}

TEST(Recycled, WhatIsKeptStaysUnderItsCap) {
    std::vector<void*> blocks;
    for (int i = 0; i < 40; ++i) blocks.push_back(recycled::take(std::size_t(4) << 20));  // 160 MB
    for (void* p : blocks) recycled::give(p, std::size_t(4) << 20);
    EXPECT_LE(recycled::keptBytes(), recycled::kKept);
    if (kKeeps) EXPECT_GT(recycled::keptBytes(), recycled::kKept / 2);
}

TEST(Recycled, AVectorOfRecycledMemoryHoldsItsElements) {
    std::vector<int, recycled::Allocator<int>> v;
    for (int i = 0; i < 200'000; ++i) v.push_back(i);  // grows through many size classes
    std::vector<int, recycled::Allocator<int>> w = v;
    v.clear();
    v.shrink_to_fit();
    long long sum = 0;
    for (int x : w) sum += x;
    EXPECT_EQ(sum, 199'999LL * 200'000 / 2);
}

}  // namespace
}  // namespace sprout
