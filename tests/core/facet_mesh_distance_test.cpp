// SPDX-License-Identifier: BSD-3-Clause
/// @file facet_mesh_distance_test.cpp
/// @brief Distances to triangle meshes: exact against brute force, and the inside test robust
/// to rays through edges and vertices.
#include "geometry/facet_mesh_distance.h"

#include "core/mesh_checks.h"
#include "geometry/point_simplex_distance.h"
#include "lsrecon/core/errors.h"
#include "lsrecon/core/level_set_extraction.h"
#include "lsrecon/testdata/analytic_shapes.h"
#include "mesh/adaptive_refinement.h"

#include <gtest/gtest.h>

#include <random>

namespace lsr {
namespace {

// The unit cube, each face cut along its diagonal, outward.
TriangleMeshDistance unit_cube() {
  Points<3> v;
  for (int i = 0; i < 8; ++i) v.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  std::vector<std::array<Index, 3>> f = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                                         {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  return TriangleMeshDistance(v, f);
}

TEST(TriangleMeshDistance, RaysThroughEdgesAndVerticesCountOnce) {
  const TriangleMeshDistance cube = unit_cube();
  // Rays along +x through face diagonals, edges and vertices of the cube, from inside and out.
  for (double y : {0.0, 0.25, 0.5, 1.0}) {
    for (double z : {0.0, 0.5, 0.75, 1.0}) {
      const bool on_boundary_line = y == 0.0 || y == 1.0 || z == 0.0 || z == 1.0;
      for (double x : {-1.0, 0.5, 2.0}) {
        const Vec<3> q(x, y, z);
        const bool inside = x == 0.5 && !on_boundary_line;
        if (x == 0.5 && on_boundary_line) continue;  // on the surface: either answer
        EXPECT_EQ(cube.inside(q), inside) << q.transpose();
      }
    }
  }
  EXPECT_DOUBLE_EQ(cube.signed_distance(Vec<3>(0.5, 0.5, 0.4)), -0.4);
  EXPECT_DOUBLE_EQ(cube.signed_distance(Vec<3>(2.0, 0.5, 0.5)), 1.0);
  EXPECT_NEAR(cube.signed_distance(Vec<3>(2.0, 2.0, 2.0)), std::sqrt(3.0), 1e-15);
}

TEST(TriangleMeshDistance, MatchesBruteForceAndTheSphereInsideOut) {
  // A closed surface from an analytic sphere: distances and signs against brute force and
  // against the sphere itself (which the mesh approximates within the interpolation error).
  const Sphere sphere{Vec<3>(0.5, 0.5, 0.5), 0.3};
  const testing::SampledField<3> f =
      testing::sampled_field<3>(sphere.sample(2000), 1.0 / 32, [&](const Vec<3>& x) { return sphere.signed_distance(x); });
  const LevelSetMesh<3> s = extract_zero_level_set(f.adaptive.mesh, f.values);
  const TriangleMeshDistance mesh(s.vertices, s.facets);
  std::mt19937 random(3);
  std::uniform_real_distribution<double> coordinate(0.0, 1.0);
  Points<3> queries;
  for (int k = 0; k < 300; ++k) queries.emplace_back(coordinate(random), coordinate(random), coordinate(random));
  const std::vector<double> fast = mesh.distances(queries);
  // The extraction misplaces the surface by at most kappa L^2 / 8 (L = sqrt(3) h, kappa = 1/r).
  const double L = std::sqrt(3.0) / 32;
  const double error = L * L / (8 * 0.3 * (1 - L / 0.3));
  for (std::size_t k = 0; k < queries.size(); ++k) {
    double brute = std::numeric_limits<double>::infinity();
    for (const auto& t : s.facets) {
      brute = std::min(brute, triangle_distance(queries[k], s.vertices[t[0]], s.vertices[t[1]], s.vertices[t[2]]));
    }
    EXPECT_EQ(fast[k], brute) << k;
    EXPECT_EQ(mesh.distance(queries[k]), brute) << k;
    const double exact = sphere.signed_distance(queries[k]);
    EXPECT_NEAR(mesh.signed_distance(queries[k]), exact, error + 1e-12) << queries[k].transpose();
  }
}

TEST(CurveDistance, RaysThroughVerticesCountOnceAndDistancesAreExact) {
  // The unit square, counter-clockwise, and rays along +x through its corners and edges.
  const CurveDistance square({Vec<2>(0, 0), Vec<2>(1, 0), Vec<2>(1, 1), Vec<2>(0, 1)}, {{0, 1}, {1, 2}, {2, 3}, {3, 0}});
  for (double y : {-0.5, 0.0, 0.5, 1.0, 1.5}) {
    for (double x : {-1.0, 0.5, 2.0}) {
      const bool on_edge = x == 0.5 && (y == 0.0 || y == 1.0);
      if (on_edge) continue;
      EXPECT_EQ(square.inside(Vec<2>(x, y)), x == 0.5 && y == 0.5) << x << ' ' << y;
    }
  }
  EXPECT_DOUBLE_EQ(square.signed_distance(Vec<2>(0.5, 0.4)), -0.4);
  EXPECT_DOUBLE_EQ(square.signed_distance(Vec<2>(-1.0, 0.5)), 1.0);
  // A 200-gon: distances against brute force.
  Points<2> v;
  std::vector<std::array<Index, 2>> e;
  for (int k = 0; k < 200; ++k) {
    v.emplace_back(std::cos(2 * kPi * k / 200), std::sin(2 * kPi * k / 200));
    e.push_back({k, (k + 1) % 200});
  }
  const CurveDistance circle(v, e);
  std::mt19937 random(4);
  std::uniform_real_distribution<double> coordinate(-2.0, 2.0);
  for (int k = 0; k < 200; ++k) {
    const Vec<2> q(coordinate(random), coordinate(random));
    double brute = std::numeric_limits<double>::infinity();
    for (const auto& s : e) brute = std::min(brute, segment_distance(q, v[s[0]], v[s[1]]));
    EXPECT_EQ(circle.distance(q), brute);
    // Inside the polygon's inscribed circle, outside its circumscribed one; in between, either.
    if (q.norm() < std::cos(kPi / 200) || q.norm() > 1.0) {
      EXPECT_EQ(circle.inside(q), q.norm() < 1.0) << q.transpose();
    }
  }
}

TEST(TriangleMeshDistance, RefusesMeshesWithoutTrianglesOrWithBadIndices) {
  EXPECT_THROW(TriangleMeshDistance({Vec<3>::Zero()}, {}), InvalidInput);
  EXPECT_THROW(TriangleMeshDistance({Vec<3>::Zero()}, {{0, 1, 2}}), InvalidInput);
}

}  // namespace
}  // namespace lsr
