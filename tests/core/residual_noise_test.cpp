// SPDX-License-Identifier: BSD-3-Clause
/// @file residual_noise_test.cpp
/// @brief The residual noise reads the noise of a flat sheet, and not the bend of a clean,
/// tightly curved sphere, which PCA's thickness counts as noise.
#include "sampling/residual_noise.h"

#include "sampling/local_sampling.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace lsr {
namespace {

TEST(ResidualNoise, ANoisySheetReadsItsDeviationTimesTheCalibration) {
  // 4000 random points of [0.2, 0.8]^2 (spacing about sqrt(6 / (pi rho)) = 0.0207), Gaussian
  // heights of deviation sigma = 0.3 spacings. Each point's deviation has 24 degrees of freedom
  // (30 neighbours, 6 parameters): the median of sqrt(chi2_24 / 24) is 0.986, and the median
  // over 4000 points is within 1% of it; 5% covers both. A residual not corrected for the
  // quadric's parameters (sqrt(24 / 30) = 0.89) or an uncalibrated one would not pass.
  const double sigma = 0.3 * 0.0207;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.2, 0.8);
  std::normal_distribution<double> g(0.0, sigma);
  Points<3> p;
  for (int i = 0; i < 4000; ++i) p.emplace_back(u(rng), u(rng), 0.5 + g(rng));
  const NearestPointIndex<3> data(p);
  const std::vector<double> noise = residual_noise(data, Points<3>(p.size(), Vec<3>::UnitZ()), 30);
  EXPECT_NEAR(median(noise) / (0.986 * std::sqrt(13.0 / 16.0) * sigma), 1.0, 0.05);
}

TEST(ResidualNoise, ATightlyCurvedCleanSphereReadsNoNoise) {
  // 800 random points of a sphere of radius R = 0.3: spacing s = R sqrt(24 / 800) = 0.17 R.
  // PCA's thickness over the 16 nearest (radius r ~ 1.58 s) reads the sagitta's spread,
  // r^2 / (4 sqrt(3) R) ~ 0.06 s, as noise, above the 5% of s at which the fits widen; a quadric
  // leaves the quartic term, at most rho^4 / (8 R^3) ~ 0.015 s at the 30th neighbour (rho ~
  // 2.2 s), whose deviation is a fraction of that.
  std::mt19937_64 rng(5);
  std::normal_distribution<double> g(0.0, 1.0);
  Points<3> p, n;
  for (int i = 0; i < 800; ++i) {
    const Vec<3> d = Vec<3>(g(rng), g(rng), g(rng)).normalized();
    p.push_back(Vec<3>::Constant(0.5) + 0.3 * d);
    n.push_back(d);
  }
  const double s = 0.3 * std::sqrt(24.0 / 800.0);
  const NearestPointIndex<3> data(p);
  const LocalSampling<3> pca = estimate_local_sampling(data);
  EXPECT_GT(median(pca.noise), 0.05 * s);
  EXPECT_LT(median(residual_noise(data, n, 30)), 0.015 * s);
}

}  // namespace
}  // namespace lsr
