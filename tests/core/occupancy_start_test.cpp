// SPDX-License-Identifier: BSD-3-Clause
/// @file occupancy_start_test.cpp
/// @brief The occupancy start: the winding number in 2D and smoothed over the samples' patches,
/// normals turned outwards by the sign of their flux, and 1/2 - w negative exactly inside a
/// torus (its hole outside, where a start across the data leaves a membrane).
#include "start/occupancy_start.h"

#include "geometry/nearest_point_index.h"
#include "start/winding_number.h"

#include <gtest/gtest.h>

#include <cmath>

namespace lsr::detail {
namespace {

constexpr int kNeighbours = 16;

// n Fibonacci points of the unit sphere at c with z >= z_min; their outward normals.
void sphere(int n, const Vec<3>& c, double z_min, Points<3>& p, Points<3>& normals) {
  const double golden = kPi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - 2.0 * (i + 0.5) / n, s = std::sqrt(1.0 - z * z);
    if (z < z_min) continue;
    const Vec<3> u(s * std::cos(golden * i), s * std::sin(golden * i), z);
    p.push_back(c + u);
    normals.push_back(u);
  }
}

// n points of the unit circle from angle 0 to `arc`; their outward normals.
void circle(int n, double arc, Points<2>& p, Points<2>& normals) {
  for (int i = 0; i < n; ++i) {
    const double t = arc * (i + 0.5) / n;
    p.emplace_back(std::cos(t), std::sin(t));
    normals.emplace_back(std::cos(t), std::sin(t));
  }
}

// As the reconstruction compares w with 1/2, an error below 0.1 leaves a margin of 0.4 either
// side at the points tested (none nearer the samples than 0.3, where the sum is a quadrature of
// a smooth integrand with about 30 samples per unit length).
constexpr double kTolerance = 0.1;

// A closed circle: w = 1 inside, 0 outside (the 2D kernel n . (p - x) / (2 pi |p - x|^2)
// integrates the angle subtended); a half circle subtends exactly half of the directions from
// every point of the diameter closing it, so w = 1/2 there.
TEST(WindingNumber2D, OneInsideACircleAndAHalfOnTheChordOfAHalfCircle) {
  Points<2> p, n;
  circle(200, 2.0 * kPi, p, n);
  const WindingNumber<2> closed(p, n, std::vector<double>(p.size(), 2.0 * kPi / 200));
  for (const Vec<2>& x : {Vec<2>(0, 0), Vec<2>(0.5, -0.2), Vec<2>(-0.6, 0.1)}) EXPECT_NEAR(closed.at(x), 1.0, kTolerance) << x.transpose();
  for (const Vec<2>& x : {Vec<2>(1.5, 0), Vec<2>(0, -3), Vec<2>(-1.3, 0.4)}) EXPECT_NEAR(closed.at(x), 0.0, kTolerance) << x.transpose();
  Points<2> q, m;
  circle(100, kPi, q, m);
  const WindingNumber<2> half(q, m, std::vector<double>(q.size(), kPi / 100));
  for (const double x : {-0.6, 0.0, 0.6}) EXPECT_NEAR(half.at(Vec<2>(x, 0)), 0.5, kTolerance) << x;
}

// Smoothed over each sample's radius, w stays bounded at the samples themselves, where the bare
// dipoles blow up (a sample at distance e adds a / (4 pi e^2)): just inside and just outside the
// sphere it lies between its values far inside (1) and far outside (0), within the tolerance.
TEST(WindingNumber, SmoothedOverTheSamplesItIsBoundedAtThem) {
  Points<3> p, n;
  sphere(4000, Vec<3>::Zero(), -1.0, p, n);
  const double spacing = std::sqrt(4.0 * kPi / 4000);
  const std::vector<double> area(p.size(), 4.0 * kPi / 4000);
  const WindingNumber<3> bare(p, n, area), smooth(p, n, area, std::vector<double>(p.size(), spacing));
  for (const std::size_t i : {std::size_t(0), std::size_t(1234), std::size_t(2999)}) {
    for (const double side : {-1e-4, 1e-4}) {
      const Vec<3> x = p[i] + side * n[i];
      EXPECT_GT(smooth.at(x), -kTolerance) << i << " " << side;
      EXPECT_LT(smooth.at(x), 1.0 + kTolerance) << i << " " << side;
    }
    EXPECT_GT(std::abs(bare.at(p[i] - 1e-4 * n[i])), 10.0) << i;  // the singularity the radius removes
  }
  // Away from the samples both sum the same dipoles.
  EXPECT_NEAR(smooth.at(Vec<3>(0.2, 0.1, 0)), 1.0, kTolerance);
  EXPECT_NEAR(smooth.at(Vec<3>(0, 0, 2)), 0.0, kTolerance);
}

Points<3> outward(const Points<3>& p, const Points<3>& flipped) {
  const NearestPointIndex<3> index(p);
  LargeVector<Index> knn;
  index.query_k(p, kNeighbours, knn);
  return outward_normals<3>(p, flipped, std::vector<double>(p.size(), 1.0), knn, kNeighbours);
}

// Two spheres (two parts of the k-nearest graph), normals flipped at random, one sphere's all
// inwards: after outward_normals every normal points out of its own sphere. The propagation
// alone makes each part consistent; the flux's sign (3 times the volume) picks outwards.
TEST(OutwardNormals, FlippedNormalsOfTwoSpheresAllPointOut) {
  Points<3> p, n;
  sphere(2000, Vec<3>::Zero(), -1.0, p, n);
  sphere(2000, Vec<3>(4, 0, 0), -1.0, p, n);
  Points<3> flipped = n;
  for (std::size_t i = 0; i < flipped.size(); ++i) {
    if (i >= 2000 || i % 3 == 0) flipped[i] = -flipped[i];
  }
  const Points<3> out = outward(p, flipped);
  for (std::size_t i = 0; i < p.size(); ++i) ASSERT_GT(out[i].dot(n[i]), 0.0) << i;
}

// An open dome, all its normals turned inwards: the flux through it of x - c, c its centroid,
// is positive on its convex side (the cone over c), so they come out pointing away from the
// sphere's centre, the side a view of it sees.
TEST(OutwardNormals, AnOpenDomeTurnsToItsConvexSide) {
  Points<3> p, n;
  sphere(4000, Vec<3>::Zero(), 0.3, p, n);
  Points<3> flipped;
  for (const Vec<3>& v : n) flipped.push_back(-v);
  const Points<3> out = outward(p, flipped);
  for (std::size_t i = 0; i < p.size(); ++i) ASSERT_GT(out[i].dot(n[i]), 0.0) << i;
}

// Three nested spheres (radii 1, 0.6, 0.3: three parts of the k-nearest graph), normals flipped
// at random: the flux turns each outwards, and with the samples' radii the even-odd rule turns
// the middle one, inside one other, inwards: it bounds the cavity of a hollow ball whose core
// (inside two) is solid again.
TEST(OutwardNormals, NestedSpheresAlternate) {
  Points<3> p, n;
  for (const double r : {1.0, 0.6, 0.3}) {
    Points<3> q, m;
    sphere(int(4000 * r * r), Vec<3>::Zero(), -1.0, q, m);
    for (std::size_t i = 0; i < q.size(); ++i) {
      p.push_back(r * q[i]);
      n.push_back(i % 3 == 0 ? Vec<3>(-m[i]) : m[i]);
    }
  }
  const NearestPointIndex<3> index(p);
  LargeVector<Index> knn;
  index.query_k(p, kNeighbours, knn);
  std::vector<double> area(p.size()), radius(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    area[i] = 4.0 * kPi / 4000.0;  // every sphere was sampled at the same density
    radius[i] = std::sqrt(6.0 * area[i] / kPi);
  }
  const Points<3> out = outward_normals<3>(p, n, area, knn, kNeighbours, {}, radius);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double r = p[i].norm(), facing = out[i].dot(p[i]) / r;
    ASSERT_GT(r > 0.45 && r < 0.75 ? -facing : facing, 0.0) << i << " at radius " << r;
  }
}

