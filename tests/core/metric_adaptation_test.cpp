// SPDX-License-Identifier: BSD-3-Clause
/// @file metric_adaptation_test.cpp
/// @brief Triangles adapted to a metric, on metrics with known answers: a constant anisotropic
/// metric (a unit mesh has a known vertex count) and a circle's level-set metric (fewer
/// vertices than the isotropic mesh of the same sizes across, at the interpolation error the
/// metric asks for).
#include "evolution/renormalization.h"
#include "mesh/adaptive_refinement.h"
#include "mesh/metric_adaptation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace lsr {
namespace {

struct MeshFigures {
  double min_quality = 1.0;
  double mean_length = 0.0;
  double share_in_bounds = 0.0;  ///< edges with metric length in [1/sqrt(2), sqrt(2)]
  double euclidean_area = 0.0;
};

MeshFigures figures(const SimplexMesh<2>& mesh, const MetricField<2>& metric) {
  MeshFigures f;
  std::vector<Metric<2>> m;
  for (const auto& p : mesh.vertices) m.push_back(metric(p));
  std::vector<std::pair<Index, Index>> edges;
  for (const auto& s : mesh.simplices) {
    const std::array<Vec<2>, 3> x{mesh.vertices[std::size_t(s[0])], mesh.vertices[std::size_t(s[1])],
                                  mesh.vertices[std::size_t(s[2])]};
    f.min_quality = std::min(f.min_quality, metric_quality(x, (m[std::size_t(s[0])] + m[std::size_t(s[1])] + m[std::size_t(s[2])]) / 3.0));
    f.euclidean_area += 0.5 * ((x[1] - x[0]).x() * (x[2] - x[0]).y() - (x[1] - x[0]).y() * (x[2] - x[0]).x());
    for (int i = 0; i < 3; ++i) {
      const Index a = s[std::size_t(i)], b = s[std::size_t((i + 1) % 3)];
      edges.emplace_back(std::min(a, b), std::max(a, b));
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  std::size_t in = 0;
  for (const auto& [a, b] : edges) {
    const double l = metric_length<2>(mesh.vertices[std::size_t(b)] - mesh.vertices[std::size_t(a)], m[std::size_t(a)], m[std::size_t(b)]);
    f.mean_length += l / double(edges.size());
    in += l >= kShortEdge && l <= kLongEdge ? 1 : 0;
  }
  f.share_in_bounds = double(in) / double(edges.size());
  return f;
}

// Vertices of a unit mesh for a metric of total measure `complexity` = integral of
// sqrt(det M): its triangles are equilateral of side 1, measure sqrt(3) / 4 each, and a
// triangulation has about twice as many triangles as vertices.
double unit_mesh_vertices(double complexity) { return complexity / (std::sqrt(3.0) / 4.0) / 2.0; }

// The integral of sqrt(det M) over the unit box by the midpoint rule on a 1000 x 1000 grid.
double complexity(const MetricField<2>& metric) {
  const int n = 1000;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) sum += std::sqrt(metric(Vec<2>((i + 0.5) / n, (j + 0.5) / n)).determinant());
  }
  return sum / (double(n) * n);
}

TEST(MetricAdaptation, LengthsAndShapesOfKnownCases) {
  const Metric<2> m = Eigen::Vector2d(1.0 / (0.1 * 0.1), 1.0 / (0.01 * 0.01)).asDiagonal();
  EXPECT_NEAR(metric_length<2>(Vec<2>(0.3, 0.04), m, m), std::sqrt(9.0 + 16.0), 1e-12);
  // Sizes 1 and 2 along a unit edge, varying geometrically: integral of 2^-t over [0, 1].
  const Metric<2> one = Metric<2>::Identity(), two = Metric<2>::Identity() / 4.0;
  EXPECT_NEAR(metric_length<2>(Vec<2>(1, 0), one, two), 0.5 / std::log(2.0), 1e-12);
  EXPECT_NEAR(metric_length<2>(Vec<2>(1, 0), two, one), 0.5 / std::log(2.0), 1e-12);
  // Equilateral in the metric: 1; the same triangle flipped: -1; flat: 0.
  const std::array<Vec<2>, 3> t{Vec<2>(0, 0), Vec<2>(0.1, 0), Vec<2>(0.05, 0.01 * std::sqrt(3.0) / 2.0)};
  EXPECT_NEAR(metric_quality(t, m), 1.0, 1e-12);
  EXPECT_NEAR(metric_quality({t[1], t[0], t[2]}, m), -1.0, 1e-12);
  EXPECT_NEAR(metric_quality({t[0], t[1], Vec<2>(0.2, 0)}, m), 0.0, 1e-12);
}

TEST(MetricAdaptation, AConstantAnisotropicMetricGivesAUnitMesh) {
  const double hx = 0.02, hy = 0.1;
  const MetricField<2> metric = [&](const Vec<2>&) -> Metric<2> {
    return Eigen::Vector2d(1.0 / (hx * hx), 1.0 / (hy * hy)).asDiagonal();
  };
  const SimplexMesh<2> start = leaf_mesh(KuhnBisectionForest<2>(4)).mesh;
  MetricAdaptationStats stats;
  const SimplexMesh<2> mesh = adapt_to_metric(start, metric, 12, &stats);
  const MeshFigures f = figures(mesh, metric);
  EXPECT_GT(f.min_quality, 0.0);
  EXPECT_NEAR(f.euclidean_area, 1.0, 1e-12);  // the box, still covered exactly
  // Edges within [1/sqrt(2), sqrt(2)] hold a vertex count within a factor 2 of a unit mesh's;
  // an isotropic mesh at hx would need 1 / (hy / hx) of it, 5x more.
  const double expected = unit_mesh_vertices(1.0 / (hx * hy));
  EXPECT_GT(double(mesh.vertices.size()), expected / 2.0);
  EXPECT_LT(double(mesh.vertices.size()), expected * 2.0);
  EXPECT_GT(f.mean_length, kShortEdge);
  EXPECT_LT(f.mean_length, kLongEdge);
  std::printf("constant metric: %zu vertices (unit mesh %.0f), %d cycles, min quality %.3f, mean length %.3f, %.3f in bounds\n",
              mesh.vertices.size(), expected, stats.cycles, f.min_quality, f.mean_length, f.share_in_bounds);
}

// The circle of radius 0.3 about the box's centre: its signed distance, and the level-set
// metric of its exact derivatives (level_set_metric_test.cpp checks those sizes).
constexpr double kRadius = 0.3;
double circle_distance(const Vec<2>& x) { return (x - Vec<2>(0.5, 0.5)).norm() - kRadius; }
MetricSizes circle_sizes() { return {1.0 / 1024, 1.0 / 8, 1e-4, 0.5}; }  // h_min, h_max, error, growth
Metric<2> circle_metric(const Vec<2>& x) {
  const Vec<2> r = x - Vec<2>(0.5, 0.5);
  const double rho = std::max(r.norm(), 1e-9);
  const Vec<2> n = r / rho;
  return level_set_metric<2>(rho - kRadius, n, (Metric<2>::Identity() - n * n.transpose()) / rho, circle_sizes());
}

// The largest distance to the circle of the zero set of the P1 interpolant of its distance.
double zero_set_error(const SimplexMesh<2>& mesh) {
  double worst = 0.0;
  for (const auto& s : mesh.simplices) {
    for (int i = 0; i < 3; ++i) {
      const Vec<2>& a = mesh.vertices[std::size_t(s[std::size_t(i)])];
      const Vec<2>& b = mesh.vertices[std::size_t(s[std::size_t((i + 1) % 3)])];
      const double ua = circle_distance(a), ub = circle_distance(b);
      if ((ua < 0.0) == (ub < 0.0)) continue;
      const Vec<2> p = a + ua / (ua - ub) * (b - a);
      worst = std::max(worst, std::abs(circle_distance(p)));
    }
  }
  return worst;
}

TEST(MetricAdaptation, ACircleNeedsFewerVerticesAlongItThanAcross) {
  const MetricSizes sizes = circle_sizes();
  const MetricField<2> anisotropic = circle_metric;
  // The same sizes across, isotropic: what a graded isotropic mesh resolving the same band is.
  const MetricField<2> isotropic = [&](const Vec<2>& x) -> Metric<2> {
    const double h = std::min(sizes.h_max, sizes.h_min + sizes.growth * std::abs(circle_distance(x)));
    return Metric<2>::Identity() / (h * h);
  };
  const SimplexMesh<2> start = leaf_mesh(KuhnBisectionForest<2>(8)).mesh;
  MetricAdaptationStats sa, si;
  const SimplexMesh<2> a = adapt_to_metric(start, anisotropic, 12, &sa);
  const SimplexMesh<2> i = adapt_to_metric(start, isotropic, 12, &si);
  const MeshFigures fa = figures(a, anisotropic), fi = figures(i, isotropic);
  EXPECT_GT(fa.min_quality, 0.0);
  EXPECT_GT(fi.min_quality, 0.0);
  EXPECT_NEAR(fa.euclidean_area, 1.0, 1e-12);
  // Each within a factor 2 of its unit mesh. Along the circle the sizes are sqrt(8 error R) /
  // h_min = 16x those across; the unit meshes' counts differ 4.3x over the box, the issue's
  // target (paper, figure 4) is 3x.
  const double na = unit_mesh_vertices(complexity(anisotropic)), ni = unit_mesh_vertices(complexity(isotropic));
  EXPECT_GT(double(a.vertices.size()), na / 2.0);
  EXPECT_LT(double(a.vertices.size()), na * 2.0);
  EXPECT_GT(double(i.vertices.size()), ni / 2.0);
  EXPECT_LT(double(i.vertices.size()), ni * 2.0);
  EXPECT_GT(double(i.vertices.size()), 3.0 * double(a.vertices.size()));
  // The chord error of an edge of metric length l along the circle is l^2 error: at most
  // 2 error for edges up to sqrt(2) (u is linear across, to first order).
  const double error = zero_set_error(a);
  EXPECT_LT(error, 2.0 * sizes.error);
  std::printf("circle: anisotropic %zu vertices (unit mesh %.0f, %d cycles, min quality %.3f, mean length %.3f, %.3f in bounds, zero set within %.2e), isotropic %zu (%.0f, %d cycles, %.2e)\n",
              a.vertices.size(), na, sa.cycles, fa.min_quality, fa.mean_length, fa.share_in_bounds, error, i.vertices.size(), ni, si.cycles,
              zero_set_error(i));
}

// The renormalisation (paper section 6.3) on the adapted mesh: the distances to the P1 zero set
// of a field with the circle's zero set are the circle's, within the zero set's chord error
// (2 error, above) wherever they are within the band. On stretched triangles a vertex next to
// the front can have no neighbour nearer to it than the band: closest-facet propagation must
// still reach it (without that, vertices 1e-4 from the front were left at the band's 1.5e-3).
TEST(MetricAdaptation, RenormalisationRestoresDistancesOnTheAdaptedMesh) {
  const MetricSizes sizes = circle_sizes();
  const SimplexMesh<2> mesh = adapt_to_metric(leaf_mesh(KuhnBisectionForest<2>(8)).mesh, MetricField<2>(circle_metric));
  Eigen::VectorXd u(Eigen::Index(mesh.vertices.size())), exact(u.size());
  for (Eigen::Index i = 0; i < u.size(); ++i) {
    exact[i] = circle_distance(mesh.vertices[std::size_t(i)]);
    u[i] = 3.0 * exact[i] * (1.0 + exact[i]);  // the same zero set, |grad u| far from 1
  }
  const double band = 6.0 * sizes.h_min, tolerance = 2.0 * sizes.error;
  renormalize<2>(mesh, u, band);
  std::size_t checked = 0;
  for (Eigen::Index i = 0; i < u.size(); ++i) {
    EXPECT_EQ(u[i] < 0.0, exact[i] < 0.0) << i;
    if (std::abs(exact[i]) < band - tolerance) {
      EXPECT_NEAR(u[i], exact[i], tolerance) << i;
      ++checked;
    }
  }
  EXPECT_GT(checked, 100u);
}

}  // namespace
}  // namespace lsr
