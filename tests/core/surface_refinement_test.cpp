// SPDX-License-Identifier: BSD-3-Clause
/// @file surface_refinement_test.cpp
/// @brief Long edges of a closed surface bisected and projected onto the fit: an octahedron
/// inscribed in a sphere becomes a closed, consistently oriented surface as fine as asked, on the
/// sphere to the fit's accuracy; a fine enough surface is left alone.
#include "checks/exact_self_intersections.h"
#include "fit/surface_refinement.h"
#include "lsrecon/testdata/analytic_shapes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace lsr::detail {
namespace {

// The octahedron inscribed in the sphere, facets oriented outwards.
LevelSetMesh<3> octahedron(const Sphere& s) {
  LevelSetMesh<3> o;
  for (int k = 0; k < 3; ++k) {
    for (const double side : {1.0, -1.0}) {
      o.vertices.push_back(s.center + side * s.radius * Vec<3>::Unit(k));
      o.sources.push_back({0, 1, 0.5});
    }
  }
  // Vertices 0/1: +-x, 2/3: +-y, 4/5: +-z.
  for (const Index x : {0, 1}) {
    for (const Index y : {2, 3}) {
      for (const Index z : {4, 5}) {
        const bool outward = (int(x == 1) + int(y == 3) + int(z == 5)) % 2 == 0;  // an even number of minus signs
        o.facets.push_back(outward ? std::array<Index, 3>{x, y, z} : std::array<Index, 3>{x, z, y});
      }
    }
  }
  return o;
}

double enclosed_volume(const LevelSetMesh<3>& m, const Vec<3>& origin) {
  double v = 0.0;
  for (const auto& f : m.facets) {
    v += (m.vertices[std::size_t(f[0])] - origin).dot((m.vertices[std::size_t(f[1])] - origin).cross(m.vertices[std::size_t(f[2])] - origin)) / 6.0;
  }
  return v;
}

TEST(SurfaceRefinement, LongEdgesBecomeFineAndLieOnTheFit) {
  const Sphere s{Vec<3>::Constant(0.5), 0.3};
  const Points<3> samples = s.sample(20000);
  Points<3> normals;
  for (const auto& p : samples) normals.push_back((p - s.center).normalized());
  const double spacing = std::sqrt(4.0 * kPi * s.radius * s.radius / 20000);
  const NearestPointIndex<3> index(samples);  // the fit refers to it
  const QuadricImplicit<3> fit(index, normals, std::vector<double>(samples.size(), spacing));
  const double length = 0.02;
  LevelSetMesh<3> surface = octahedron(s);
  ASSERT_GT(enclosed_volume(surface, s.center), 0.0);
  Points<3> surface_normals(surface.vertices.size(), Vec<3>::Zero());
  Points<3> flat = surface.vertices;  // the octahedron, subdivided alongside
  refine_long_edges(surface, surface_normals, fit, [&](std::size_t) { return length; }, flat, 1);
  EXPECT_EQ(surface.sources.size(), surface.vertices.size());
  EXPECT_EQ(surface_normals.size(), surface.vertices.size());
  // The reference is the octahedron subdivided: its vertices on its faces, no intersection.
  ASSERT_EQ(flat.size(), surface.vertices.size());
  for (const auto& p : flat) EXPECT_NEAR((p - s.center).lpNorm<1>(), s.radius, 1e-12);
  EXPECT_EQ(testing::cgal_self_intersections(flat, surface.facets), 0u);
  // Closed and consistently oriented: every directed edge once, its reverse once.
  std::map<std::pair<Index, Index>, int> directed;
  for (const auto& f : surface.facets) {
    for (std::size_t i = 0; i < 3; ++i) {
      const Index a = f[i], b = f[(i + 1) % 3];
      ++directed[{a, b}];
      EXPECT_LE((surface.vertices[std::size_t(b)] - surface.vertices[std::size_t(a)]).norm(), 2.0 * length);
    }
  }
  for (const auto& [e, n] : directed) {
    EXPECT_EQ(n, 1);
    EXPECT_EQ(directed.count({e.second, e.first}), 1u);
  }
  // A sphere: V - E + F = 2.
  EXPECT_EQ(long(surface.vertices.size()) - long(directed.size() / 2) + long(surface.facets.size()), 2);
  for (const auto& x : surface.vertices) {
    // The fit of the sphere's samples: within the next term of its height fields, far below the
    // chords' sagitta (kappa L^2 / 8 = 4e-3 for the octahedron's edges).
    EXPECT_NEAR((x - s.center).norm(), s.radius, 1e-5);
  }
  // Inside the sphere by the facets' sagitta at most: kappa (2 length)^2 / 8 = 6.7e-4 deep.
  const double ball = 4.0 / 3.0 * kPi * std::pow(s.radius, 3);
  EXPECT_LT(enclosed_volume(surface, s.center), ball);
  EXPECT_GT(enclosed_volume(surface, s.center), 4.0 / 3.0 * kPi * std::pow(s.radius - 6.7e-4, 3));
  // As fine as asked already: unchanged.
  const std::size_t vertices = surface.vertices.size();
  refine_long_edges(surface, surface_normals, fit, [&](std::size_t) { return length; }, flat, 1);
  EXPECT_EQ(surface.vertices.size(), vertices);
}

}  // namespace
}  // namespace lsr::detail
