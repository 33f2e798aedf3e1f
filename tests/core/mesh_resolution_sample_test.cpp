// SPDX-License-Identifier: BSD-3-Clause
/// @file mesh_resolution_sample_test.cpp
/// @brief The sample at the mesh's resolution: every point where the mesh raised no scale, the
/// density of the raised scale elsewhere (from the spacing, or on scan lines, whose spacing is
/// not their density, measured), the same choice on every call.
#include "sampling/mesh_resolution_sample.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace lsr {
namespace {

constexpr double kPi = 3.14159265358979323846;

// n i.i.d. points, uniform on the unit sphere (D = 3) or circle (D = 2).
template <int D>
Points<D> random_sphere(std::size_t n, unsigned seed) {
  std::mt19937 random(seed);
  std::normal_distribution<double> gauss;
  Points<D> p(n);
  for (auto& x : p) {
    for (int d = 0; d < D; ++d) x[d] = gauss(random);
    x.normalize();
  }
  return p;
}

// The kept count of n points with expected share p: binomial, plus the spread of the shares'
// mean (each share has coefficient of variation cv, and about k neighbouring points share
// their neighbours): within 5 standard deviations.
void expect_share(std::size_t kept, std::size_t n, double p, double cv, int k) {
  const double variance = double(n) * p * (1.0 - p) + double(k) * double(n) * std::pow(p * cv, 2);
  EXPECT_NEAR(double(kept), double(n) * p, 5.0 * std::sqrt(variance));
}

TEST(MeshResolutionSample, KeepsEveryPointWhereNoScaleWasRaised) {
  const NearestPointIndex<3> data(random_sphere<3>(1000, 1));
  const std::vector<double> scale(1000, 0.01);
  for (bool scan_lines : {false, true}) {
    const std::vector<Index> kept = mesh_resolution_sample<3>(data, scale, scale, scan_lines);
    ASSERT_EQ(kept.size(), scale.size());
    for (std::size_t i = 0; i < kept.size(); ++i) EXPECT_EQ(kept[i], Index(i));
  }
}

// From the spacing: scales raised 4x, a surface (3D) keeps 1 / 16 of its points, a curve (2D)
// 1 / 4. The count is binomial: within 5 standard deviations of n p (a false alarm once in 3.5
// million runs, were the hash random; it is fixed, so the test is deterministic).
TEST(MeshResolutionSample, KeepsTheDensityOfTheRaisedScaleFromTheSpacing) {
  const std::size_t n = 100000;
  const std::vector<double> sampling(n, 0.001), raised(n, 0.004);
  const NearestPointIndex<3> surface(random_sphere<3>(n, 5));
  const NearestPointIndex<2> curve(random_sphere<2>(n, 6));
  expect_share(mesh_resolution_sample<3>(surface, sampling, raised, false).size(), n, 1.0 / 16.0, 0.0, 0);
  expect_share(mesh_resolution_sample<2>(curve, sampling, raised, false).size(), n, 1.0 / 4.0, 0.0, 0);
}

// Measured (as on scan lines) on i.i.d. points of density rho: the share is the density of a
// sampling at the raised scale l, 6 / (pi rho l^2) on a surface, 1 / (rho l) on a curve, what
// the spacing gives on average. On the unit sphere a cap of chord radius r has area pi r^2
// exactly, so pi rho r_30^2 is Gamma(29) (the point and 29 others; coefficient of variation
// 1 / sqrt(29)); on the circle 2 rho r_10 is Gamma(9) up to the chord's 1e-9 (cv 1 / 3). l is
// set for a share of 1 / 16 and 1 / 4.
TEST(MeshResolutionSample, KeepsTheDensityOfTheRaisedScaleOnRandomSamples) {
  const std::size_t n = 100000;
  {
    const NearestPointIndex<3> data(random_sphere<3>(n, 2));
    const double rho = double(n) / (4.0 * kPi), l = std::sqrt(6.0 * 16.0 / (kPi * rho));
    const std::vector<double> sampling(n, 0.5 * l), raised(n, l);
    const std::vector<Index> kept = mesh_resolution_sample<3>(data, sampling, raised, true);
    expect_share(kept.size(), n, 1.0 / 16.0, 1.0 / std::sqrt(29.0), 30);
    EXPECT_EQ(kept, mesh_resolution_sample<3>(data, sampling, raised, true));
  }
  {
    const NearestPointIndex<2> data(random_sphere<2>(n, 3));
    const double rho = double(n) / (2.0 * kPi), l = 4.0 / rho;
    const std::vector<double> sampling(n, 0.5 * l), raised(n, l);
    expect_share(mesh_resolution_sample<2>(data, sampling, raised, true).size(), n, 1.0 / 4.0, 1.0 / 3.0, 10);
  }
}

// Scan lines: points a apart along lines g = 8 a apart, in a plane, their spacing raised to
// 0.9 l by the gap between the lines (the spacing's share would keep 81%). Their density is
// 1 / (a g): the share is 6 a g / (pi l^2), here 1 / 16. The 30 nearest lie on 3 lines, each
// holding its chord / a points, up to 2 more or less at its ends: the disc's count, 30, is
// within 6 of its area times the density, so the share within 20%; beyond that, binomial (5
// standard deviations). Points within 4 g of the border are not counted.
TEST(MeshResolutionSample, KeepsTheDensityOfTheRaisedScaleOnScanLines) {
  const double a = 1.0, g = 8.0;
  const int lines = 60, along = 1000;
  Points<3> p;
  for (int j = 0; j < lines; ++j) {
    for (int i = 0; i < along; ++i) p.push_back(Vec<3>(i * a, j * g, 0.0));
  }
  const NearestPointIndex<3> data(p);
  const double share = 1.0 / 16.0, l = std::sqrt(6.0 * a * g / (kPi * share));
  const std::vector<double> sampling(p.size(), 0.9 * l), raised(p.size(), l);
  std::vector<char> kept(p.size(), 0);
  for (Index i : mesh_resolution_sample<3>(data, sampling, raised, true)) kept[std::size_t(i)] = 1;
  std::size_t inner = 0, inner_kept = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec<3>& x = p[i];
    if (x.x() < 4 * g || x.x() > (along - 1) * a - 4 * g || x.y() < 4 * g || x.y() > (lines - 1) * g - 4 * g) continue;
    ++inner;
    inner_kept += kept[i];
  }
  const double expected = double(inner) * share;
  const double binomial = 5.0 * std::sqrt(expected * (1.0 - share));
  EXPECT_GT(double(inner_kept), 0.8 * expected - binomial);
  EXPECT_LT(double(inner_kept), 1.2 * expected + binomial);
}

// Spread evenly: each tenth of the indices (a patch, the points being in Z-order) keeps its
// share, within 5 standard deviations of its own binomial count.
TEST(MeshResolutionSample, SpreadsTheKeptPointsEvenly) {
  const std::size_t n = 100000, parts = 10;
  Points<3> p = random_sphere<3>(n, 4);
  std::sort(p.begin(), p.end(), [](const Vec<3>& x, const Vec<3>& y) { return x.z() < y.z(); });  // tenths: zones
  const NearestPointIndex<3> data(p);
  const double rho = double(n) / (4.0 * kPi), l = std::sqrt(6.0 * 16.0 / (kPi * rho));
  const std::vector<double> sampling(n, 0.5 * l), raised(n, l);
  std::vector<double> count(parts, 0.0);
  for (Index i : mesh_resolution_sample<3>(data, sampling, raised, true)) count[std::size_t(i) * parts / n] += 1.0;
  for (double c : count) expect_share(std::size_t(c), n / parts, 1.0 / 16.0, 1.0 / std::sqrt(29.0), 30);
}

}  // namespace
}  // namespace lsr
