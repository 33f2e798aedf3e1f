// SPDX-License-Identifier: BSD-3-Clause
/// @file tile_mesh_test.cpp
/// @brief A tile's mesh: the adaptive mesh refined by the sizing rule only in a region around
/// the tile's core, from the data near that region alone, has the whole mesh's simplices in
/// its core (the first step of solving in tiles).
#include "core/tile_grid.h"
#include "lsrecon/testdata/analytic_shapes.h"
#include "mesh/tile_core.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <iterator>
#include <set>
#include <vector>

namespace lsr {
namespace {

using namespace testing;
using Leaf = std::vector<double>;  // sorted vertex coordinates

template <int D>
std::set<Leaf> leaves(const SimplexMesh<D>& m) {
  std::set<Leaf> out;
  for (const auto& s : m.simplices) {
    std::vector<Leaf> v;
    for (Index i : s) v.emplace_back(m.vertices[std::size_t(i)].data(), m.vertices[std::size_t(i)].data() + D);
    std::sort(v.begin(), v.end());
    Leaf key;
    for (const Leaf& p : v) key.insert(key.end(), p.begin(), p.end());
    out.insert(key);
  }
  return out;
}

// The simplices in which the 2^D tiles' cores differ from the whole mesh's.
template <int D>
std::size_t core_differences(const Points<D>& points, const AdaptiveMeshOptions& o, double cut, double margin) {
  const SimplexMesh<D> whole = build_adaptive_mesh(NearestPointIndex<D>(points), o).mesh;
  std::size_t differ = 0;
  for (int t = 0; t < (1 << D); ++t) {
    Vec<D> lo, hi;
    tile_box<D>(t, cut, lo, hi);
    const std::set<Leaf> a = leaves<D>(tile_core<D>(whole, lo, hi).mesh);
    const std::set<Leaf> b = leaves<D>(tile_core<D>(tile_mesh<D>(points, o, lo, hi, margin), lo, hi).mesh);
    std::vector<Leaf> diff;
    std::set_symmetric_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(diff));
    differ += diff.size();
  }
  return differ;
}

// The closure of a bisection outside the region refines coarser simplices next to it, which
// may lie in the core: without a margin the cores differ (the region is not ignored). Two
// background cells (2 h_max) of margin suffice: on this torus one did at h_max = 1/16 and 1/32,
// two at 1/64. Not a proof: one closure chain reaches at most about 8.4 h_max in 3D (its
// simplices grow 2^(1/D) a step, each adjacent to the last), but simplices it creates inside the
// region may be marked and chain further, so stitched tiles will check their seams.
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

TEST(TileMesh, CoreKeepsTheSimplicesWhoseCentroidItHolds) {
  SimplexMesh<2> m;
  m.vertices = {Vec<2>(0, 0), Vec<2>(1, 0), Vec<2>(1, 1), Vec<2>(0, 1)};
  m.simplices.push_back({0, 1, 2});  // centroid (2/3, 1/3)
  m.simplices.push_back({0, 2, 3});  // centroid (1/3, 2/3)
  const TileCore<2> right = tile_core<2>(m, Vec<2>(0.5, 0.0), Vec<2>(2.0, 2.0));
  ASSERT_EQ(right.mesh.simplices.size(), 1u);
  EXPECT_EQ(right.vertex, (std::vector<Index>{0, 1, 2}));
  EXPECT_EQ(right.mesh.simplices[0], (std::array<Index, 3>{0, 1, 2}));
  const TileCore<2> left = tile_core<2>(m, Vec<2>(0.0, 0.0), Vec<2>(0.5, 2.0));
  ASSERT_EQ(left.mesh.simplices.size(), 1u);
  EXPECT_EQ(left.vertex, (std::vector<Index>{0, 2, 3}));
  EXPECT_EQ(left.mesh.simplices[0], (std::array<Index, 3>{0, 1, 2}));
  EXPECT_EQ(left.mesh.vertices[2], Vec<2>(0, 1));
}

}  // namespace
}  // namespace lsr
