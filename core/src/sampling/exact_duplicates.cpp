// SPDX-License-Identifier: BSD-3-Clause
/// @file exact_duplicates.cpp
#include "sampling/exact_duplicates.h"

#include <cstdint>
#include <cstring>
#include <unordered_map>

namespace lsr {
namespace {

template <int D>
struct CoordinateHash {
  const Points<D>* points;
  std::size_t operator()(std::size_t i) const {
    std::uint64_t h = 1469598103934665603ull;  // FNV-1a over the coordinates' bits
    for (int k = 0; k < D; ++k) {
      const double c = (*points)[i][k] + 0.0;  // -0.0 + 0.0 is +0.0: equal values, equal bits
      std::uint64_t bits;
      std::memcpy(&bits, &c, sizeof(bits));
      h = (h ^ bits) * 1099511628211ull;
    }
    return std::size_t(h ^ (h >> 29));
  }
};

template <int D>
struct SameCoordinates {
  const Points<D>* points;
  bool operator()(std::size_t a, std::size_t b) const { return (*points)[a] == (*points)[b]; }
};

}  // namespace

template <int D>
DistinctPoints<D> merge_exact_duplicates(const Points<D>& points) {
  DistinctPoints<D> out;
  out.index_of.resize(points.size());
  // Keyed by the input index of a first copy, compared through the coordinates.
  std::unordered_map<std::size_t, std::size_t, CoordinateHash<D>, SameCoordinates<D>> seen(
      points.size(), CoordinateHash<D>{&points}, SameCoordinates<D>{&points});
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto [at, inserted] = seen.emplace(i, out.points.size());
    if (inserted) {
      out.points.push_back(points[i]);
      out.first.push_back(i);
    }
    out.index_of[i] = at->second;
  }
  return out;
}

template DistinctPoints<2> merge_exact_duplicates<2>(const Points<2>&);
template DistinctPoints<3> merge_exact_duplicates<3>(const Points<3>&);

}  // namespace lsr
