// SPDX-License-Identifier: BSD-3-Clause
/// @file pcl_points_test.cpp
#include "lsrecon/adapters/pcl_points.h"

#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <limits>

namespace lsr::adapters {
namespace {

template <typename PointT>
pcl::PointCloud<PointT> cloud_with_a_nan() {
  pcl::PointCloud<PointT> cloud;
  PointT p;
  p.x = 1;
  p.y = 2;
  p.z = 3;
  cloud.push_back(p);
  p.x = std::numeric_limits<float>::quiet_NaN();
  cloud.push_back(p);
  p.x = 4;
  p.z = -std::numeric_limits<float>::infinity();
  cloud.push_back(p);
  p.z = 6;
  cloud.push_back(p);
  return cloud;
}

template <typename PointT>
void check_conversion() {
  const auto cloud = cloud_with_a_nan<PointT>();
  const ConvertedPoints all = points_from_cloud(cloud);
  ASSERT_EQ(all.points.size(), 2u);
  EXPECT_EQ(all.skipped_non_finite, 2u);
  EXPECT_EQ(all.points[0], Vec<3>(1, 2, 3));
  EXPECT_EQ(all.points[1], Vec<3>(4, 2, 6));

  const pcl::Indices some{3, 1, 7, -1};
  const ConvertedPoints picked = points_from_cloud(cloud, &some);
  ASSERT_EQ(picked.points.size(), 1u);
  EXPECT_EQ(picked.points[0], Vec<3>(4, 2, 6));
  EXPECT_EQ(picked.skipped_non_finite, 1u);
  EXPECT_EQ(picked.skipped_bad_index, 2u);
}

TEST(PclPoints, ConvertsPointTypesWithAndWithoutNormals) {
  check_conversion<pcl::PointXYZ>();
  check_conversion<pcl::PointXYZRGB>();
  check_conversion<pcl::PointNormal>();
}

}  // namespace
}  // namespace lsr::adapters
