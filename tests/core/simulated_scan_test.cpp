// SPDX-License-Identifier: BSD-3-Clause
/// @file simulated_scan_test.cpp
/// @brief The simulated scanner: hits on the surface with their true normals, the raster's
/// along / across spacing, an unseen underside from above, and each view's rigid registration
/// error, on a sphere where all of it is exact.
#include "lsrecon/testdata/simulated_scan.h"

#include "geometry/nearest_point_index.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace lsr {
namespace {

TestShape unit_sphere() {
  TestShape s;
  s.name = "sphere";
  s.sdf = [](const Vec<3>& p) { return p.norm() - 1.0; };
  s.lo = Vec<3>::Constant(-1.0);
  s.hi = Vec<3>::Constant(1.0);
  s.genus = {0};
  return s;
}

ScannerSettings exact() {
  ScannerSettings s;
  s.range_noise = 0.0;
  s.registration_angle = 0.0;
  s.registration_shift = 0.0;
  s.lines = 40;
  s.samples_per_line = 200;
  return s;
}

TEST(SimulatedScan, HitsLieOnTheSurfaceWithTheirNormalsAndCoverItFromAllSides) {
  const SampledShape scan = simulate_scan(unit_sphere(), exact());
  ASSERT_GT(scan.points.size(), 6u * 40 * 200 / 4);
  double lowest = 1.0, highest = -1.0;
  for (std::size_t i = 0; i < scan.points.size(); ++i) {
    EXPECT_NEAR(scan.points[i].norm(), 1.0, 1e-6);  // sphere tracing stops within 1e-7 diagonals
    EXPECT_NEAR(scan.normals[i].dot(scan.points[i]), 1.0, 1e-6);
    lowest = std::min(lowest, scan.points[i].z());
    highest = std::max(highest, scan.points[i].z());
  }
  EXPECT_LT(lowest, -0.9);
  EXPECT_GT(highest, 0.9);
}

// Along a line the rays are 2 half_angle / samples apart, across 2 half_angle / lines: 5 times
// farther with 40 lines of 200. Facing the view (at the sphere's nearest point, range 1.5 d - 1
// with d = 2 sqrt(3)), the hits are that angle times the range apart; the median neighbour is
// one along the line, far below the lines' spacing.
TEST(SimulatedScan, ScanLinesAreDenseAlongAndSparseAcross) {
  ScannerSettings s = exact();
  s.views = 1;
  const SampledShape scan = simulate_scan(unit_sphere(), s);
  const double diagonal = 2.0 * std::sqrt(3.0), range = 1.5 * diagonal - 1.0;
  const double half_angle = std::asin(0.5 * diagonal / (1.5 * diagonal));
  const double along = 2.0 * half_angle / 200 * range, across = 2.0 * half_angle / 40 * range;
  // The nearest neighbour of each hit: rays at least about the angle apart (cos(half_angle) of
  // it off the raster's centre line), hits at least the facing range away.
  const NearestPointIndex<3> index(scan.points);
  LargeVector<Index> nearest;
  index.query_k(scan.points, 2, nearest, 1);
  std::vector<double> spacing;
  for (std::size_t i = 0; i < scan.points.size(); ++i) spacing.push_back((scan.points[std::size_t(nearest[2 * i + 1])] - scan.points[i]).norm());
  std::nth_element(spacing.begin(), spacing.begin() + spacing.size() / 2, spacing.end());
  const double median = spacing[spacing.size() / 2];
  // Neighbours along the line: at least the facing spacing (foreshortening only widens it),
  // and well below the across-line spacing.
  EXPECT_GE(median, std::cos(half_angle) * along);
  EXPECT_LT(median, 0.5 * across);
}

TEST(SimulatedScan, FromAboveTheUndersideIsUnseen) {
  ScannerSettings s = exact();
  s.from_above = true;
  const SampledShape scan = simulate_scan(unit_sphere(), s);
  // Views at elevations from asin(0.1) up, at 1.5 diagonals: a view sees the sphere down to
  // the circle where its tangent rays touch, whose lowest point is below the view's own
  // elevation by the tangent angle acos(1 / range) = 79 degrees: no hit below z = -sin(79 - 5.7
  // degrees) = -0.96, and none near the bottom pole.
  for (const auto& p : scan.points) EXPECT_GT(p.z(), -0.96);
  const Vec<3> bottom(0, 0, -1);
  const double nearest_to_bottom =
      (*std::min_element(scan.points.begin(), scan.points.end(), [&](const Vec<3>& a, const Vec<3>& b) {
        return (a - bottom).norm() < (b - bottom).norm();
      }) - bottom).norm();
  EXPECT_GT(nearest_to_bottom, 0.25);
}

TEST(SimulatedScan, EachViewIsMovedRigidlyByItsRegistrationError) {
  ScannerSettings s = exact();
  s.registration_angle = 0.002;
  s.registration_shift = 0.002;
  const SampledShape scan = simulate_scan(unit_sphere(), s);
  // A rotation about the centre keeps the radius; the shift moves it by at most 0.002 d.
  const double shift = 0.002 * 2.0 * std::sqrt(3.0);
  double worst = 0.0;
  for (const auto& p : scan.points) worst = std::max(worst, std::abs(p.norm() - 1.0));
  EXPECT_LE(worst, shift + 1e-6);
  EXPECT_GT(worst, 0.3 * shift);
  // Deterministic.
  EXPECT_EQ(simulate_scan(unit_sphere(), s).points, scan.points);
}

}  // namespace
}  // namespace lsr
