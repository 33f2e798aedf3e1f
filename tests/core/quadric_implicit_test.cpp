// SPDX-License-Identifier: BSD-3-Clause
/// @file quadric_implicit_test.cpp
/// @brief The blended quadric fit is exact on planes and quadrics of the tangent frame, and its
/// error on a sphere is the next term of the height function, r^4 / (8 R^3); it does not
/// round a crease over the whole neighbourhood.
#include "fit/quadric_implicit.h"
#include "lsrecon/testdata/shape_corpus.h"
#include "sampling/local_sampling.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace lsr {
namespace {

TEST(QuadricImplicit, PlaneIsExact) {
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Points<3> p;
  for (int i = 0; i < 3000; ++i) p.emplace_back(unit(rng), unit(rng), 0.4);
  const NearestPointIndex<3> index(p);
  const QuadricImplicit<3> f(index, Points<3>(p.size(), Vec<3>::UnitZ()), std::vector<double>(p.size(), 0.03));
  std::vector<double> value;
  Points<3> normal;
  f.evaluate({Vec<3>(0.5, 0.5, 0.45), Vec<3>(0.3, 0.6, 0.38)}, value, &normal);
  EXPECT_NEAR(value[0], 0.05, 1e-9);
  EXPECT_NEAR(value[1], -0.02, 1e-9);
  EXPECT_NEAR(normal[0].z(), 1.0, 1e-9);
}

TEST(QuadricImplicit, SphereErrorIsTheFourthOrderTermOfItsNeighbourhood) {
  const double R = 1.0;
  const int n = 20000;
  const Points<3> p = sample_implicit_surface([R](const Vec<3>& x) { return x.norm() - R; }, -1.1 * Vec<3>::Ones(),
                                              1.1 * Vec<3>::Ones(), n, 9);
  const NearestPointIndex<3> index(p);
  const LocalSampling<3> s = estimate_local_sampling(index);
  Points<3> normals;
  for (const auto& x : p) normals.push_back(x.normalized());
  const QuadricImplicit<3> f(index, normals, s.spacing);
  // A fit's neighbourhood holds 30 points, radius about r with pi r^2 rho = 30; 30 random
  // points lie within 2 r with overwhelming probability (a disc of radius 2 r holds 120 on
  // average), and a blended fit is evaluated within that radius of its centre. The height
  // function's first term a quadric cannot follow is t^4 / (8 R^3).
  const double r = std::sqrt(30.0 / (kPi * n / (4 * kPi * R * R)));
  const double bound = std::pow(2 * r, 4) / (8 * R * R * R);
  Points<3> q;
  std::vector<double> truth;
  for (int i = 0; i < 2000; i += 7) {
    const double offset = 0.02 * ((i % 5) - 2);
    q.push_back(p[i] * (1 + offset / R));
    truth.push_back(offset);
  }
  std::vector<double> value;
  f.evaluate(q, value);
  for (std::size_t k = 0; k < q.size(); ++k) EXPECT_NEAR(value[k], truth[k], bound + 1e-3 * std::abs(truth[k]));
  Points<3> moved = q;
  f.project(moved);
  for (const auto& x : moved) EXPECT_NEAR(x.norm(), R, bound);
}

// The largest |F| on the ridge of a roof of random points, whose facets' normals differ by
// `angle`, with PCA normals as the reconstruction gives them.
double ridge_error(double angle) {
  const double slope = std::tan(angle / 2);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Points<3> p;
  for (int i = 0; i < 10000; ++i) {
    const double x = unit(rng), y = unit(rng);
    p.emplace_back(x, y, 0.5 - slope * std::abs(x - 0.5));
  }
  const NearestPointIndex<3> index(p);
  const LocalSampling<3> s = estimate_local_sampling(index);
  Points<3> normals = s.normals;
  for (auto& n : normals) n *= n.z() < 0.0 ? -1.0 : 1.0;
  const QuadricImplicit<3> f(index, normals, s.spacing);
  Points<3> ridge;
  for (int i = 0; i < 100; ++i) ridge.emplace_back(0.5, 0.3 + 0.004 * i, 0.5);
  std::vector<double> value;
  f.evaluate(ridge, value);
  double worst = 0.0;
  for (double v : value) worst = std::max(worst, std::abs(v));
  return worst;
}

// A fit whose neighbourhood straddles a crease rounds it by a fraction of the neighbourhood's
// radius times tan(angle / 2): 3.3x more at 60 degrees than at 20 (measured without the
// normals' weights: 0.36 and 0.11 spacings). Fits that keep to their own side leave only the
// PCA normals' blur at the crease, which does not grow like that.
TEST(QuadricImplicit, CreaseIsNotRoundedOverTheNeighbourhood) {
  const double at20 = ridge_error(20 * kPi / 180), at60 = ridge_error(60 * kPi / 180);
  EXPECT_LT(at60, 1.5 * at20);
}

// A bump one spacing wide and two tall, a exp(-r^2 / 2 w^2), on a plane of 20,000 random points
// with noise sigma = 0.15 spacings, given to the fit: it widens every fit to 160 points (a
// reach of 5 w), which would round the bump off. The fits that miss their own nearest by more
// than the noise are narrowed, so on the bump F stays within the noise: a least-squares height
// misses a fitted point by at most sigma in deviation (0.8 sigma in mean absolute value), where
// a rounded bump misses by a fraction of its height, 13 sigma. On the flat part the fits keep
// their width: a 160-point fit's height deviates by about sigma sqrt(6 / 160) = 0.19 sigma
// (mean absolute 0.15 sigma), a 30-point one's by 0.45 sigma (0.36).
TEST(QuadricImplicit, ANoisyFitNarrowsWhereItsWidthWouldRoundABumpOff) {
  const double w = 0.01, a = 2 * w, sigma = 0.0015;
  std::mt19937 rng(6);
  std::uniform_real_distribution<double> unit(-0.5, 0.5);
  std::normal_distribution<double> gauss(0.0, sigma);
  const auto height = [&](double x, double y) { return a * std::exp(-(x * x + y * y) / (2 * w * w)); };
  Points<3> p, normals, bump, flat;
  for (int i = 0; i < 20000; ++i) {
    const double x = unit(rng), y = unit(rng), h = height(x, y);
    normals.push_back(Vec<3>(x * h / (w * w), y * h / (w * w), 1.0).normalized());
    p.push_back(Vec<3>(x, y, h) + gauss(rng) * normals.back());
    const double r = std::hypot(x, y);
    if (r < 2 * w) bump.emplace_back(x, y, h);
    if (r > 0.15 && std::max(std::abs(x), std::abs(y)) < 0.4) flat.emplace_back(x, y, h);
  }
  const NearestPointIndex<3> index(p);
  const LocalSampling<3> s = estimate_local_sampling(index);
  const QuadricImplicit<3> f(index, normals, s.spacing, std::vector<double>(p.size(), sigma));
  const auto mean_abs = [&f](const Points<3>& q) {
    std::vector<double> value;
    f.evaluate(q, value);
    double sum = 0.0;
    for (double v : value) sum += std::abs(v);
    return sum / double(value.size());
  };
  EXPECT_LT(mean_abs(bump), sigma);
  EXPECT_LT(mean_abs(flat), 0.25 * sigma);
}

TEST(QuadricImplicit, CircleIn2D) {
  const int n = 2000;
  Points<2> p, normals;
  for (int i = 0; i < n; ++i) {
    const double t = 2 * kPi * (i + 0.37 * std::sin(i)) / n;
    normals.emplace_back(std::cos(t), std::sin(t));
    p.push_back(0.3 * normals.back());
  }
  const NearestPointIndex<2> index(p);
  const LocalSampling<2> s = estimate_local_sampling(index);
  const QuadricImplicit<2> f(index, normals, s.spacing);
  Points<2> q{Vec<2>(0.31, 0.0), Vec<2>(0.0, -0.29)};
  f.project(q);
  // Ten points span r = 5 spacings of 0.3 * 2 pi / n; as on the sphere, the bound is the
  // quartic term over twice that radius.
  const double r = 5 * 0.3 * 2 * kPi / n;
  const double bound = std::pow(2 * r, 4) / (8 * 0.3 * 0.3 * 0.3);
  EXPECT_NEAR(q[0].norm(), 0.3, bound);
  EXPECT_NEAR(q[1].norm(), 0.3, bound);
}

}  // namespace
}  // namespace lsr
