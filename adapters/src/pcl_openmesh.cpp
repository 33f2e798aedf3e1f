// SPDX-License-Identifier: BSD-3-Clause
/// @file pcl_openmesh.cpp
#include "lsrecon/adapters/pcl_openmesh.h"

#include "lsrecon/adapters/pcl_mesh.h"

#include <pcl/common/io.h>
#include <pcl/conversions.h>

#include <cstring>

namespace lsr::adapters {

TriMesh to_openmesh(const pcl::PolygonMesh& mesh) {
  LevelSetMesh<3> surface;
  triangles_from_polygon_mesh(mesh, surface.vertices, surface.facets);
  Points<3> normals;
  if (pcl::getFieldIndex(mesh.cloud, "normal_x") >= 0) {
    pcl::PointCloud<pcl::Normal> n;
    pcl::fromPCLPointCloud2(mesh.cloud, n);
    for (const auto& p : n) normals.emplace_back(p.normal_x, p.normal_y, p.normal_z);
  }
  TriMesh out = to_openmesh(surface, normals);
  const int d = pcl::getFieldIndex(mesh.cloud, kDistanceProperty);
  if (d >= 0 && mesh.cloud.fields[std::size_t(d)].datatype == pcl::PCLPointField::FLOAT32) {
    std::vector<double> distance(surface.vertices.size());
    for (std::size_t i = 0; i < distance.size(); ++i) {
      float value = 0.0f;
      std::memcpy(&value, &mesh.cloud.data[i * mesh.cloud.point_step + mesh.cloud.fields[std::size_t(d)].offset], sizeof value);
      distance[i] = value;
    }
    set_distance_to_data(out, distance);
  }
  return out;
}

}  // namespace lsr::adapters
