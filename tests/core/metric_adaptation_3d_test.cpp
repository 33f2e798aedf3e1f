// SPDX-License-Identifier: BSD-3-Clause
/// @file metric_adaptation_3d_test.cpp
/// @brief Tetrahedra adapted to a metric, on metrics with known answers: a constant anisotropic
/// metric and a sphere's level-set metric. The adapted mesh must still tile the box (positive
/// tetrahedra, each inner face shared by two, the others on the box, total volume 1).
#include "mesh/adaptive_refinement.h"
#include "mesh/metric_adaptation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

namespace lsr {
namespace {

struct TetFigures {
  double min_quality = 1.0;
  double mean_length = 0.0;
  double share_in_bounds = 0.0;  ///< edges with metric length in [1/sqrt(2), sqrt(2)]
  double volume = 0.0;
  std::size_t faces_shared_by_more_than_two = 0, open_faces_off_the_box = 0;
};

TetFigures figures(const SimplexMesh<3>& mesh, const MetricField<3>& metric) {
  TetFigures f;
  std::vector<Metric<3>> m;
  for (const auto& p : mesh.vertices) m.push_back(metric(p));
  std::vector<std::pair<Index, Index>> edges;
  std::vector<std::array<Index, 3>> faces;
  for (const auto& s : mesh.simplices) {
    std::array<Vec<3>, 4> x;
    Metric<3> mean = Metric<3>::Zero();
    for (std::size_t i = 0; i < 4; ++i) {
      x[i] = mesh.vertices[std::size_t(s[i])];
      mean += m[std::size_t(s[i])] / 4.0;
    }
    f.min_quality = std::min(f.min_quality, metric_quality(x, mean));
    f.volume += (x[1] - x[0]).dot((x[2] - x[0]).cross(x[3] - x[0])) / 6.0;
    for (std::size_t i = 0; i < 4; ++i) {
      for (std::size_t j = i + 1; j < 4; ++j) edges.emplace_back(std::min(s[i], s[j]), std::max(s[i], s[j]));
      std::array<Index, 3> face{s[(i + 1) % 4], s[(i + 2) % 4], s[(i + 3) % 4]};
      std::sort(face.begin(), face.end());
      faces.push_back(face);
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  std::size_t in = 0;
  for (const auto& [a, b] : edges) {
    const double l = metric_length<3>(mesh.vertices[std::size_t(b)] - mesh.vertices[std::size_t(a)], m[std::size_t(a)], m[std::size_t(b)]);
    f.mean_length += l / double(edges.size());
    in += l >= kShortEdge && l <= kLongEdge ? 1 : 0;
  }
  f.share_in_bounds = double(in) / double(edges.size());
  std::sort(faces.begin(), faces.end());
  for (std::size_t i = 0; i < faces.size();) {
    std::size_t j = i;
    while (j < faces.size() && faces[j] == faces[i]) ++j;
    if (j - i > 2) ++f.faces_shared_by_more_than_two;
    if (j - i == 1) {
      // An open face lies in a face of the unit box: its three vertices share a coordinate 0 or 1.
      bool on_box = false;
      for (int k = 0; k < 3; ++k) {
        for (const double side : {0.0, 1.0}) {
          bool all = true;
          for (Index v : faces[i]) all = all && mesh.vertices[std::size_t(v)][k] == side;
          on_box = on_box || all;
        }
      }
      if (!on_box) ++f.open_faces_off_the_box;
    }
    i = j;
  }
  return f;
}

void expect_tiles_the_box(const TetFigures& f) {
  EXPECT_GT(f.min_quality, 0.0);
  EXPECT_NEAR(f.volume, 1.0, 1e-12);
  EXPECT_EQ(f.faces_shared_by_more_than_two, 0u);
  EXPECT_EQ(f.open_faces_off_the_box, 0u);
}

TEST(MetricAdaptation3d, ShapesOfKnownTetrahedra) {
  const Metric<3> m = Eigen::Vector3d(1.0 / (0.1 * 0.1), 1.0 / (0.01 * 0.01), 1.0).asDiagonal();
  // The regular tetrahedron of side 1, stretched by the metric's sizes: 1; mirrored: -1; flat: 0.
  std::array<Vec<3>, 4> t{Vec<3>(0, 0, 0), Vec<3>(1, 0, 0), Vec<3>(0.5, std::sqrt(3.0) / 2.0, 0),
                          Vec<3>(0.5, std::sqrt(3.0) / 6.0, std::sqrt(2.0 / 3.0))};
  for (auto& x : t) x = Vec<3>(0.1 * x.x(), 0.01 * x.y(), x.z());
  EXPECT_NEAR(metric_quality(t, m), 1.0, 1e-12);
  EXPECT_NEAR(metric_quality({t[1], t[0], t[2], t[3]}, m), -1.0, 1e-12);
  EXPECT_NEAR(metric_quality({t[0], t[1], t[2], Vec<3>(0.05, 0.002, 0)}, m), 0.0, 1e-12);
}

// Tetrahedra of a unit mesh for a metric of total measure `complexity` (the integral of
// sqrt(det M)): regular of side 1, each of measure 1 / (6 sqrt(2)).
double unit_mesh_tetrahedra(double complexity) { return complexity * 6.0 * std::sqrt(2.0); }

TEST(MetricAdaptation3d, AConstantAnisotropicMetricGivesAUnitMesh) {
  const Vec<3> h(0.05, 0.1, 0.2);
  const MetricField<3> metric = [&](const Vec<3>&) -> Metric<3> { return h.cwiseInverse().cwiseAbs2().asDiagonal(); };
  MetricAdaptationStats stats;
  const SimplexMesh<3> mesh = adapt_to_metric(leaf_mesh(KuhnBisectionForest<3>(2)).mesh, metric, 12, &stats);
  const TetFigures f = figures(mesh, metric);
  expect_tiles_the_box(f);
  // Edges of metric length in [1/sqrt(2), sqrt(2)] give tetrahedra of volume between a unit
  // one's 1 / 2^(3/2) and 2^(3/2) times, where they are fair: their count within 2^(3/2) of a
  // unit mesh's. An isotropic mesh at the smallest size would need 8x more.
  const double expected = unit_mesh_tetrahedra(1.0 / (h.x() * h.y() * h.z()));
  EXPECT_GT(double(mesh.simplices.size()), expected / std::pow(2.0, 1.5));
  EXPECT_LT(double(mesh.simplices.size()), expected * std::pow(2.0, 1.5));
  EXPECT_GT(f.mean_length, kShortEdge);
  EXPECT_LT(f.mean_length, kLongEdge);
  std::printf("constant metric: %zu vertices, %zu tetrahedra (unit mesh %.0f), %d cycles, %ld splits, %ld collapses, %ld swaps, "
              "min quality %.3f, mean length %.3f, %.3f in bounds\n",
              mesh.vertices.size(), mesh.simplices.size(), expected, stats.cycles, long(stats.splits), long(stats.collapses),
              long(stats.flips), f.min_quality, f.mean_length, f.share_in_bounds);
}

// The sphere of radius 0.3 about the box's centre, and its level-set metric from its exact
// derivatives (the Hessian of the distance is (I - n n^T) / rho).
constexpr double kRadius = 0.3;
double sphere_distance(const Vec<3>& x) { return (x - Vec<3>::Constant(0.5)).norm() - kRadius; }
// h_min, h_max, error (lsrecon's default: a quarter of the size across), growth
MetricSizes sphere_sizes() { return {1.0 / 64, 1.0 / 4, 0.25 / 64, 0.5}; }
Metric<3> sphere_metric(const Vec<3>& x) {
  const Vec<3> r = x - Vec<3>::Constant(0.5);
  const double rho = std::max(r.norm(), 1e-9);
  const Vec<3> n = r / rho;
  return level_set_metric<3>(rho - kRadius, n, (Metric<3>::Identity() - n * n.transpose()) / rho, sphere_sizes());
}

// The largest distance to the sphere of the points where the P1 interpolant of its distance
// vanishes on the mesh's edges.
double zero_set_error(const SimplexMesh<3>& mesh) {
  double worst = 0.0;
  for (const auto& s : mesh.simplices) {
    for (std::size_t i = 0; i < 4; ++i) {
      for (std::size_t j = i + 1; j < 4; ++j) {
        const Vec<3>& a = mesh.vertices[std::size_t(s[i])];
        const Vec<3>& b = mesh.vertices[std::size_t(s[j])];
        const double ua = sphere_distance(a), ub = sphere_distance(b);
        if ((ua < 0.0) == (ub < 0.0)) continue;
        worst = std::max(worst, std::abs(sphere_distance(a + ua / (ua - ub) * (b - a))));
      }
    }
  }
  return worst;
}

TEST(MetricAdaptation3d, ASphereNeedsFewerVerticesAlongItThanAcross) {
  const MetricSizes sizes = sphere_sizes();
  const MetricField<3> anisotropic = sphere_metric;
  const MetricField<3> isotropic = [&](const Vec<3>& x) -> Metric<3> {
    const double h = std::min(sizes.h_max, sizes.h_min + sizes.growth * std::abs(sphere_distance(x)));
    return Metric<3>::Identity() / (h * h);
  };
  const SimplexMesh<3> start = leaf_mesh(KuhnBisectionForest<3>(4)).mesh;
  MetricAdaptationStats sa, si;
  const SimplexMesh<3> a = adapt_to_metric(start, anisotropic, 12, &sa);
  const SimplexMesh<3> i = adapt_to_metric(start, isotropic, 12, &si);
  const TetFigures fa = figures(a, anisotropic), fi = figures(i, isotropic);
  expect_tiles_the_box(fa);
  expect_tiles_the_box(fi);
  // Along the sphere the sizes are sqrt(8 error R) = sqrt(0.6 h_min) = 6.2 h_min in both
  // directions: near it a unit mesh has 38x fewer vertices than the isotropic one. The issue's
  // bar for the 3D corpus is 2x.
  EXPECT_GT(double(i.vertices.size()), 2.0 * double(a.vertices.size()));
  // As in 2D: an edge of metric length l crossing the sphere cuts it within l^2 error.
  const double error = zero_set_error(a);
  EXPECT_LT(error, 2.0 * sizes.error);
  std::printf("sphere: anisotropic %zu vertices (%d cycles, %ld splits, %ld collapses, %ld swaps, min quality %.3f, mean length %.3f, "
              "%.3f in bounds, zero set within %.2e), isotropic %zu (%d cycles, min quality %.3f, %.3f in bounds, %.2e)\n",
              a.vertices.size(), sa.cycles, long(sa.splits), long(sa.collapses), long(sa.flips), fa.min_quality, fa.mean_length,
              fa.share_in_bounds, error, i.vertices.size(), si.cycles, fi.min_quality, fi.share_in_bounds, zero_set_error(i));
}

}  // namespace
}  // namespace lsr
