// SPDX-License-Identifier: BSD-3-Clause
/// @file surface_distance.cpp
#include "lsrecon/testdata/surface_distance.h"

#include "geometry/facet_mesh_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace lsr {
namespace {

Vec<3> sdf_gradient(const std::function<double(const Vec<3>&)>& sdf, const Vec<3>& p, double h) {
  Vec<3> g;
  for (int d = 0; d < 3; ++d) {
    Vec<3> e = Vec<3>::Zero();
    e[d] = h;
    g[d] = (sdf(p + e) - sdf(p - e)) / (2 * h);
  }
  return g;
}

}  // namespace

SurfaceDistances compare_to_truth(const Points<3>& vertices, const std::vector<std::array<Index, 3>>& triangles,
                                  const std::function<double(const Vec<3>&)>& sdf, const Points<3>& truth_samples,
                                  int samples) {
  SurfaceDistances out;
  if (triangles.empty()) {
    out.mean_to_truth = out.max_to_truth = out.mean_from_truth = out.max_from_truth = out.chamfer =
        out.hausdorff = std::numeric_limits<double>::infinity();
    return out;
  }
  // Reconstruction -> truth: vertices plus area-proportional samples.
  std::vector<double> area(triangles.size());
  double total_area = 0.0;
  Vec<3> lo = vertices[0], hi = vertices[0];
  for (const auto& v : vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  const double step = 1e-6 * (hi - lo).norm();
  double normal_sum = 0.0;
  for (std::size_t f = 0; f < triangles.size(); ++f) {
    const auto& t = triangles[f];
    const Vec<3> n = (vertices[t[1]] - vertices[t[0]]).cross(vertices[t[2]] - vertices[t[0]]);
    area[f] = 0.5 * n.norm();
    total_area += area[f];
    if (area[f] > 0.0) {
      const Vec<3> c = (vertices[t[0]] + vertices[t[1]] + vertices[t[2]]) / 3.0;
      const Vec<3> g = sdf_gradient(sdf, c, step);
      if (g.norm() > 0.0) normal_sum += area[f] * n.normalized().dot(g.normalized());
    }
  }
  out.normal_consistency = total_area > 0.0 ? normal_sum / total_area : 0.0;
  std::mt19937 rng(12345);
  std::discrete_distribution<std::size_t> pick(area.begin(), area.end());
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double sum = 0.0;
  std::size_t count = 0;
  auto add = [&](const Vec<3>& p) {
    const double e = std::abs(sdf(p));
    sum += e;
    out.max_to_truth = std::max(out.max_to_truth, e);
    ++count;
  };
  for (const auto& v : vertices) add(v);
  for (int s = 0; s < samples && total_area > 0.0; ++s) {
    const auto& t = triangles[pick(rng)];
    double a = unit(rng), b = unit(rng);
    if (a + b > 1.0) {
      a = 1.0 - a;
      b = 1.0 - b;
    }
    add(vertices[t[0]] + a * (vertices[t[1]] - vertices[t[0]]) + b * (vertices[t[2]] - vertices[t[0]]));
  }
  out.mean_to_truth = sum / double(count);

  // Truth -> reconstruction, exact.
  const std::vector<double> best = TriangleMeshDistance(vertices, triangles).distances(truth_samples);
  sum = 0.0;
  for (double b : best) {
    sum += b;
    out.max_from_truth = std::max(out.max_from_truth, b);
  }
  out.mean_from_truth = sum / double(std::max<std::size_t>(1, truth_samples.size()));
  out.chamfer = 0.5 * (out.mean_to_truth + out.mean_from_truth);
  out.hausdorff = std::max(out.max_to_truth, out.max_from_truth);
  return out;
}

}  // namespace lsr
