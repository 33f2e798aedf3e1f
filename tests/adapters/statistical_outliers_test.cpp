// SPDX-License-Identifier: BSD-3-Clause
/// @file statistical_outliers_test.cpp
#include "lsrecon/adapters/statistical_outliers.h"

#include "lsrecon/core/errors.h"
#include "lsrecon/testdata/shape_corpus.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace lsr::adapters {
namespace {

// A random sphere sample (radius about 1) with a cluster of 6 points 0.5 off it.
struct Cloud {
  Points<3> points;
  std::size_t genuine = 0;
};

Cloud sphere_with_a_cluster() {
  Cloud c;
  c.points = sample_test_shape(make_test_shape("sphere"), 3000).points;
  c.genuine = c.points.size();
  Vec<3> far = c.points[0] * 1.5;
  for (int k = 0; k < 6; ++k) c.points.push_back(far + Vec<3>(0.01 * k, -0.007 * k, 0.003 * k));
  return c;
}

TEST(StatisticalOutliers, RemoveAFarClusterAndFewGenuinePoints) {
  const Cloud c = sphere_with_a_cluster();
  const std::vector<std::size_t> kept = statistical_inliers(c.points, {16, 3.0});
  EXPECT_TRUE(std::is_sorted(kept.begin(), kept.end()));
  // The cluster's 16 nearest neighbours are mostly sphere points 0.5 away: far beyond the mean.
  EXPECT_LT(kept.back(), c.genuine);
  // A 3-deviation threshold cuts 0.13% of a normal distribution; the mean-distance distribution
  // of a random sample is skewed towards large values, so allow a few times that.
  EXPECT_GE(double(kept.size()), 0.99 * double(c.genuine));
}

TEST(StatisticalOutliers, OffKeepsEverythingAndLargeOffsetsChangeNothing) {
  Cloud c = sphere_with_a_cluster();
  EXPECT_EQ(statistical_inliers(c.points, {}).size(), c.points.size());
  const std::vector<std::size_t> kept = statistical_inliers(c.points, {16, 3.0});
  for (auto& p : c.points) p += Vec<3>(1e6, -2e6, 1e6);  // georeferenced scan coordinates
  EXPECT_EQ(statistical_inliers(c.points, {16, 3.0}), kept);
  EXPECT_THROW(statistical_inliers(c.points, {-1, 3.0}), InvalidInput);
  EXPECT_THROW(statistical_inliers(c.points, {16, 0.0}), InvalidInput);
}

TEST(StatisticalOutliers, KeepOnlyCompactsInOrder) {
  std::vector<int> v = {10, 11, 12, 13, 14};
  keep_only(v, {0, 2, 3});
  EXPECT_EQ(v, (std::vector<int>{10, 12, 13}));
}

}  // namespace
}  // namespace lsr::adapters
