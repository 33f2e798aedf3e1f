// SPDX-License-Identifier: BSD-3-Clause
/// @file z_order.cpp
#include "sampling/z_order.h"

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <utility>

namespace lsr {

namespace {

// Bit b of x moves to bit D b: the standard shift-and-mask spreading (one mask set per D, so
// two functions of the same shape).
std::uint64_t spread(std::uint64_t x, std::integral_constant<int, 2>) {
  x &= 0xffffffffu;
  x = (x | x << 16) & 0x0000ffff0000ffffu;
  x = (x | x << 8) & 0x00ff00ff00ff00ffu;
  x = (x | x << 4) & 0x0f0f0f0f0f0f0f0fu;
  x = (x | x << 2) & 0x3333333333333333u;
  return (x | x << 1) & 0x5555555555555555u;
}

std::uint64_t spread(std::uint64_t x, std::integral_constant<int, 3>) {
  x &= 0x1fffffu;
  x = (x | x << 32) & 0x001f00000000ffffu;
  x = (x | x << 16) & 0x001f0000ff0000ffu;
  x = (x | x << 8) & 0x100f00f00f00f00fu;
  x = (x | x << 4) & 0x10c30c30c30c30c3u;
  return (x | x << 2) & 0x1249249249249249u;
}

}  // namespace

template <int D>
std::uint64_t morton_key(const Vec<D>& x) {
  constexpr int bits = 64 / D;
  const double cells = std::ldexp(1.0, bits) - 1.0;
  // Bit b of coordinate d goes to bit D b + (D - 1 - d): the first coordinate leads.
  std::uint64_t key = 0;
  for (int d = 0; d < D; ++d) {
    key |= spread(std::uint64_t(std::clamp(x[d], 0.0, 1.0) * cells), std::integral_constant<int, D>()) << (D - 1 - d);
  }
  return key;
}

template <int D>
std::vector<Index> z_order(const Points<D>& points) {
  std::vector<std::pair<std::uint64_t, Index>> keys(points.size());
  const long n = long(points.size());
#pragma omp parallel for schedule(static) if (n > 20000)
  for (long i = 0; i < n; ++i) keys[std::size_t(i)] = {morton_key<D>(points[std::size_t(i)]), Index(i)};
  // The pairs are distinct, so any sort gives the same order: two halves on two threads, merged.
  const auto middle = keys.begin() + std::ptrdiff_t(keys.size() / 2);
#pragma omp parallel sections if (n > 20000)
  {
#pragma omp section
    std::sort(keys.begin(), middle);
#pragma omp section
    std::sort(middle, keys.end());
  }
  std::inplace_merge(keys.begin(), middle, keys.end());
  std::vector<Index> order(points.size());
  for (std::size_t r = 0; r < keys.size(); ++r) order[r] = keys[r].second;
  return order;
}

template std::uint64_t morton_key<2>(const Vec<2>&);
template std::uint64_t morton_key<3>(const Vec<3>&);
template std::vector<Index> z_order<2>(const Points<2>&);
template std::vector<Index> z_order<3>(const Points<3>&);

}  // namespace lsr
