// SPDX-License-Identifier: BSD-3-Clause
/// @file large_array_allocator_test.cpp
/// @brief LargeVector behaves as a std::vector on both sides of the large-array threshold, and
/// places large storage on huge-page boundaries.
#include "lsrecon/core/large_array_allocator.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <numeric>
#include <thread>

namespace lsr {
namespace {

constexpr std::uintptr_t kHugePage = std::uintptr_t(2) << 20;

TEST(LargeArrayAllocator, GrowthAcrossTheThresholdKeepsTheContents) {
  // From small storage (operator new) to large (aligned and advised) and back by shrinking.
  const std::size_t large = 3 * detail::kLargeArrayBytes / sizeof(std::int64_t);
  LargeVector<std::int64_t> v;
  for (std::size_t i = 0; i < large; ++i) v.push_back(std::int64_t(i) * 7);
  ASSERT_EQ(v.size(), large);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(v.data()) % kHugePage, 0u);
  for (std::size_t i = 0; i < large; i += 9973) ASSERT_EQ(v[i], std::int64_t(i) * 7) << i;
  EXPECT_EQ(v.back(), std::int64_t(large - 1) * 7);
  v.resize(10);
  v.shrink_to_fit();
  EXPECT_EQ(v.size(), 10u);
  EXPECT_EQ(v[9], 63);
}

TEST(LargeArrayAllocator, CopiesAndMovesAreIndependentStorage) {
  LargeVector<double> a(detail::kLargeArrayBytes / sizeof(double) + 1);
  std::iota(a.begin(), a.end(), 0.5);
  LargeVector<double> b = a;
  b[0] = -1.0;
  EXPECT_EQ(a[0], 0.5);
  const double* storage = a.data();
  LargeVector<double> c = std::move(a);
  EXPECT_EQ(c.data(), storage);
  EXPECT_EQ(c.back(), double(c.size() - 1) + 0.5);
  EXPECT_TRUE(LargeArrayAllocator<double>() == LargeArrayAllocator<int>());
}

TEST(LargeArrayAllocator, PopulatingLeavesTheContentsAndStopsAtTheCapacity) {
  const std::size_t n = 3 * detail::kLargeArrayBytes / sizeof(std::int64_t);
  LargeVector<std::int64_t> v(n / 2);
  std::iota(v.begin(), v.end(), std::int64_t(1));
  v.reserve(n);
  // From inside the live elements (the page holding them) to past the capacity: clamped.
  const StorageRange range = storage_range(v, n / 4 + 3, 2 * n);
  EXPECT_EQ(range.begin, static_cast<const void*>(v.data() + n / 4 + 3));
  EXPECT_EQ(range.bytes, (n - n / 4 - 3) * sizeof(std::int64_t));
  EXPECT_EQ(storage_range(v, n, n + 5).bytes, 0u);
  EXPECT_EQ(storage_range(v, 7, 7).bytes, 0u);
  // Populated while this thread appends: the appended and the earlier values stay.
  std::thread helper([range] { populate(range); });
  for (std::size_t i = n / 2; i < n; ++i) v.push_back(std::int64_t(i) + 1);
  helper.join();
  for (std::size_t i = 0; i < n; i += 4099) ASSERT_EQ(v[i], std::int64_t(i) + 1) << i;
  EXPECT_EQ(v.back(), std::int64_t(n));
}

TEST(LargeArrayAllocator, ImpossibleSizesThrow) {
  LargeArrayAllocator<double> allocator;
  EXPECT_THROW((void)allocator.allocate(std::numeric_limits<std::size_t>::max() / 4), std::bad_array_new_length);
}

}  // namespace
}  // namespace lsr
