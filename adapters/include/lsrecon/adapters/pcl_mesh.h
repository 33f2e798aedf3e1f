// SPDX-License-Identifier: BSD-3-Clause
/// @file pcl_mesh.h
/// @brief Core reconstructions -> pcl::PolygonMesh (shared vertices with normals, as a
/// pcl::PointNormal cloud) and back to core triangles for checks.
#pragma once

#include "lsrecon/adapters/file_formats.h"
#include "lsrecon/core/level_set_extraction.h"

#include <pcl/PolygonMesh.h>
#include <pcl/conversions.h>
#include <pcl/point_types.h>

#include <string>
#include <vector>

namespace lsr::adapters {

/// @brief A cloud of one FLOAT32 field `name`, one point per value.
pcl::PCLPointCloud2 scalar_field(const std::string& name, const std::vector<float>& values);

/// @brief Appends to `to` the fields of `from` that `to` lacks, point by point (the same
/// number of points), e.g. the colour of each vertex's nearest input point.
/// @throw lsr::Error if the point counts differ.
void append_fields(const pcl::PCLPointCloud2& from, pcl::PCLPointCloud2& to);

/// @brief One pcl::PointNormal per vertex, with its unit normal (z = z_plane, normal_z = 0 in 2D).
template <int D>
pcl::PointCloud<pcl::PointNormal> normal_cloud(const Points<D>& vertices, const Points<D>& normals,
                                               double z_plane = 0.0) {
  pcl::PointCloud<pcl::PointNormal> cloud;
  cloud.resize(vertices.size());
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    pcl::PointNormal& p = cloud[i];
    p.x = float(vertices[i][0]);
    p.y = float(vertices[i][1]);
    p.z = float(D == 3 ? vertices[i][D - 1] : z_plane);
    p.normal_x = float(normals[i][0]);
    p.normal_y = float(normals[i][1]);
    p.normal_z = float(D == 3 ? normals[i][D - 1] : 0.0);
    p.curvature = 0.0f;
  }
  cloud.width = std::uint32_t(cloud.size());
  cloud.height = 1;
  cloud.is_dense = true;
  return cloud;
}

/// @brief Triangles (3D) as pcl::Vertices.
inline std::vector<pcl::Vertices> polygons_from_triangles(const std::vector<std::array<Index, 3>>& triangles) {
  std::vector<pcl::Vertices> polygons(triangles.size());
  for (std::size_t f = 0; f < triangles.size(); ++f) {
    polygons[f].vertices = {pcl::index_t(triangles[f][0]), pcl::index_t(triangles[f][1]), pcl::index_t(triangles[f][2])};
  }
  return polygons;
}

/// @brief Closed loops (2D) as pcl::Vertices, one per loop, in order (as pcl::ConcaveHull).
inline std::vector<pcl::Vertices> polygons_from_loops(const std::vector<std::vector<Index>>& loops) {
  std::vector<pcl::Vertices> polygons(loops.size());
  for (std::size_t l = 0; l < loops.size(); ++l) {
    polygons[l].vertices.assign(loops[l].begin(), loops[l].end());
  }
  return polygons;
}

/// @brief The x, y, z of a PolygonMesh's cloud and its triangles (non-triangles are skipped),
/// e.g. to check a mesh with lsr::analyze_surface.
inline void triangles_from_polygon_mesh(const pcl::PolygonMesh& mesh, Points<3>& vertices,
                                        std::vector<std::array<Index, 3>>& triangles) {
  pcl::PointCloud<pcl::PointXYZ> cloud;
  pcl::fromPCLPointCloud2(mesh.cloud, cloud);
  vertices.clear();
  for (const auto& p : cloud) vertices.emplace_back(p.x, p.y, p.z);
  triangles.clear();
  for (const auto& poly : mesh.polygons) {
    if (poly.vertices.size() == 3) {
      triangles.push_back({Index(poly.vertices[0]), Index(poly.vertices[1]), Index(poly.vertices[2])});
    }
  }
}

}  // namespace lsr::adapters
