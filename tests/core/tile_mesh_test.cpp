// SPDX-License-Identifier: BSD-3-Clause
/// @file tile_mesh_test.cpp
/// @brief A tile's mesh: the adaptive mesh refined by the sizing rule only in a region around
/// the tile's core, from the data near that region alone, has the whole mesh's simplices in
/// its core (the first step of solving in tiles).
#include "lsrecon/testdata/analytic_shapes.h"
#include "mesh/adaptive_refinement.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <set>
#include <vector>

namespace lsr {
namespace {

using Leaf = std::vector<double>;  // sorted vertex coordinates

// The leaves whose centroid lies in [lo, hi): the cores of a grid of tiles partition the mesh.
template <int D>
std::set<Leaf> core_leaves(const SimplexMesh<D>& m, const Vec<D>& lo, const Vec<D>& hi) {
  std::set<Leaf> out;
  for (const auto& s : m.simplices) {
    Vec<D> c = Vec<D>::Zero();
    std::vector<Leaf> v;
    for (Index i : s) {
      const Vec<D>& p = m.vertices[std::size_t(i)];
      c += p / double(D + 1);
      v.emplace_back(p.data(), p.data() + D);
    }
    if (((c - lo).array() >= 0.0).all() && ((hi - c).array() > 0.0).all()) {
      std::sort(v.begin(), v.end());
      Leaf key;
      for (const Leaf& p : v) key.insert(key.end(), p.begin(), p.end());
      out.insert(key);
    }
  }
  return out;
}

// Marks the whole mesh's rule would make in the region are made from the data within
// 2 radius + size / grading of it: a simplex meeting the region has its centroid within its
// radius of it, and searches within radius + size / grading of its centroid. The radius of a
// simplex of size c is at most its longest edge, sqrt(D) c, and no size exceeds h_max.
double data_reach(const AdaptiveMeshOptions& o, int dim) { return (2.0 * std::sqrt(double(dim)) + 1.0 / o.grading) * o.h_max; }

// Splits [0,1]^D at `cut` along every axis into 2^D tiles, meshes each from the data near its
// region (the core widened by `margin`) and counts the simplices in which the cores differ from
// the whole mesh's.
template <int D>
std::size_t core_differences(const Points<D>& points, const AdaptiveMeshOptions& o, double cut, double margin) {
  const SimplexMesh<D> whole = build_adaptive_mesh(NearestPointIndex<D>(points), o).mesh;
  std::size_t differ = 0;
  for (int t = 0; t < (1 << D); ++t) {
    Vec<D> lo, hi;
    for (int a = 0; a < D; ++a) lo[a] = (t >> a & 1) ? cut : 0.0, hi[a] = (t >> a & 1) ? 1.0 : cut;
    AdaptiveMeshOptions to = o;
    to.region_lo.assign(D, 0.0), to.region_hi.assign(D, 0.0);
    for (int a = 0; a < D; ++a) to.region_lo[a] = lo[a] - margin, to.region_hi[a] = hi[a] + margin;
    const double reach = margin + data_reach(o, D);
    Points<D> near;
    to.point_size.clear();  // the sizes of the tile's points
    for (std::size_t i = 0; i < points.size(); ++i) {
      const Vec<D>& p = points[i];
      if (((p - lo).array() < -reach).any() || ((hi - p).array() < -reach).any()) continue;
      near.push_back(p);
      to.point_size.push_back(o.point_size[i]);
    }
    const SimplexMesh<D> tile = build_adaptive_mesh(NearestPointIndex<D>(near), to).mesh;
    std::vector<Leaf> diff;
    const std::set<Leaf> a = core_leaves<D>(whole, lo, hi), b = core_leaves<D>(tile, lo, hi);
    std::set_symmetric_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(diff));
    differ += diff.size();
  }
  return differ;
}

// Sizes that vary fourfold across the cut: the conforming closure grades between them.
template <int D>
AdaptiveMeshOptions two_sizes(const Points<D>& points, double h_min) {
  AdaptiveMeshOptions o;
  o.h_min = h_min;
  o.h_max = 1.0 / 32;
  for (const Vec<D>& p : points) o.point_size.push_back(p[0] < 0.5 ? h_min : 4.0 * h_min);
  return o;
}

// The closure of a bisection outside the region refines coarser simplices next to it, which
// may lie in the core: without a margin the cores differ (the region is not ignored). Two
// background cells (2 h_max) of margin suffice: on this torus one did at h_max = 1/16 and 1/32,
// two at 1/64. Not a proof: one closure chain reaches at most about 8.4 h_max in 3D (its simplices
// grow 2^(1/D) a step, each adjacent to the last), but simplices it creates inside the region
// may be marked and chain further, so stitched tiles will check their seams.
TEST(TileMesh, CoresEqualTheWholeMeshWithAMarginOfTwoBackgroundCells) {
  const Points<3> torus = Torus{Vec<3>(0.5, 0.5, 0.5), 0.3, 0.1}.sample(20000);
  const AdaptiveMeshOptions o3 = two_sizes<3>(torus, 1.0 / 128);
  EXPECT_GT(core_differences<3>(torus, o3, 0.45, 0.0), 0u);
  EXPECT_EQ(core_differences<3>(torus, o3, 0.45, 2.0 * o3.h_max), 0u);

  const Points<2> circle = Circle{Vec<2>(0.5, 0.5), 0.3}.sample(20000);
  const AdaptiveMeshOptions o2 = two_sizes<2>(circle, 1.0 / 1024);
  EXPECT_GT(core_differences<2>(circle, o2, 0.47, 0.0), 0u);  // a cut where the closure crosses
  EXPECT_EQ(core_differences<2>(circle, o2, 0.47, 2.0 * o2.h_max), 0u);

  AdaptiveMeshOptions bad = o2;
  bad.region_lo = {0.0, 0.0, 0.0}, bad.region_hi = {1.0, 1.0, 1.0};
  EXPECT_THROW(build_adaptive_mesh(NearestPointIndex<2>(circle), bad), InvalidInput);
}

}  // namespace
}  // namespace lsr
