// SPDX-License-Identifier: BSD-3-Clause
/// @file embedded_moves.h
/// @brief The moves of a surface's vertices after the extraction (the projection onto the fit,
/// the fairing, the refinement onto the fit), kept embedded: a level set of a P1 field on a
/// simplicial mesh does not intersect itself, a vertex moved past its neighbours or through
/// another sheet would make it.
#pragma once

#include "lsrecon/core/level_set_extraction.h"

#include <algorithm>
#include <vector>

namespace lsr::detail {

/// @brief Shortens the moves from `embedded` (#surface vertices) to the surface's positions
/// until no two facets intersect (self_intersections.h): round after round, each moved vertex
/// of an intersecting pair keeps 3/4 of its move, after kRounds rounds none of it. With
/// `float_grid`, every position (the embedded ones, the targets and each shortened one) is first
/// rounded to float: what float readers (PCL's PolygonMesh, STL, VTK, OpenMesh's PLY reader)
/// see is then exactly what was checked, whatever their rounding. Shortened vertices take their
/// facets' normals in `normals` (#vertices, or empty).
/// @pre the surface at `embedded` (rounded, with `float_grid`) does not intersect itself: an
/// extracted level set, or a subdivision of one.
/// @post the surface does not intersect itself: each round puts a vertex back for good or
/// shortens moves, and the surface at `embedded` is embedded.
/// @return the vertices whose moves were shortened (#vertices flags)
template <int D>
std::vector<char> keep_embedded(LevelSetMesh<D>& surface, Points<D> embedded, bool float_grid, Points<D>& normals, int threads);

/// @brief x rounded to float, as a float reader stores it. Through a volatile float: GCC 12's
/// SLP vectorizer drops a double-to-float-to-double round trip of adjacent values (-O2).
template <int D>
Vec<D> rounded_to_float(const Vec<D>& x) {
  Vec<D> rounded;
  for (int k = 0; k < D; ++k) {
    const volatile float f = static_cast<float>(x[k]);
    rounded[k] = f;
  }
  return rounded;
}

/// @brief Whether rounding `x` to float moves no vertex farther than `resolution`: by at most
/// 2^-24 of its largest coordinate (half a float's unit in the last place).
template <int D>
bool float_grid_is_finer(const Points<D>& x, double resolution) {
  double largest = 0.0;
  for (const auto& p : x) largest = std::max(largest, p.template lpNorm<Eigen::Infinity>());
  return 0x1p-24 * largest <= resolution;
}

}  // namespace lsr::detail
