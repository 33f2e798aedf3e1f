// SPDX-License-Identifier: BSD-3-Clause
/// @file stitched_extraction_test.cpp
/// @brief Tiles solved apart, extracted apart, welded into one closed manifold surface: the
/// extraction of the whole mesh with the owners' values.
#include "core/mesh_checks.h"
#include "core/tile_grid.h"
#include "lsrecon/testdata/analytic_shapes.h"
#include "mesh/tile_core.h"
#include "surface/stitched_extraction.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace lsr {
namespace {

using namespace testing;

constexpr double kCut = 0.45;
const Torus kTorus{Vec<3>(0.5, 0.5, 0.5), 0.3, 0.1};

// Tile t's "solution": the shape's distance, off by a different wave in every tile (tiles
// solved apart disagree where they overlap), a quarter of the finest cell at most.
template <int D, class Shape>
double tile_value(const Shape& shape, int t, const Vec<D>& x, double h_min) {
  return shape.signed_distance(x) + 0.25 * h_min * double(t + 1) / double(1 << D) * std::sin(37.0 * x[0] + 11.0 * x[1] + 5.0 * x[D - 1]);
}

// The 2^D tiles' cores with each vertex's value from its owner, or from the tile itself.
template <int D, class Shape>
std::vector<TileField<D>> tile_fields(const Shape& shape, const Points<D>& points, const AdaptiveMeshOptions& o, bool owners) {
  std::vector<TileField<D>> out;
  for (int t = 0; t < (1 << D); ++t) {
    Vec<D> lo, hi;
    tile_box<D>(t, kCut, lo, hi);
    TileField<D> f;
    f.core = tile_core<D>(tile_mesh<D>(points, o, lo, hi, 2.0 * o.h_max), lo, hi).mesh;
    for (const Vec<D>& x : f.core.vertices) f.u.push_back(tile_value<D>(shape, owners ? tile_owner<D>(x, kCut) : t, x, o.h_min));
    out.push_back(std::move(f));
  }
  return out;
}

TEST(StitchedExtraction, TilesWithTheOwnersValuesWeldIntoTheWholeMeshsSurface) {
  const Points<3> points = kTorus.sample(20000);
  const AdaptiveMeshOptions o = two_sizes<3>(points, 1.0 / 128);
  const LevelSetMesh<3> stitched = stitched_zero_level_set<3>(tile_fields<3>(kTorus, points, o, true));
  expect_closed_surface(stitched, 1, {1});

  // The whole mesh's extraction with the same values: the same points (the seam's computed
  // from the other end of their edge differ by rounding, a few ulps of coordinates below 1)
  // and the same triangles.
  const SimplexMesh<3> whole = build_adaptive_mesh(NearestPointIndex<3>(points), o).mesh;
  std::vector<double> u;
  for (const Vec<3>& x : whole.vertices) u.push_back(tile_value<3>(kTorus, tile_owner<3>(x, kCut), x, o.h_min));
  const LevelSetMesh<3> reference = extract_zero_level_set(whole, u);
  ASSERT_EQ(stitched.vertices.size(), reference.vertices.size());
  ASSERT_EQ(stitched.facets.size(), reference.facets.size());
  const NearestPointIndex<3> index(reference.vertices);
  std::vector<double> dist;
  std::vector<Index> same;
  index.query(stitched.vertices, dist, &same);
  EXPECT_LE(*std::max_element(dist.begin(), dist.end()), 1e-15);
  auto triangles = [](const std::vector<std::array<Index, 3>>& facets, const std::vector<Index>* map) {
    std::set<std::array<Index, 3>> out;
    for (auto f : facets) {
      if (map) for (Index& v : f) v = (*map)[std::size_t(v)];
      std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());  // keeps the orientation
      out.insert(f);
    }
    return out;
  };
  EXPECT_EQ(triangles(stitched.facets, &same), triangles(reference.facets, nullptr));

  // Each tile with its own values: some seam vertices have other signs in the two tiles, and
  // there the pieces do not meet (an edge both tiles cross is welded whatever their values).
  const LevelSetMesh<3> apart = stitched_zero_level_set<3>(tile_fields<3>(kTorus, points, o, false));
  EXPECT_FALSE(analyze_surface(apart.vertices, apart.facets).watertight);
}

// In 2D the pieces are curves: with the owners' values they close into the circle's one loop.
TEST(StitchedExtraction, CurvesOfFourTilesCloseIntoOneLoop) {
  const Circle circle{Vec<2>(0.5, 0.5), 0.3};
  const Points<2> points = circle.sample(20000);
  const AdaptiveMeshOptions o = two_sizes<2>(points, 1.0 / 1024);
  const LevelSetMesh<2> stitched = stitched_zero_level_set<2>(tile_fields<2>(circle, points, o, true));
  EXPECT_EQ(closed_loops(stitched).size(), 1u);
}

}  // namespace
}  // namespace lsr
