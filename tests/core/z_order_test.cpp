// SPDX-License-Identifier: BSD-3-Clause
/// @file z_order_test.cpp
/// @brief Morton keys interleave the coordinates' bits, first coordinate leading; z_order sorts by them.
#include "sampling/z_order.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace lsr {
namespace {

// The definition, one bit at a time.
template <int D>
std::uint64_t interleaved_bits(const Vec<D>& x) {
  constexpr int bits = 64 / D;
  const double cells = std::ldexp(1.0, bits) - 1.0;
  std::uint64_t key = 0;
  for (int b = bits - 1; b >= 0; --b) {
    for (int d = 0; d < D; ++d) key = (key << 1) | ((std::uint64_t(std::clamp(x[d], 0.0, 1.0) * cells) >> b) & 1u);
  }
  return key;
}

template <int D>
void check_keys_and_order() {
  std::mt19937 random(3);
  std::uniform_real_distribution<double> coordinate(-0.1, 1.1);  // clamped outside [0, 1]
  Points<D> points(50000);
  for (auto& p : points) {
    for (int d = 0; d < D; ++d) p[d] = coordinate(random);
  }
  points[0].setZero();
  points[1].setOnes();
  for (const auto& p : points) ASSERT_EQ(morton_key<D>(p), interleaved_bits<D>(p));
  const std::vector<Index> order = z_order<D>(points);
  ASSERT_EQ(order.size(), points.size());
  for (std::size_t r = 1; r < order.size(); ++r) {
    const auto a = morton_key<D>(points[std::size_t(order[r - 1])]), b = morton_key<D>(points[std::size_t(order[r])]);
    ASSERT_TRUE(a < b || (a == b && order[r - 1] < order[r])) << "rank " << r;
  }
}

TEST(ZOrder, KeysInterleaveTheBitsAndTheOrderSortsThem2D) { check_keys_and_order<2>(); }
TEST(ZOrder, KeysInterleaveTheBitsAndTheOrderSortsThem3D) { check_keys_and_order<3>(); }

}  // namespace
}  // namespace lsr
