// SPDX-License-Identifier: BSD-3-Clause
/// @file point_location_test.cpp
#include "lsrecon/testdata/analytic_shapes.h"
#include "mesh/metric_adaptation.h"
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

// Random points of the unit box, a few on its walls.
template <int D>
Points<D> box_points() {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Points<D> p(5000);
  for (std::size_t q = 0; q < p.size(); ++q) {
    for (int d = 0; d < D; ++d) p[q][d] = unit(rng);
    if (q < std::size_t(D)) p[q][int(q)] = 1.0;
  }
  return p;
}

template <int D>
void check_linear_reproduction(const SimplexMesh<D>& mesh, const Points<D>& points, const std::vector<Location<D>>& located) {
  const Vec<D> a = Vec<D>::LinSpaced(0.7, -1.3);
  const double b = 0.25;
  std::vector<double> u(mesh.vertices.size());
  for (std::size_t i = 0; i < u.size(); ++i) u[i] = a.dot(mesh.vertices[i]) + b;
  ASSERT_EQ(located.size(), points.size());
  for (std::size_t q = 0; q < points.size(); ++q) {
    const Vec<D>& p = points[q];
    const Location<D>& at = located[q];
    ASSERT_TRUE(at.found());
    // The weights are barycentric coordinates of p in that simplex.
    Vec<D> rebuilt = Vec<D>::Zero();
    double sum = 0.0;
    for (int k = 0; k <= D; ++k) {
      EXPECT_GE(at.weights[k], -1e-12);
      rebuilt += at.weights[k] * mesh.vertices[at.vertices[k]];
      sum += at.weights[k];
    }
    EXPECT_NEAR(sum, 1.0, 1e-12);
    EXPECT_LE((rebuilt - p).norm(), 1e-12);
    EXPECT_NEAR(interpolate(at, u), a.dot(p) + b, 1e-12);
    const auto& simplex = mesh.simplices[at.simplex];
    for (Index v : at.vertices) EXPECT_EQ(std::count(simplex.begin(), simplex.end(), v), 1);
  }
}

template <int D>
void check_both_locations(const AdaptiveMesh<D>& m) {
  const Points<D> p = box_points<D>();
  std::vector<Location<D>> by_forest;
  for (const auto& x : p) by_forest.push_back(locate(m, x));
  check_linear_reproduction(m.mesh, p, by_forest);
  check_linear_reproduction(m.mesh, p, locate_all(m.mesh, p));  // through the grid of buckets
}

TEST(PointLocation, InterpolationReproducesLinearFunctions2D) {
  check_both_locations(mesh_around<2>(Circle{Vec<2>(0.5, 0.5), 0.3}.sample(2000), 1.0 / 256));
}

TEST(PointLocation, InterpolationReproducesLinearFunctions3D) {
  check_both_locations(mesh_around<3>(Sphere{Vec<3>(0.5, 0.5, 0.5), 0.3}.sample(5000), 1.0 / 64));
}

TEST(PointLocation, TheGridLocatesInStretchedTriangles) {
  // A mesh of triangles 20:1 (the metric's unit mesh: metric_adaptation.h).
  const MetricField<2> metric = [](const Vec<2>&) -> Metric<2> { return Eigen::Vector2d(1.0 / (0.005 * 0.005), 1.0 / (0.1 * 0.1)).asDiagonal(); };
  const SimplexMesh<2> mesh = adapt_to_metric(leaf_mesh(KuhnBisectionForest<2>(4)).mesh, metric);
  const Points<2> p = box_points<2>();
  check_linear_reproduction(mesh, p, locate_all(mesh, p));
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