// A wrong turn of the spanning tree flips a whole region: here the cap z > 0.5 of a sphere
// (a quarter of it). Probed two spacings either side, the normals at the cap's border point
// towards larger w, flip, and the region wears down pass by pass until every normal points out.
TEST(OutwardNormals, AFlippedCapIsMadeConsistent) {
  Points<3> p, n;
  sphere(4000, Vec<3>::Zero(), -1.0, p, n);
  Points<3> out = n;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p[i].z() > 0.5) out[i] = -out[i];
  }
  const double area = 4.0 * kPi / 4000;
  const NearestPointIndex<3> index(p);
  LargeVector<Index> knn;
  index.query_k(p, kNeighbours, knn);
  make_consistent<3>(p, out, std::vector<double>(p.size(), area), std::vector<double>(p.size(), std::sqrt(6.0 * area / kPi)), knn,
                     kNeighbours, 1);
  for (std::size_t i = 0; i < p.size(); ++i) ASSERT_GT(out[i].dot(n[i]), 0.0) << i;
}

// A torus (R = 1, r = 0.4) sampled with unoriented normals: 1/2 - w is about -1/2 on the tube's
// core circle and about +1/2 at the hole's centre and beyond the torus, above and below the
// hole: the sign a start across the data lacks there, where two sheets may span the hole.
TEST(OccupancyStart, NegativeExactlyInsideATorus) {
  Points<3> p, n;
  const int around = 160, along = 64;
  for (int i = 0; i < around; ++i) {
    for (int j = 0; j < along; ++j) {
      const double a = 2.0 * kPi * (i + 0.5 * (j % 2)) / around, b = 2.0 * kPi * j / along;
      const Vec<3> radial(std::cos(a), std::sin(a), 0.0);
      const Vec<3> normal = std::cos(b) * radial + std::sin(b) * Vec<3>::UnitZ();
      p.push_back(radial + 0.4 * normal);
      n.push_back((i + j) % 2 == 0 ? normal : Vec<3>(-normal));
    }
  }
  const Points<3> inside = {Vec<3>(1, 0, 0), Vec<3>(0, -1, 0), Vec<3>(-0.7, 0.7, 0.1)};
  const Points<3> outside = {Vec<3>(0, 0, 0), Vec<3>(0, 0, 0.3), Vec<3>(0.3, 0.2, -0.3), Vec<3>(2, 0, 0), Vec<3>(0, 0, 1)};
  Points<3> at = inside;
  at.insert(at.end(), outside.begin(), outside.end());
  const Eigen::VectorXd u = occupancy_start<3>(at, NearestPointIndex<3>(p), n, {}, std::vector<double>(p.size(), 0.0), 1);
  for (std::size_t i = 0; i < inside.size(); ++i) EXPECT_NEAR(u[Eigen::Index(i)], -0.5, kTolerance) << at[i].transpose();
  for (std::size_t i = inside.size(); i < at.size(); ++i) EXPECT_NEAR(u[Eigen::Index(i)], 0.5, kTolerance) << at[i].transpose();
}

