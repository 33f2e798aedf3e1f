// SPDX-License-Identifier: BSD-3-Clause
/// @file point_location_test.cpp
#include "lsrecon/testdata/analytic_shapes.h"
#include "mesh/point_location.h"

#include <gtest/gtest.h>

#include <random>

namespace lsr {
namespace {

template <int D>
AdaptiveMesh<D> mesh_around(const Points<D>& data, double h_min) {
  AdaptiveMeshOptions o;
  o.h_min = h_min;
  return build_adaptive_mesh(NearestPointIndex<D>(data), o);
}

template <int D>
void check_linear_reproduction(const AdaptiveMesh<D>& m) {
  const Vec<D> a = Vec<D>::LinSpaced(0.7, -1.3);
  const double b = 0.25;
  std::vector<double> u(m.mesh.vertices.size());
  for (std::size_t i = 0; i < u.size(); ++i) u[i] = a.dot(m.mesh.vertices[i]) + b;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int q = 0; q < 5000; ++q) {
    Vec<D> p;
    for (int d = 0; d < D; ++d) p[d] = unit(rng);
    if (q < D) p[q] = 1.0;  // a few points on the box walls
    const Location<D> at = locate(m, p);
    ASSERT_TRUE(at.found());
    // The weights are barycentric coordinates of p in that simplex.
    Vec<D> rebuilt = Vec<D>::Zero();
    double sum = 0.0;
    for (int k = 0; k <= D; ++k) {
      EXPECT_GE(at.weights[k], -1e-12);
      rebuilt += at.weights[k] * m.mesh.vertices[at.vertices[k]];
      sum += at.weights[k];
    }
    EXPECT_NEAR(sum, 1.0, 1e-12);
    EXPECT_LE((rebuilt - p).norm(), 1e-12);
    EXPECT_NEAR(interpolate(at, u), a.dot(p) + b, 1e-12);
    const auto& simplex = m.mesh.simplices[at.simplex];
    for (Index v : at.vertices) EXPECT_EQ(std::count(simplex.begin(), simplex.end(), v), 1);
  }
}

TEST(PointLocation, InterpolationReproducesLinearFunctions2D) {
  check_linear_reproduction(mesh_around<2>(Circle{Vec<2>(0.5, 0.5), 0.3}.sample(2000), 1.0 / 256));
}

TEST(PointLocation, InterpolationReproducesLinearFunctions3D) {
  check_linear_reproduction(
      mesh_around<3>(Sphere{Vec<3>(0.5, 0.5, 0.5), 0.3}.sample(5000), 1.0 / 64));
}

TEST(PointLocation, PointsOutsideTheBoxAreNotFound) {
  const auto m = mesh_around<2>(Circle{Vec<2>(0.5, 0.5), 0.3}.sample(200), 1.0 / 32);
  EXPECT_FALSE(locate(m, Vec<2>(-0.1, 0.5)).found());
  EXPECT_FALSE(locate(m, Vec<2>(0.5, 1.5)).found());
  EXPECT_FALSE(locate(m, Vec<2>(std::nan(""), 0.5)).found());
  EXPECT_TRUE(locate(m, Vec<2>(1.0, 0.0)).found());
}

}  // namespace
}  // namespace lsr
