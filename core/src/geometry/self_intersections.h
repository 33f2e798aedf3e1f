// SPDX-License-Identifier: BSD-3-Clause
/// @file self_intersections.h
/// @brief The pairs of facets of a surface (triangles) or curve (segments) that intersect other
/// than in what they share, decided exactly (facet_intersection.h); candidates from a
/// bounding-volume hierarchy (Eigen's KdBVH) of boxes that may hold each facet over a move.
#pragma once

#include "lsrecon/core/types.h"

#include <Eigen/Geometry>
#include <unsupported/Eigen/BVH>

#include <array>
#include <utility>
#include <vector>

namespace lsr::detail {

template <int D>
class SelfIntersections {
 public:
  using Facet = std::array<Index, D>;
  using Pair = std::pair<Index, Index>;

  /// @brief Boxes of each facet at `from` and, when `to` is given (#from entries), at `to`: a
  /// vertex anywhere on the segment between its two positions stays in its facets' boxes.
  SelfIntersections(const std::vector<Facet>& facets, const Points<D>& from, const Points<D>& to = {});

  /// @brief The intersecting pairs (i < j) at positions `x` (within the boxes), of which one
  /// facet is `among` (#facets flags; empty: every pair), in order.
  std::vector<Pair> pairs(const Points<D>& x, const std::vector<char>& among, int threads) const;

 private:
  using Box = Eigen::AlignedBox<double, D>;
  const std::vector<Facet>& facets_;
  std::vector<Box> boxes_;
  Eigen::KdBVH<double, D, Index> tree_;
};

/// @brief How many pairs of facets intersect (0: the surface or curve is embedded).
std::size_t count_self_intersections(const Points<2>& x, const std::vector<std::array<Index, 2>>& facets, int threads);
std::size_t count_self_intersections(const Points<3>& x, const std::vector<std::array<Index, 3>>& facets, int threads);

}  // namespace lsr::detail
