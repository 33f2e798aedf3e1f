// SPDX-License-Identifier: BSD-3-Clause
/// @file tangent_discs_test.cpp
/// @brief The discs span a hole, follow a curved surface across it, and leave the gap between
/// two close sheets open.
#include "lsrecon/testdata/shape_corpus.h"
#include "start/tangent_discs.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace lsr {
namespace {

// Random points of the square [0.2, 0.8]^2 at height z, without the disc of radius a at
// (0.5, 0.5).
Points<3> holey_plane(double z, double a, int n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.2, 0.8);
  Points<3> p;
  while (int(p.size()) < n) {
    const Vec<3> x(u(rng), u(rng), z);
    if (std::hypot(x.x() - 0.5, x.y() - 0.5) > a) p.push_back(x);
  }
  return p;
}

std::vector<double> distances(const NearestPointIndex<3>& data, const Points<3>& queries) {
  std::vector<double> d;
  data.query(queries, d);
  return d;
}

TEST(TangentDiscs, SpanAHoleNarrowerThanTheirRadiusAndNoWider) {
  const double a = 0.05;  // about 3 spacings of 4000 points on 0.36
  const NearestPointIndex<3> data(holey_plane(0.5, a, 4000, 1));
  const LocalSampling<3> s = estimate_local_sampling(data, 0, HeightFieldsAt::all);
  const Points<3> q = {Vec<3>(0.5, 0.5, 0.5), Vec<3>(0.5, 0.5, 0.51), Vec<3>(0.52, 0.49, 0.48)};
  const std::vector<double> d = distances(data, q);
  const std::vector<double> cap(q.size(), 1.0);
  for (std::size_t i = 0; i < q.size(); ++i) ASSERT_GT(d[i], 0.5 * a) << i;  // the hole is empty
  // Radius 1.5 a: the rim's discs cover the hole; a plane is fitted exactly (to rounding).
  const std::vector<double> covered = tangent_disc_distance(data, s, 1.5 * a, q, d, cap);
  for (std::size_t i = 0; i < q.size(); ++i) EXPECT_NEAR(covered[i], std::abs(q[i].z() - 0.5), 1e-9) << i;
  // Radius a / 2: the hole's middle stays at least a / 2 from every disc.
  const std::vector<double> open = tangent_disc_distance(data, s, 0.5 * a, q, d, cap);
  EXPECT_GE(open[0], 0.5 * a - 0.02 * a);
}

TEST(TangentDiscs, RimsRingAHoleAndAreRareInsideASurface) {
  // 32 neighbours of 4000 points on 0.36 reach r32 = sqrt(32 / (pi 4000 / 0.36)) = 0.030. A rim
  // point sees 120 degrees free among its 31 nearest: a point within about a spacing of the
  // hole's edge (the hole subtends more), a point inside with probability about
  // 31 (2/3)^30 = 1.6e-4 (the largest of 31 random gaps): 0.6 of 4000, 3 of 20000 expected.
  const double a = 0.05, r32 = 0.030;
  const Points<3> p = holey_plane(0.5, a, 4000, 1);
  const LocalSampling<3> s = estimate_local_sampling(NearestPointIndex<3>(p), 0, HeightFieldsAt::rims);
  std::vector<int> sectors(6, 0);
  int inside = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!s.rim[i]) continue;
    const double from_hole = std::hypot(p[i].x() - 0.5, p[i].y() - 0.5) - a;
    const double from_border = std::min({p[i].x() - 0.2, 0.8 - p[i].x(), p[i].y() - 0.2, 0.8 - p[i].y()});
    if (from_hole < r32) ++sectors[std::size_t(3.0 * (std::atan2(p[i].y() - 0.5, p[i].x() - 0.5) / M_PI + 1.0)) % 6];
    if (std::min(from_hole, from_border) > r32) ++inside;
  }
  // Every 60 degrees of the rim (5.4 spacings of arc) has a rim point, so the hole's middle lies
  // within a of one: discs of radius >= a cover it. (Every 30 degrees held on 7 of 12 draws of
  // this plane, every 60 on 12 of 12.)
  for (int k = 0; k < 6; ++k) EXPECT_GE(sectors[std::size_t(k)], 1) << "no rim point in sector " << k;
  EXPECT_LE(inside, 4);  // P(Poisson(0.6) > 4) = 5e-4
  // Closed: a random sphere has no rim but the rare wide gaps.
  const Points<3> sphere = sample_test_shape(make_test_shape("sphere"), 20000).points;
  const LocalSampling<3> closed = estimate_local_sampling(NearestPointIndex<3>(sphere), 0, HeightFieldsAt::rims);
  EXPECT_LE(std::count(closed.rim.begin(), closed.rim.end(), 1), 12);  // P(Poisson(3.2) > 12) = 3e-5
}

