// SPDX-License-Identifier: BSD-3-Clause
/// @file mesh_measures.cpp
#include "mesh_measures.h"

#include "geometry/nearest_point_index.h"
#include "lsrecon/adapters/pcl_mesh.h"

#include <algorithm>

namespace lsr::demos {

void weld(const pcl::PolygonMesh& mesh, double diagonal, lsr::Points<3>& vertices,
          std::vector<std::array<lsr::Index, 3>>& triangles) {
  lsr::Points<3> raw;
  std::vector<std::array<lsr::Index, 3>> soup;
  lsr::adapters::triangles_from_polygon_mesh(mesh, raw, soup);
  // Each vertex joins the lowest-index vertex within the tolerance: deterministic, and unlike
  // rounding to cells it never separates two copies that straddle a cell boundary.
  const double tolerance = 1e-6 * diagonal;
  std::vector<lsr::Index> remap(raw.size(), -1);
  vertices.clear();
  if (!raw.empty()) {
    const lsr::NearestPointIndex<3> index(raw);
    std::vector<lsr::Index> near;
    for (std::size_t i = 0; i < raw.size(); ++i) {
      if (remap[i] >= 0) continue;
      remap[i] = lsr::Index(vertices.size());
      vertices.push_back(raw[i]);
      index.within(raw[i], tolerance, near);
      for (lsr::Index j : near) {
        if (remap[j] < 0) remap[j] = remap[i];
      }
    }
  }
  triangles.clear();
  for (auto t : soup) {
    for (auto& v : t) v = remap[v];
    if (t[0] != t[1] && t[1] != t[2] && t[0] != t[2]) triangles.push_back(t);
  }
}

SupportFigures support_figures(const lsr::Points<3>& vertices, const std::vector<std::array<lsr::Index, 3>>& triangles,
                               const lsr::Points<3>& points) {
  SupportFigures f;
  if (triangles.empty() || points.size() < 9) return f;
  const lsr::NearestPointIndex<3> data(points);
  lsr::LargeVector<lsr::Index> knn;
  data.query_k(points, 9, knn);  // the point itself first
  std::vector<double> eighth(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) eighth[i] = (points[std::size_t(knn[9 * i + 8])] - points[i]).norm();
  std::nth_element(eighth.begin(), eighth.begin() + long(eighth.size() / 2), eighth.end());
  const double spacing = eighth[eighth.size() / 2];
  lsr::Points<3> centroids;
  std::vector<double> area;
  for (const auto& t : triangles) {
    const lsr::Vec<3>&a = vertices[std::size_t(t[0])], &b = vertices[std::size_t(t[1])], &c = vertices[std::size_t(t[2])];
    centroids.push_back((a + b + c) / 3.0);
    area.push_back(0.5 * (b - a).cross(c - a).norm());
  }
  std::vector<double> distance;
  data.query(centroids, distance);
  double far = 0.0;
  for (std::size_t k = 0; k < area.size(); ++k) {
    f.area += area[k];
    if (distance[k] > 2.0 * spacing) far += area[k];
  }
  f.far_share = f.area > 0.0 ? far / f.area : 0.0;
  return f;
}

}  // namespace lsr::demos
