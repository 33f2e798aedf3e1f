// SPDX-License-Identifier: BSD-3-Clause
/// @file data_preparation_test.cpp
/// @brief The data stage: distinct finite points and where each input point went; spanning
/// checks; isolated points; mesh sizes clamped to the resolution limits.
#include "sampling/data_preparation.h"

#include "lsrecon/core/errors.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace lsr::detail {
namespace {

TEST(DataPreparation, CopiesAndNonFinitePointsMapBackToTheInput) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const Points<2> input = {Vec<2>(0, 0), Vec<2>(nan, 1), Vec<2>(1, 0), Vec<2>(0, 0), Vec<2>(0, 1)};
  const DataPoints<2> d = distinct_finite_points(input);
  EXPECT_EQ(d.points, (Points<2>{Vec<2>(0, 0), Vec<2>(1, 0), Vec<2>(0, 1)}));
  EXPECT_EQ(d.kept, (std::vector<std::size_t>{0, 2, 4}));
  EXPECT_EQ(d.finite, (std::vector<std::size_t>{0, 2, 3, 4}));
  EXPECT_EQ(d.first, (std::vector<std::size_t>{0, 2, 0, 4}));
  // Normals per distinct point come back per input point: the copy shares its first's, the
  // non-finite point has none.
  const Points<2> normals = {Vec<2>(1, 0), Vec<2>(0, 1), Vec<2>(-1, 0)};
  const Points<2> n = d.input_normals(normals, input.size());
  EXPECT_EQ(n[0], normals[0]);
  EXPECT_TRUE(std::isnan(n[1].x()));
  EXPECT_EQ(n[2], normals[1]);
  EXPECT_EQ(n[3], normals[0]);
  EXPECT_EQ(n[4], normals[2]);
}

TEST(DataPreparation, PointsThatSpanNoRegionAreRefused) {
  EXPECT_THROW(require_spanning<3>({Vec<3>(0, 0, 0), Vec<3>(1, 0, 0), Vec<3>(0, 1, 0)}), InvalidInput);
  EXPECT_THROW(require_spanning<3>({Vec<3>(0, 0, 0), Vec<3>(1, 0, 0), Vec<3>(0, 1, 0), Vec<3>(1, 1, 0)}), InvalidInput);
  EXPECT_NO_THROW(require_spanning<3>({Vec<3>(0, 0, 0), Vec<3>(1, 0, 0), Vec<3>(0, 1, 0), Vec<3>(0, 0, 1)}));
  EXPECT_THROW(require_spanning<2>({Vec<2>(0, 0), Vec<2>(1, 1), Vec<2>(2, 2)}), InvalidInput);
}

TEST(DataPreparation, IsolatedPointsGoWithTheirInputIndices) {
  LocalSampling<2> s;
  s.spacing = {1.0, 1.0, 1.0};
  s.gap = {1.0, 3.5, 2.9};  // the second lies beyond 3 spacings
  Points<2> points = {Vec<2>(0, 0), Vec<2>(9, 9), Vec<2>(1, 0)};
  std::vector<std::size_t> kept = {4, 7, 9};
  EXPECT_TRUE(drop_isolated(s, 3.0, points, kept));
  EXPECT_EQ(kept, (std::vector<std::size_t>{4, 9}));
  EXPECT_EQ(points, (Points<2>{Vec<2>(0, 0), Vec<2>(1, 0)}));
  EXPECT_FALSE(drop_isolated(s, 0.0, points, kept));  // factor 0: keep all
}

TEST(DataPreparation, MeshSizesFollowTheScaleWithinTheResolutionLimits) {
  // 3D: within [1/256, 1/32] by default, [1/64, 1/32] with a resolution cap of 64.
  const std::vector<double> scale = {1e-5, 0.01, 0.5};
  EXPECT_EQ(local_mesh_sizes<3>(scale, 0.0, 0.0), (std::vector<double>{1.0 / 256, 0.01, 1.0 / 32}));
  EXPECT_EQ(local_mesh_sizes<3>(scale, 0.0, 64.0), (std::vector<double>{1.0 / 64, 1.0 / 64, 1.0 / 32}));
  EXPECT_EQ(local_mesh_sizes<2>(scale, 0.0, 0.0), (std::vector<double>{1.0 / 4096, 0.01, 1.0 / 64}));
  EXPECT_EQ(local_mesh_sizes<3>(scale, 0.02, 0.0), (std::vector<double>{0.02, 0.02, 0.02}));  // asked for
}

}  // namespace
}  // namespace lsr::detail
