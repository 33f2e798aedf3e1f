// SPDX-License-Identifier: BSD-3-Clause
/// @file z_order.cpp
#include "lsrecon/core/z_order.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace lsr {

template <int D>
std::uint64_t morton_key(const Vec<D>& x) {
  constexpr int bits = 64 / D;
  const double cells = std::ldexp(1.0, bits) - 1.0;
  std::array<std::uint64_t, D> q{};
  for (int d = 0; d < D; ++d) q[d] = std::uint64_t(std::clamp(x[d], 0.0, 1.0) * cells);
  std::uint64_t key = 0;
  for (int b = bits - 1; b >= 0; --b) {
    for (int d = 0; d < D; ++d) key = (key << 1) | ((q[d] >> b) & 1u);
  }
  return key;
}

template <int D>
std::vector<Index> z_order(const Points<D>& points) {
  std::vector<std::pair<std::uint64_t, Index>> keys(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) keys[i] = {morton_key<D>(points[i]), Index(i)};
  std::sort(keys.begin(), keys.end());
  std::vector<Index> order(points.size());
  for (std::size_t r = 0; r < keys.size(); ++r) order[r] = keys[r].second;
  return order;
}

template std::uint64_t morton_key<2>(const Vec<2>&);
template std::uint64_t morton_key<3>(const Vec<3>&);
template std::vector<Index> z_order<2>(const Points<2>&);
template std::vector<Index> z_order<3>(const Points<3>&);

}  // namespace lsr
