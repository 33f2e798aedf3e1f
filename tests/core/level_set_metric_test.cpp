// SPDX-License-Identifier: BSD-3-Clause
/// @file level_set_metric_test.cpp
/// @brief The level-set metric on analytic cases: exact sizes and directions from the exact
/// derivatives of a circle's, a sphere's and a plane's distance, then from the derivatives the
/// scheme recovers on uniform Kuhn meshes, converging to them.
#include "mesh/level_set_metric.h"
#include "lsrecon/testdata/analytic_shapes.h"
#include "mesh/adaptive_refinement.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace lsr {
namespace {

MetricSizes sizes() { return {1.0 / 512, 1.0 / 8, 1e-4, 0.5}; }  // h_min, h_max, error, growth

// What the metric should prescribe at distance d from a circle / sphere of radius R: across,
// h_min + growth |d|; along, where the level set through the point has curvature 1 / (R + d),
// sqrt(8 error (R + d)) within [across, h_max].
struct Expected {
  double across, along;
};
Expected expected(double radius, double d, const MetricSizes& s) {
  const double across = std::min(s.h_max, s.h_min + s.growth * std::abs(d));
  return {across, std::clamp(std::sqrt(8.0 * s.error * (radius + d)), across, s.h_max)};
}

template <int D>
void expect_sizes(const Metric<D>& m, const Vec<D>& normal, const Expected& e, double relative) {
  Vec<D> h;
  Metric<D> directions;
  metric_sizes<D>(m, h, directions);
  EXPECT_NEAR(h[0], e.across, relative * e.across);
  for (int k = 1; k < D; ++k) EXPECT_NEAR(h[k], e.along, relative * e.along);
  // The finest direction is the normal, where the metric is anisotropic (else any direction is).
  if (e.along > (1.0 + 1e-9) * e.across) {
    EXPECT_NEAR(std::abs(directions.col(0).dot(normal)), 1.0, relative);
  }
}

TEST(LevelSetMetric, ExactDerivativesOfCirclesSpheresAndPlanes) {
  const MetricSizes s = sizes();
  const double radius = 0.3;
  for (double d : {-0.05, -0.001, 0.0, 0.002, 0.04, 0.5}) {
    // A circle: g = n, H = (I - n n^T) / (R + d).
    const Vec<2> n2 = Vec<2>(3, -4).normalized();
    const Metric<2> h2 = (Metric<2>::Identity() - n2 * n2.transpose()) / (radius + d);
    expect_sizes<2>(level_set_metric<2>(d, n2, h2, s), n2, expected(radius, d, s), 1e-12);
    // A sphere; and its gradient scaled (u = 3 distance): the same sizes.
    const Vec<3> n3 = Vec<3>(1, 2, -2).normalized();
    const Metric<3> h3 = (Metric<3>::Identity() - n3 * n3.transpose()) / (radius + d);
    expect_sizes<3>(level_set_metric<3>(d, n3, h3, s), n3, expected(radius, d, s), 1e-12);
    expect_sizes<3>(level_set_metric<3>(3 * d, 3 * n3, 3 * h3, s), n3, expected(radius, d, s), 1e-12);
    // A plane: no curvature, h_max along it.
    expect_sizes<3>(level_set_metric<3>(d, n3, Metric<3>::Zero(), s), n3,
                    {std::min(s.h_max, s.h_min + s.growth * std::abs(d)), s.h_max}, 1e-12);
  }
  // No gradient: no level set to adapt to.
  Vec<3> h;
  Metric<3> directions;
  metric_sizes<3>(level_set_metric<3>(0.1, Vec<3>::Zero(), Metric<3>::Identity(), s), h, directions);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(h[k], s.h_max, 1e-15);
}

// With a reach R: the sizes along shrink linearly to the size across, which they equal from R
// on.
TEST(LevelSetMetric, IsotropicPastTheReach) {
  MetricSizes s = sizes();
  s.anisotropic_reach = 0.01;
  const double radius = 0.3;
  const Vec<3> n = Vec<3>(1, 2, -2).normalized();
  for (double d : {0.0, 0.002, -0.005, 0.0099, 0.01, 0.04, -0.1}) {
    const Metric<3> h = (Metric<3>::Identity() - n * n.transpose()) / (radius + d);
    Expected e = expected(radius, d, s);
    e.along = e.across + std::max(0.0, 1.0 - std::abs(d) / s.anisotropic_reach) * (e.along - e.across);
    expect_sizes<3>(level_set_metric<3>(d, n, h, s), n, e, 1e-12);
  }
}

// RMS relative error of the sizes along the level sets, over the vertices within h of the
// curve / surface, on the uniform Kuhn mesh with n cells per axis.
template <int D, class Shape>
double along_rms_error(const Shape& shape, int n) {
  const AdaptiveMesh<D> m = leaf_mesh(KuhnBisectionForest<D>(n));
  const P1Operators<D> ops = assemble_p1_operators(m.mesh, compute_simplex_geometry(m.mesh), true);
  Eigen::VectorXd u(m.mesh.vertices.size());
  for (std::size_t i = 0; i < m.mesh.vertices.size(); ++i) {
    u[Eigen::Index(i)] = shape.signed_distance(m.mesh.vertices[i]);
  }
  const MetricSizes s = sizes();
  const std::vector<Metric<D>> metric = level_set_metrics<D>(ops, u, s);
  double sum2 = 0.0;
  int count = 0;
  for (Eigen::Index i = 0; i < u.size(); ++i) {
    if (std::abs(u[i]) > 1.0 / n) continue;
    Vec<D> h;
    Metric<D> directions;
    metric_sizes<D>(metric[std::size_t(i)], h, directions);
    const Expected e = expected(shape.radius, u[i], s);
    for (int k = 1; k < D; ++k) sum2 += std::pow(h[k] / e.along - 1.0, 2);
    count += D - 1;
  }
  return std::sqrt(sum2 / count);
}

// The along sizes go like kappa^(-1/2): their relative error is half the curvature's, which the
// recovered Hessian G (G u) gives at second order on translation-invariant meshes, as the
// scheme's curvature (p1_operators_test.cpp).
TEST(LevelSetMetric, RecoveredOnACircleConvergesAtSecondOrder) {
  const Circle c{Vec<2>(0.5, 0.5), 0.3};
  const double e1 = along_rms_error<2>(c, 128), e2 = along_rms_error<2>(c, 256);
  std::printf("circle: along-size error %.2e (n = 128), %.2e (256)\n", e1, e2);
  EXPECT_GE(std::log2(e1 / e2), 1.8);
}

TEST(LevelSetMetric, RecoveredOnASphereConvergesAtSecondOrder) {
  const Sphere s{Vec<3>(0.5, 0.5, 0.5), 0.3};
  const double e1 = along_rms_error<3>(s, 32), e2 = along_rms_error<3>(s, 64);
  std::printf("sphere: along-size error %.2e (n = 32), %.2e (64)\n", e1, e2);
  EXPECT_GE(std::log2(e1 / e2), 1.8);
}

}  // namespace
}  // namespace lsr
