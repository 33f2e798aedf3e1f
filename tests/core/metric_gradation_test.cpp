// SPDX-License-Identifier: BSD-3-Clause
/// @file metric_gradation_test.cpp
/// @brief Metric intersection and the gradation limit on cases with known answers: isotropic
/// and crossed anisotropic metrics; a point of tiny size in a coarse field, whose neighbours'
/// sizes must then grow at most linearly with the distance to it.
#include "mesh/adaptive_refinement.h"
#include "mesh/metric_gradation.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <cmath>

namespace lsr {
namespace {

// m - a positive semi-definite, up to rounding: m asks for sizes at most a's in every direction.
template <int D>
void expect_contains(const Metric<D>& m, const Metric<D>& a) {
  const Eigen::SelfAdjointEigenSolver<Metric<D>> e(m - a);
  EXPECT_GE(e.eigenvalues().minCoeff(), -1e-12 * m.norm());
}

TEST(MetricGradation, IntersectionsOfKnownMetrics) {
  const Metric<2> a = Eigen::Vector2d(1, 100).asDiagonal(), b = Eigen::Vector2d(100, 1).asDiagonal();
  EXPECT_LE((metric_intersection<2>(a, b) - Metric<2>(Eigen::Vector2d(100, 100).asDiagonal())).norm(), 1e-12 * 100);
  EXPECT_LE((metric_intersection<2>(a, a) - a).norm(), 1e-12 * 100);
  const Metric<3> small = Metric<3>::Identity() / (0.01 * 0.01), large = Metric<3>::Identity() / (0.2 * 0.2);
  EXPECT_LE((metric_intersection<3>(large, small) - small).norm(), 1e-12 * small.norm());
  // A general pair: the intersection contains both, and is symmetric.
  Metric<3> c;
  c << 4, 1, 0.5, 1, 3, 0.2, 0.5, 0.2, 2;
  const Metric<3> d = Eigen::Vector3d(9, 0.5, 1).asDiagonal();
  const Metric<3> m = metric_intersection<3>(c, d);
  expect_contains<3>(m, c);
  expect_contains<3>(m, d);
  EXPECT_LE((m - m.transpose()).norm(), 1e-12 * m.norm());
}

// Isotropic metrics stay isotropic; sizes h = 1 / sqrt(eigenvalue).
double size_of(const Metric<2>& m) { return 1.0 / std::sqrt(m(0, 0)); }

TEST(MetricGradation, ATinySizeSpreadsLinearly) {
  const AdaptiveMesh<2> a = leaf_mesh(KuhnBisectionForest<2>(32));
  const SimplexMesh<2>& mesh = a.mesh;
  const double coarse = 0.25, fine = 1e-3, beta = 1.5;
  std::vector<Metric<2>> metrics(mesh.vertices.size(), Metric<2>::Identity() / (coarse * coarse));
  std::size_t centre = 0;
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    if ((mesh.vertices[v] - Vec<2>(0.5, 0.5)).norm() < 1e-12) centre = v;
  }
  metrics[centre] = Metric<2>::Identity() / (fine * fine);
  const std::vector<Metric<2>> before = metrics;
  const int sweeps = limit_gradation<2>(mesh, metrics, beta);
  EXPECT_LT(sweeps, 100);
  EXPECT_NEAR(size_of(metrics[centre]), fine, 1e-12);
  // Along every edge pq, q's size at most p's grown by the law: h_q <= h_p + ln(beta) |pq|
  // (the relative 1e-9 of the sweep's convergence test); and no size grew.
  for (const auto& s : mesh.simplices) {
    for (int i = 0; i < 3; ++i) {
      const auto p = std::size_t(s[std::size_t(i)]), q = std::size_t(s[std::size_t((i + 1) % 3)]);
      const double l = (mesh.vertices[q] - mesh.vertices[p]).norm();
      EXPECT_LE(size_of(metrics[q]), (size_of(metrics[p]) + std::log(beta) * l) * (1 + 1e-8));
      EXPECT_LE(size_of(metrics[p]), (size_of(metrics[q]) + std::log(beta) * l) * (1 + 1e-8));
    }
  }
  for (std::size_t v = 0; v < metrics.size(); ++v) expect_contains<2>(metrics[v], before[v]);
  // The mesh's spacing is 1/32: the centre's neighbours at most fine + ln(1.5) / 32.
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    const double r = (mesh.vertices[v] - mesh.vertices[centre]).norm();
    if (r > 0.0 && r < 0.04) {
      EXPECT_LE(size_of(metrics[v]), fine + std::log(beta) * r * (1 + 1e-8));
    }
  }
}

}  // namespace
}  // namespace lsr
