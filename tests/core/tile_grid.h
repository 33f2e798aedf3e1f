// SPDX-License-Identifier: BSD-3-Clause
/// @file tile_grid.h
/// @brief 2^D tiles of [0,1]^D cut at one coordinate along every axis, each meshed from the
/// data near its region alone (tile_mesh_test.cpp, stitched_extraction_test.cpp).
#pragma once

#include "mesh/adaptive_refinement.h"

#include <cmath>
#include <vector>

namespace lsr::testing {

// Tile t's core [lo, hi): the upper tiles reach past 1, so every point of the box has one owner.
template <int D>
void tile_box(int t, double cut, Vec<D>& lo, Vec<D>& hi) {
  for (int a = 0; a < D; ++a) lo[a] = (t >> a & 1) ? cut : 0.0, hi[a] = (t >> a & 1) ? 2.0 : cut;
}

// The tile whose core holds x.
template <int D>
int tile_owner(const Vec<D>& x, double cut) {
  int t = 0;
  for (int a = 0; a < D; ++a) t |= int(x[a] >= cut) << a;
  return t;
}

// Marks the whole mesh's rule would make in the region are made from the data within
// 2 radius + size / grading of it: a simplex meeting the region has its centroid within its
// radius of it, and searches within radius + size / grading of its centroid. The radius of a
// simplex of size c is at most its longest edge, sqrt(D) c, and no size exceeds h_max.
inline double data_reach(const AdaptiveMeshOptions& o, int dim) {
  return (2.0 * std::sqrt(double(dim)) + 1.0 / o.grading) * o.h_max;
}

// The tile's mesh: refined by the rule in its core widened by `margin`, from the points (and
// their sizes) within that region's data reach.
template <int D>
SimplexMesh<D> tile_mesh(const Points<D>& points, const AdaptiveMeshOptions& o, const Vec<D>& lo, const Vec<D>& hi, double margin) {
  AdaptiveMeshOptions to = o;
  to.region_lo.assign(D, 0.0), to.region_hi.assign(D, 0.0);
  for (int a = 0; a < D; ++a) to.region_lo[std::size_t(a)] = lo[a] - margin, to.region_hi[std::size_t(a)] = hi[a] + margin;
  const double reach = margin + data_reach(o, D);
  Points<D> near;
  to.point_size.clear();
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec<D>& p = points[i];
    if (((p - lo).array() < -reach).any() || ((hi - p).array() < -reach).any()) continue;
    near.push_back(p);
    to.point_size.push_back(o.point_size[i]);
  }
  return build_adaptive_mesh(NearestPointIndex<D>(near), to).mesh;
}

// Sizes that vary fourfold across x = 0.5: the conforming closure grades between them.
template <int D>
AdaptiveMeshOptions two_sizes(const Points<D>& points, double h_min) {
  AdaptiveMeshOptions o;
  o.h_min = h_min;
  o.h_max = 1.0 / 32;
  for (const Vec<D>& p : points) o.point_size.push_back(p[0] < 0.5 ? h_min : 4.0 * h_min);
  return o;
}

}  // namespace lsr::testing