// A sphere sampled four times as densely above its equator as below (a thinned sample, or
// overlapping views on one side): each sample stands for the area its own neighbourhood's
// density gives, so w is 1 at the centre (-1/2 for the start), 0 outside. With one area for
// all, the centre would read 4/5 or 2 of the sphere's area.
TEST(OccupancyStart, AreasFollowTheSamplesDensity) {
  Points<3> p, n, q, m;
  sphere(16000, Vec<3>::Zero(), 0.0, p, n);
  sphere(4000, Vec<3>::Zero(), -1.0, q, m);
  for (std::size_t i = 0; i < q.size(); ++i) {
    if (q[i].z() >= 0.0) continue;
    p.push_back(q[i]);
    n.push_back(-m[i]);
  }
  const Points<3> at = {Vec<3>::Zero(), Vec<3>(0.3, -0.2, -0.4), Vec<3>(0, 0, 2), Vec<3>(1.5, 0, -0.5)};
  const Eigen::VectorXd u = occupancy_start<3>(at, NearestPointIndex<3>(p), n, {}, std::vector<double>(p.size(), 0.0), 1);
  EXPECT_NEAR(u[0], -0.5, kTolerance);
  EXPECT_NEAR(u[1], -0.5, kTolerance);
  EXPECT_NEAR(u[2], 0.5, kTolerance);
  EXPECT_NEAR(u[3], 0.5, kTolerance);
}

}  // namespace
}  // namespace lsr::detail
