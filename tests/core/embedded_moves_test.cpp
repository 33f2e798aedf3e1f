// SPDX-License-Identifier: BSD-3-Clause
/// @file embedded_moves_test.cpp
/// @brief keep_embedded: moves that tangle a surface or curve are shortened until CGAL finds no
/// self-intersection; moves that keep it embedded are left whole.
#include "checks/exact_self_intersections.h"
#include "core/mesh_checks.h"
#include "lsrecon/testdata/analytic_shapes.h"
#include "surface/embedded_moves.h"

#include <gtest/gtest.h>

#include <random>

namespace lsr {
namespace {

using detail::keep_embedded;
using testing::cgal_self_intersections;

template <int D, class Shape>
LevelSetMesh<D> extracted(const Shape& shape, const Points<D>& samples, double h) {
  const testing::SampledField<D> f = testing::sampled_field<D>(samples, h, [&](const Vec<D>& p) { return shape.signed_distance(p); });
  return extract_zero_level_set(f.adaptive.mesh, f.values);
}

// Each vertex's final position lies on the segment from where it was extracted to its target.
template <int D>
void expect_on_segments(const Points<D>& from, const Points<D>& to, const Points<D>& x) {
  for (std::size_t v = 0; v < x.size(); ++v) {
    const Vec<D> d = to[v] - from[v];
    const double t = d.squaredNorm() > 0.0 ? (x[v] - from[v]).dot(d) / d.squaredNorm() : 0.0;
    EXPECT_GE(t, 0.0);
    EXPECT_LE(t, 1.0);
    EXPECT_LE((from[v] + t * d - x[v]).norm(), 1e-12);
  }
}

TEST(EmbeddedMoves, TangledSurfaceComesOutEmbedded) {
  const Sphere sphere{Vec<3>(0.5, 0.5, 0.5), 0.3};
  LevelSetMesh<3> s = extracted<3>(sphere, sphere.sample(400), 1.0 / 32.0);
  const Points<3> from = s.vertices;
  std::mt19937_64 random(5);
  std::normal_distribution<double> move(0.0, 0.01);  // a third of a mesh size
  for (auto& x : s.vertices) x += Vec<3>(move(random), move(random), move(random));
  const Points<3> to = s.vertices;
  ASSERT_GT(cgal_self_intersections(s.vertices, s.facets), 100u);
  Points<3> normals(s.vertices.size(), Vec<3>::UnitX());
  const std::vector<char> shortened = keep_embedded(s, from, false, normals, 2);
  EXPECT_EQ(cgal_self_intersections(s.vertices, s.facets), 0u);
  expect_on_segments<3>(from, to, s.vertices);
  // Only what had to: some moves kept whole.
  const auto count = std::count(shortened.begin(), shortened.end(), char(1));
  EXPECT_GT(count, 0);
  EXPECT_LT(std::size_t(count), s.vertices.size());
  for (std::size_t v = 0; v < shortened.size(); ++v) {
    if (!shortened[v]) {
      EXPECT_EQ(s.vertices[v], to[v]);
    }
  }
}

TEST(EmbeddedMoves, MovesThatKeepTheSurfaceEmbeddedAreLeftWhole) {
  // Every vertex half a mesh size outwards along the radius: a larger sphere's polyhedron.
  const Sphere sphere{Vec<3>(0.5, 0.5, 0.5), 0.3};
  LevelSetMesh<3> s = extracted<3>(sphere, sphere.sample(400), 1.0 / 32.0);
  const Points<3> from = s.vertices;
  for (auto& x : s.vertices) x = sphere.center + (x - sphere.center) * (1.0 + 0.5 / 32.0 / 0.3);
  const Points<3> to = s.vertices;
  Points<3> no_normals;
  const std::vector<char> shortened = keep_embedded(s, from, false, no_normals, 2);
  EXPECT_EQ(std::count(shortened.begin(), shortened.end(), char(1)), 0);
  EXPECT_EQ(s.vertices, to);
}

// On the float grid: every position a float, so what a float reader sees is what was checked.
TEST(EmbeddedMoves, OnTheFloatGridEveryPositionIsAFloat) {
  const Sphere sphere{Vec<3>(0.5, 0.5, 0.5), 0.3};
  LevelSetMesh<3> s = extracted<3>(sphere, sphere.sample(400), 1.0 / 32.0);
  const Vec<3> offset(100.0, -20.0, 3.0);  // coordinates where float's unit is 2^-17
  for (auto& x : s.vertices) x += offset;
  const Points<3> from = s.vertices;
  std::mt19937_64 random(5);
  std::normal_distribution<double> move(0.0, 0.01);
  for (auto& x : s.vertices) x += Vec<3>(move(random), move(random), move(random));
  ASSERT_TRUE(detail::float_grid_is_finer(s.vertices, 1e-4));
  ASSERT_FALSE(detail::float_grid_is_finer(s.vertices, 1e-7));
  Points<3> no_normals;
  keep_embedded(s, from, true, no_normals, 2);
  for (const auto& x : s.vertices) {
    for (int k = 0; k < 3; ++k) {
      const volatile float f = static_cast<float>(x[k]);  // not the helper under test
      EXPECT_EQ(x[k], double(f));
    }
  }
  EXPECT_EQ(cgal_self_intersections(s.vertices, s.facets), 0u);
}

TEST(EmbeddedMoves, TangledCurveComesOutSimple) {
  const Circle circle{Vec<2>(0.5, 0.5), 0.3};
  LevelSetMesh<2> c = extracted<2>(circle, circle.sample(200), 1.0 / 128.0);
  const Points<2> from = c.vertices;
  std::mt19937_64 random(9);
  std::normal_distribution<double> move(0.0, 0.01);
  for (auto& x : c.vertices) x += Vec<2>(move(random), move(random));
  const Points<2> to = c.vertices;
  ASSERT_GT(cgal_self_intersections(c.vertices, c.facets), 10u);
  Points<2> normals(c.vertices.size(), Vec<2>::UnitX());
  keep_embedded(c, from, false, normals, 2);
  EXPECT_EQ(cgal_self_intersections(c.vertices, c.facets), 0u);
  expect_on_segments<2>(from, to, c.vertices);
}

}  // namespace
}  // namespace lsr
