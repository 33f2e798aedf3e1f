// SPDX-License-Identifier: BSD-3-Clause
/// @file height_field_fit_test.cpp
/// @brief The quadric / cubic choice of a height-field fit: what noise alone removes matches
/// its prediction, noise seldom buys the cubic terms, a cubic above the noise keeps them and is
/// recovered within its standard errors.
#include "fit/height_field_fit.h"

#include <Eigen/LU>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace lsr {
namespace {

constexpr int kPoints = 160;  // a wide fit's neighbours (quadric_implicit.h)

// kPoints uniform in the unit disc with Wendland weights (1 - r^2 / 1.44)^2 as the fits use,
// heights z(t) + N(0, sigma).
template <class Height>
HeightFieldEquations<3, kCubicTerms> disc_fit(std::mt19937& rng, double sigma, const Height& z, bool equal_weights = false) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::normal_distribution<double> noise(0.0, sigma);
  HeightFieldEquations<3, kCubicTerms> e;
  for (int i = 0; i < kPoints;) {
    const Eigen::Vector2d t(unit(rng), unit(rng));
    if (t.squaredNorm() > 1.0) continue;
    const double w = equal_weights ? 1.0 : std::pow(1.0 - t.squaredNorm() / 1.44, 2);
    e.add(w, height_monomials<3, kCubicTerms>(t), z(t) + noise(rng));
    ++i;
  }
  return e;
}

TEST(HeightFieldFit, WithEqualWeightsFourCubicTermsTakeFourSigmaSquaredFromNoise) {
  std::mt19937 rng(1);
  const CubicSelection s = select_cubic(disc_fit(rng, 1.0, [](const Eigen::Vector2d&) { return 0.0; }, true), 1.0);
  EXPECT_NEAR(s.by_noise, 4.0, 1e-9);
  EXPECT_NEAR(s.points, kPoints, 1e-9);
}

// On a noisy quadric the cubic terms remove, in the mean, by_noise sigma^2 (a weighted
// chi-square): checked within 4 standard errors of 2000 draws. Schwarz's threshold, ln(n)
// times that mean, lies past the chi-square's tail: with 4 equal-weight terms and n = 60,
// P(chi2_4 > 4 ln 60 = 16.4) = 0.25%; allowed here: 1%.
TEST(HeightFieldFit, NoiseRemovesWhatItsMeanPredictsAndSeldomBuysTheCubic) {
  std::mt19937 rng(2);
  const double sigma = 0.01;
  const auto quadric = [](const Eigen::Vector2d& t) { return 0.3 * t.x() - 0.2 * t.y() + 0.5 * t.x() * t.x() - t.x() * t.y(); };
  const int draws = 2000;
  double sum = 0.0, sum2 = 0.0;
  int kept = 0;
  for (int d = 0; d < draws; ++d) {
    const CubicSelection s = select_cubic(disc_fit(rng, sigma, quadric), sigma);
    const double ratio = s.removed / (sigma * sigma * s.by_noise);
    sum += ratio;
    sum2 += ratio * ratio;
    kept += s.cubic_kept;
  }
  const double mean = sum / draws, error = std::sqrt((sum2 / draws - mean * mean) / draws);
  EXPECT_NEAR(mean, 1.0, 4.0 * error);
  EXPECT_LE(kept, draws / 100);
}

// A cubic whose terms lie well above the noise over the disc is kept, and its coefficients
// come out within 5 standard errors, sigma times the square roots of the diagonal of
// A^-1 B A^-1 (weighted least squares' covariance).
TEST(HeightFieldFit, ACubicAboveTheNoiseIsKeptAndRecovered) {
  std::mt19937 rng(3);
  const double sigma = 0.01;
  const Eigen::Vector4d c(0.6, -0.9, 0.3, 1.2);
  const auto cubic = [&](const Eigen::Vector2d& t) {
    return 0.1 + height_monomials<3, kCubicTerms>(t).tail<4>().dot(c);
  };
  const HeightFieldEquations<3, kCubicTerms> e = disc_fit(rng, sigma, cubic);
  const CubicSelection s = select_cubic(e, sigma);
  ASSERT_TRUE(s.cubic_kept);
  const Eigen::Matrix<double, kCubicTerms, kCubicTerms> inverse = e.ata.inverse();
  const Eigen::Matrix<double, kCubicTerms, kCubicTerms> covariance = sigma * sigma * inverse * e.ata2 * inverse;
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(s.cubic[k], c[k], 5.0 * std::sqrt(covariance(6 + k, 6 + k))) << k;
  EXPECT_NEAR(s.quadric[0], 0.1, 5.0 * std::sqrt(covariance(0, 0)));
}

}  // namespace
}  // namespace lsr
