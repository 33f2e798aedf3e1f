// SPDX-License-Identifier: BSD-3-Clause
#include "lsrecon/adapters/statistical_outliers.h"

#include "lsrecon/core/errors.h"

#include <pcl/filters/statistical_outlier_removal.h>
#include <pcl/point_types.h>

#include <cmath>
#include <numeric>

namespace lsr::adapters {

std::vector<std::size_t> statistical_inliers(const Points<3>& points, const StatisticalOutlierFilter& f) {
  if (f.mean_k < 0) throw InvalidInput("the statistical outlier filter needs a neighbour count >= 0", "use 0 (off) or e.g. 16");
  if (!(std::isfinite(f.stddev_mul) && f.stddev_mul > 0.0)) {
    throw InvalidInput("the statistical outlier threshold must be a positive number of deviations", "use e.g. 3");
  }
  std::vector<std::size_t> all(points.size());
  std::iota(all.begin(), all.end(), std::size_t(0));
  if (f.mean_k == 0 || points.size() <= std::size_t(f.mean_k)) return all;
  Vec<3> centroid = Vec<3>::Zero();
  for (const auto& p : points) centroid += p / double(points.size());
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud(new pcl::PointCloud<pcl::PointXYZ>);
  cloud->reserve(points.size());
  for (const auto& p : points) {
    const Vec<3> q = p - centroid;
    cloud->push_back(pcl::PointXYZ(float(q.x()), float(q.y()), float(q.z())));
  }
  pcl::StatisticalOutlierRemoval<pcl::PointXYZ> filter;
  filter.setInputCloud(cloud);
  filter.setMeanK(f.mean_k);
  filter.setStddevMulThresh(f.stddev_mul);
  pcl::Indices kept;
  filter.filter(kept);
  return {kept.begin(), kept.end()};
}

}  // namespace lsr::adapters
