// SPDX-License-Identifier: BSD-3-Clause
/// @file pcl_points.h
/// @brief pcl::PointCloud<PointT> -> core points: honours indices, skips (and counts) points
/// with NaN or infinite coordinates, as PCL clouds routinely carry them.
#pragma once

#include "lsrecon/core/types.h"

#include <pcl/point_cloud.h>
#include <pcl/types.h>

#include <cmath>
#include <cstddef>
#include <vector>

namespace lsr::adapters {

/// @brief Points taken from a cloud, and how many were left out.
struct ConvertedPoints {
  Points<3> points;
  std::vector<pcl::index_t> source;  ///< #points: the cloud index each point came from
  std::size_t skipped_non_finite = 0;
  std::size_t skipped_bad_index = 0;  ///< indices that were negative or past the cloud's end
};

/// @brief The x, y, z of the cloud's points (only those listed in indices when it is given).
template <typename PointT>
ConvertedPoints points_from_cloud(const pcl::PointCloud<PointT>& cloud,
                                  const pcl::Indices* indices = nullptr) {
  ConvertedPoints out;
  auto take = [&](const PointT& p, pcl::index_t i) {
    if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) {
      out.points.emplace_back(double(p.x), double(p.y), double(p.z));
      out.source.push_back(i);
    } else {
      ++out.skipped_non_finite;
    }
  };
  if (indices) {
    out.points.reserve(indices->size());
    for (const auto i : *indices) {
      if (i < 0 || std::size_t(i) >= cloud.size()) {
        ++out.skipped_bad_index;
      } else {
        take(cloud[std::size_t(i)], i);
      }
    }
  } else {
    out.points.reserve(cloud.size());
    for (std::size_t i = 0; i < cloud.size(); ++i) take(cloud[i], pcl::index_t(i));
  }
  return out;
}

}  // namespace lsr::adapters
