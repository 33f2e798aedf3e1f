// SPDX-License-Identifier: BSD-3-Clause
/// @file stitched_extraction_test.cpp
/// @brief Tiles solved apart, extracted apart, welded into one closed manifold surface: the
/// extraction of the whole mesh with the owners' values.
#include "core/tile_grid.h"
#include "lsrecon/testdata/analytic_shapes.h"
#include "mesh/tile_core.h"
#include "surface/stitched_extraction.h"
#include "surface/surface_topology.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace lsr {
namespace {

using namespace testing;

constexpr double kCut = 0.45;
const Torus kTorus{Vec<3>(0.5, 0.5, 0.5), 0.3, 0.1};

// Tile t's "solution": the torus's distance, off by a different wave in every tile (tiles
// solved apart disagree where they overlap), a quarter of the finest cell at most.
double tile_value(int t, const Vec<3>& x, double h_min) {
  return kTorus.signed_distance(x) + 0.25 * h_min * double(t + 1) / 8.0 * std::sin(37.0 * x[0] + 11.0 * x[1] + 5.0 * x[2]);
}

int owner(const Vec<3>& x) {
  for (int t = 0; t < 8; ++t) {
    Vec<3> lo, hi;
    tile_box<3>(t, kCut, lo, hi);
    if (((x - lo).array() >= 0.0).all() && ((hi - x).array() > 0.0).all()) return t;
  }
  return -1;
}

// The 8 tiles' cores with each vertex's value from its owner, or from the tile itself.
std::vector<TileField<3>> tile_fields(const Points<3>& points, const AdaptiveMeshOptions& o, bool owners) {
  std::vector<TileField<3>> out;
  for (int t = 0; t < 8; ++t) {
    Vec<3> lo, hi;
    tile_box<3>(t, kCut, lo, hi);
    TileField<3> f;
    f.core = tile_core<3>(tile_mesh<3>(points, o, lo, hi, 2.0 * o.h_max), lo, hi).mesh;
    for (const Vec<3>& x : f.core.vertices) f.u.push_back(tile_value(owners ? owner(x) : t, x, o.h_min));
    out.push_back(std::move(f));
  }
  return out;
}

TEST(StitchedExtraction, TilesWithTheOwnersValuesWeldIntoTheWholeMeshsSurface) {
  const Points<3> points = kTorus.sample(20000);
  const AdaptiveMeshOptions o = two_sizes<3>(points, 1.0 / 128);
  const LevelSetMesh<3> stitched = stitched_zero_level_set<3>(tile_fields(points, o, true));

  const SurfaceTopology topology = analyze_surface(stitched.vertices, stitched.facets);
  EXPECT_TRUE(topology.watertight);
  EXPECT_TRUE(topology.edge_manifold);
  EXPECT_TRUE(topology.vertex_manifold);
  EXPECT_TRUE(topology.oriented);
  EXPECT_EQ(topology.components, 1);
  EXPECT_EQ(topology.genus, std::vector<int>{1});
  EXPECT_GT(topology.signed_volume, 0.0);

  // The whole mesh's extraction with the same values: the same points (the seam's computed
  // from the other end of their edge differ by rounding, a few ulps of coordinates below 1)
  // and the same triangles.
  const SimplexMesh<3> whole = build_adaptive_mesh(NearestPointIndex<3>(points), o).mesh;
  std::vector<double> u;
  for (const Vec<3>& x : whole.vertices) u.push_back(tile_value(owner(x), x, o.h_min));
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

  // Each tile with its own values: the pieces do not meet on the seams.
  const LevelSetMesh<3> apart = stitched_zero_level_set<3>(tile_fields(points, o, false));
  EXPECT_FALSE(analyze_surface(apart.vertices, apart.facets).watertight);
}

// In 2D the pieces are curves: with the owners' values they close into the circle's one loop.
TEST(StitchedExtraction, CurvesOfFourTilesCloseIntoOneLoop) {
  const Circle circle{Vec<2>(0.5, 0.5), 0.3};
  const Points<2> points = circle.sample(20000);
  const AdaptiveMeshOptions o = two_sizes<2>(points, 1.0 / 1024);
  auto value = [&](int t, const Vec<2>& x) { return circle.signed_distance(x) + 0.25 * o.h_min * double(t + 1) / 4.0 * std::sin(41.0 * x[0] + 7.0 * x[1]); };
  auto fields = [&](bool owners) {
    std::vector<TileField<2>> out;
    for (int t = 0; t < 4; ++t) {
      Vec<2> lo, hi;
      tile_box<2>(t, kCut, lo, hi);
      TileField<2> f;
      f.core = tile_core<2>(tile_mesh<2>(points, o, lo, hi, 2.0 * o.h_max), lo, hi).mesh;
      for (const Vec<2>& x : f.core.vertices) {
        int owner = t;
        for (int k = 0; owners && k < 4; ++k) {
          Vec<2> a, b;
          tile_box<2>(k, kCut, a, b);
          if (((x - a).array() >= 0.0).all() && ((b - x).array() > 0.0).all()) owner = k;
        }
        f.u.push_back(value(owner, x));
      }
      out.push_back(std::move(f));
    }
    return out;
  };
  const LevelSetMesh<2> stitched = stitched_zero_level_set<2>(fields(true));
  EXPECT_EQ(closed_loops(stitched).size(), 1u);
  EXPECT_THROW(closed_loops(stitched_zero_level_set<2>(fields(false))), InvalidInput);
}

}  // namespace
}  // namespace lsr
