// SPDX-License-Identifier: BSD-3-Clause
/// @file rim_normals_test.cpp
/// @brief Normals past the last scan row of a sphere and past the end of a circle's arc come
/// from the quadric through the data, within the error of its neglected quartic term.
#include "fit/rim_normals.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace lsr {
namespace {

constexpr double kDegree = 3.14159265358979323846 / 180.0;

Vec<3> on_unit_sphere(double polar, double azimuth) {
  return Vec<3>(std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth), std::cos(polar));
}

// A neighbourhood within rho of the query sees the circle or sphere of radius 1 as the height
// field 1 - sqrt(1 - t^2) = t^2 / 2 + t^4 / 8 + ...: the fitted quadric misses the quartic,
// whose slope t^3 / 2 and the quadric's share of it (about rho^2 t / 4) leave an error below
// 4 rho^3 in the slope (an angle in radians) anywhere within rho.
double quartic_bound(const NearestPointIndex<3>& data, const Vec<3>& q, int k) {
  std::vector<double> d;
  for (const auto& p : data.points()) d.push_back((p - q).norm());
  std::nth_element(d.begin(), d.begin() + (k - 1), d.end());
  return 4.0 * std::pow(d[std::size_t(k - 1)], 3);
}

TEST(RimNormals, PastTheLastScanRowOfASphere) {
  // Rows every 1.5 degrees of polar angle from 20 to 50 degrees, each sampled every 0.3 degrees
  // of azimuth over 80 degrees: 5-10x denser along the rows than across them.
  Points<3> p;
  for (int row = 0; row <= 20; ++row) {
    for (int a = -133; a <= 133; ++a) p.push_back(on_unit_sphere((20.0 + 1.5 * row) * kDegree, 0.3 * a * kDegree));
  }
  const NearestPointIndex<3> data(p);
  Points<3> queries;
  for (int a = -4; a <= 4; ++a) queries.push_back(on_unit_sphere(53.0 * kDegree, 5.0 * a * kDegree));
  const Points<3> n = rim_normals(data, queries, 1);
  for (std::size_t i = 0; i < queries.size(); ++i) {
    const double bound = quartic_bound(data, queries[i], kRimNormalNeighbours<3>);
    double nearest = 0.0;  // the normal of the nearest point is farther off than the bound
    data.nearest(queries[i], nearest);
    ASSERT_LT(bound, 2.0 * std::asin(nearest / 2.0));
    EXPECT_NEAR(n[i].norm(), 1.0, 1e-12);
    EXPECT_LT(std::acos(std::min(1.0, std::abs(n[i].dot(queries[i])))), bound) << i;
  }
}

TEST(RimNormals, PastTheEndOfACirclesArc) {
  Points<2> p;
  for (int a = 0; a <= 240; ++a) p.push_back(Vec<2>(std::cos(0.25 * a * kDegree), std::sin(0.25 * a * kDegree)));
  const NearestPointIndex<2> data(p);
  const Points<2> queries{Vec<2>(std::cos(62 * kDegree), std::sin(62 * kDegree)), Vec<2>(std::cos(63 * kDegree), std::sin(63 * kDegree))};
  const Points<2> n = rim_normals(data, queries, 1);
  for (std::size_t i = 0; i < queries.size(); ++i) {
    std::vector<double> d;
    for (const auto& x : p) d.push_back((x - queries[i]).norm());
    std::nth_element(d.begin(), d.begin() + (kRimNormalNeighbours<2> - 1), d.end());
    const double bound = 4.0 * std::pow(d[std::size_t(kRimNormalNeighbours<2> - 1)], 3);
    ASSERT_LT(bound, 2.0 * std::asin(*std::min_element(d.begin(), d.end()) / 2.0));
    EXPECT_LT(std::acos(std::min(1.0, std::abs(n[i].dot(queries[i])))), bound) << i;
  }
}

TEST(RimNormals, TooFewPointsGiveNoNormal) {
  const NearestPointIndex<3> data(Points<3>{Vec<3>(0, 0, 0), Vec<3>(1, 0, 0), Vec<3>(0, 1, 0)});
  const Points<3> n = rim_normals(data, Points<3>{Vec<3>(0.5, 0.5, 0.1)}, 1);
  EXPECT_EQ(n[0], Vec<3>::Zero());
}

}  // namespace
}  // namespace lsr
