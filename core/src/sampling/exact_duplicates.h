// SPDX-License-Identifier: BSD-3-Clause
/// @file exact_duplicates.h
/// @brief Merges points with equal coordinates, in time linear in their number. Scanners write
/// (0,0,0) for every missing return: 40,000 copies of one point made every k-nearest query of
/// the sampling scan all of them (43 s for a 3,000-point sphere).
#pragma once

#include "lsrecon/core/types.h"

#include <vector>

namespace lsr {

/// @brief The distinct points of a set and where each point went.
template <int D>
struct DistinctPoints {
  Points<D> points;                    ///< each position once, in order of first appearance
  std::vector<std::size_t> first;      ///< #points: the input index of each one's first copy
  std::vector<std::size_t> index_of;   ///< #input: the index in points of each input point
  std::size_t duplicates() const { return index_of.size() - points.size(); }
};

/// @brief Merges the points of `points` whose coordinates compare equal (0.0 == -0.0); a set
/// without duplicates comes back in the same order. Expected O(n) (a hash of the coordinates).
/// @note Every coordinate must be finite (NaN never compares equal: drop_non_finite first).
template <int D>
DistinctPoints<D> merge_exact_duplicates(const Points<D>& points);

}  // namespace lsr