TEST(TangentDiscs, RimDiscsAloneSpanAHole) {
  const double a = 0.05;
  const NearestPointIndex<3> data(holey_plane(0.5, a, 4000, 1));
  const LocalSampling<3> s = estimate_local_sampling(data, 0, HeightFieldsAt::rims);
  const Points<3> q = {Vec<3>(0.5, 0.5, 0.5), Vec<3>(0.5, 0.5, 0.51), Vec<3>(0.52, 0.49, 0.48)};
  const std::vector<double> d = distances(data, q);
  const std::vector<double> cap(q.size(), 1.0);
  const std::vector<double> covered = tangent_disc_distance(data, s, 1.5 * a, q, d, cap, 0, true);
  for (std::size_t i = 0; i < q.size(); ++i) EXPECT_NEAR(covered[i], std::abs(q[i].z() - 0.5), 1e-9) << i;
  const std::vector<double> open = tangent_disc_distance(data, s, 0.5 * a, q, d, cap, 0, true);
  EXPECT_GE(open[0], 0.5 * a - 0.02 * a);
}

TEST(TangentDiscs, FollowTheCurvatureAcrossAHole) {
  // A cap of angular radius 0.15 missing from a random unit sphere: flat discs of radius 0.2
  // would pass 0.15^2 / 2 ~ 0.011 above its pole; bent ones by the quartic term only.
  const TestShape sphere = make_test_shape("sphere");
  Points<3> p;
  for (const Vec<3>& x : sample_test_shape(sphere, 20000).points) {
    if (std::acos(std::clamp(x.z(), -1.0, 1.0)) > 0.15) p.push_back(x);
  }
  const NearestPointIndex<3> data(p);
  const LocalSampling<3> s = estimate_local_sampling(data, 0, HeightFieldsAt::all);
  const Points<3> pole = {Vec<3>(0.0, 0.0, 1.0)};
  const std::vector<double> d = distances(data, pole);
  ASSERT_GT(d[0], 0.14);
  const std::vector<double> bent = tangent_disc_distance(data, s, 0.2, pole, d, {1.0});
  // The quadric of a rim point extrapolated 0.15: h error ~ x^4 / (8 R^3) = 6e-5, plus its fit error.
  EXPECT_LT(bent[0], 2e-3);
}

TEST(TangentDiscs, LeaveTheGapBetweenCloseSheetsOpen) {
  // Two parallel sheets 0.03 apart, farther than a neighbourhood's radius (16 of 3000 points on
  // 0.36: 0.025), so that each point's height field is its own sheet's: however large the
  // discs, the middle stays 0.015 from both.
  Points<3> p = holey_plane(0.5, 0.0, 3000, 2);
  const Points<3> upper = holey_plane(0.53, 0.0, 3000, 3);
  p.insert(p.end(), upper.begin(), upper.end());
  const NearestPointIndex<3> data(p);
  const LocalSampling<3> s = estimate_local_sampling(data, 0, HeightFieldsAt::all);
  const Points<3> middle = {Vec<3>(0.5, 0.5, 0.515), Vec<3>(0.3, 0.6, 0.515)};
  const std::vector<double> d = distances(data, middle);
  const std::vector<double> discs = tangent_disc_distance(data, s, 0.2, middle, d, {1.0, 1.0});
  for (std::size_t i = 0; i < middle.size(); ++i) EXPECT_NEAR(discs[i], 0.015, 1e-6) << i;
}

TEST(TangentDiscs, ShapeStopsAtTheRadiusOfCurvatureAlongEachPrincipalDirection) {
  // A cylinder of radius 0.05 along (1, 1) / sqrt 2: h = -(x . e)^2 / (2 0.05) across the axis e.
  HeightField<3> f;
  const Eigen::Vector2d axis = Eigen::Vector2d(1.0, 1.0).normalized(), across(-axis.y(), axis.x());
  const Eigen::Matrix2d a = -20.0 * across * across.transpose();
  f.coefficients = {0.0, 0.0, 0.0, a(0, 0), a(0, 1), a(1, 1)};
  const Eigen::Matrix2d s = disc_shape(f, 0.1);
  EXPECT_NEAR((s * axis).norm(), 1.0 / 0.1, 1e-9);     // flat: the full radius
  EXPECT_NEAR((s * across).norm(), 1.0 / 0.05, 1e-9);  // round: the radius of curvature
  HeightField<2> flat;
  EXPECT_NEAR(disc_shape(flat, 0.1)(0, 0), 10.0, 1e-12);
}

}  // namespace
}  // namespace lsr
