// SPDX-License-Identifier: BSD-3-Clause
/// @file consumer.cpp
/// @brief Uses the installed package as a user would: a generated cloud through
/// pcl::LevelSetReconstruction, including PCL and lsrecon's PCL header only. Exit 0 when the result is a converged, non-empty mesh.
#include <lsrecon/pcl/level_set_reconstruction.h>

#include <pcl/point_types.h>

#ifdef OM_VERSION
#error "lsrecon's PCL header included OpenMesh: the PCL class must not need it"
#endif

#include <cmath>
#include <cstdio>

int main() {
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud(new pcl::PointCloud<pcl::PointXYZ>);
  const int n = 3000;
  for (int i = 0; i < n; ++i) {  // Fibonacci sphere
    const double z = 1.0 - (2.0 * i + 1.0) / n, r = std::sqrt(1.0 - z * z), a = 2.399963229728653 * i;
    cloud->push_back(pcl::PointXYZ(float(r * std::cos(a)), float(r * std::sin(a)), float(z)));
  }
  pcl::LevelSetReconstruction<pcl::PointXYZ> ls;
  ls.setInputCloud(cloud);
  ls.setResolution(0.08);  // cloud units: the sphere has radius 1
  pcl::PolygonMesh mesh;
  ls.reconstruct(mesh);
  std::printf("consumer: %zu triangles, converged %d\n", mesh.polygons.size(), int(ls.getStatus().converged));
  return ls.getStatus().converged && !mesh.polygons.empty() ? 0 : 1;
}
