// SPDX-License-Identifier: BSD-3-Clause
/// @file statistical_outliers.h
/// @brief pcl::StatisticalOutlierRemoval on core points, for scans with clusters of outliers.
///
/// The core already leaves out isolated points (SamplingOptions::outlier_factor: nearest
/// neighbour farther than a few local spacings). PCL's filter instead removes points whose mean
/// distance to their k nearest neighbours exceeds the cloud's mean by stddev_mul standard
/// deviations: it also catches small clusters of outliers, but on an i.i.d. random sample its
/// tail holds genuine points in the sparser regions, so it is off unless asked for.
#pragma once

#include "lsrecon/core/types.h"

#include <cstddef>
#include <vector>

namespace lsr::adapters {

/// @brief pcl::StatisticalOutlierRemoval's two parameters.
struct StatisticalOutlierFilter {
  int mean_k = 0;           ///< neighbours whose mean distance is compared (setMeanK); 0: off
  double stddev_mul = 3.0;  ///< threshold in standard deviations (setStddevMulThresh)
};

/// @brief The indices (ascending) of the points the filter keeps; all of them when it is off.
/// Distances are taken in float about the points' centroid, so a large coordinate offset
/// (1e6) does not erase them.
/// @throw lsr::InvalidInput if mean_k < 0 or stddev_mul is not finite and positive.
std::vector<std::size_t> statistical_inliers(const Points<3>& points, const StatisticalOutlierFilter& filter);

/// @brief Keeps the listed entries of v, in order.
template <class T, class A>
void keep_only(std::vector<T, A>& v, const std::vector<std::size_t>& kept) {
  std::size_t n = 0;
  for (const std::size_t i : kept) v[n++] = v[i];
  v.resize(n);
}

}  // namespace lsr::adapters
