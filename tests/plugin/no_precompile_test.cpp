// SPDX-License-Identifier: BSD-3-Clause
/// @file no_precompile_test.cpp
/// @brief A point type without an explicit instantiation, through PCL_NO_PRECOMPILE.
#define PCL_NO_PRECOMPILE
#include "lsrecon/testdata/analytic_shapes.h"
#include "lsrecon/pcl/level_set_reconstruction.h"

#include <pcl/point_types.h>

#include <gtest/gtest.h>

TEST(PclLevelSetReconstruction, OtherPointTypesWorkWithPclNoPrecompile) {
  pcl::PointCloud<pcl::PointWithViewpoint>::Ptr cloud(new pcl::PointCloud<pcl::PointWithViewpoint>);
  for (const auto& p : lsr::Sphere{lsr::Vec<3>(0, 0, 0), 1.0}.sample(3000)) {
    pcl::PointWithViewpoint q;
    q.x = float(p.x());
    q.y = float(p.y());
    q.z = float(p.z());
    cloud->push_back(q);
  }
  pcl::LevelSetReconstruction<pcl::PointWithViewpoint> ls;
  ls.setInputCloud(cloud);
  ls.setResolution(0.08);  // cloud units: the sphere has radius 1
  pcl::PolygonMesh mesh;
  ls.reconstruct(mesh);
  EXPECT_TRUE(ls.getStatus().converged);
  EXPECT_GT(mesh.polygons.size(), 1000u);
}
