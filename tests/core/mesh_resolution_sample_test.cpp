// SPDX-License-Identifier: BSD-3-Clause
/// @file mesh_resolution_sample_test.cpp
/// @brief The fits' sample: every point where the mesh raised no scale, the density of the
/// raised scale elsewhere, the same choice on every call.
#include "fit/mesh_resolution_sample.h"

#include <gtest/gtest.h>

#include <cmath>

namespace lsr {
namespace {

TEST(MeshResolutionSample, KeepsEveryPointWhereNoScaleWasRaised) {
  const std::vector<double> scale(1000, 0.01);
  const std::vector<Index> kept = mesh_resolution_sample<3>(scale, scale);
  ASSERT_EQ(kept.size(), scale.size());
  for (std::size_t i = 0; i < kept.size(); ++i) EXPECT_EQ(kept[i], Index(i));
}

// Scales raised 4x: a surface (3D) keeps 1 / 16 of its points, a curve (2D) 1 / 4. The count
// is binomial: within 5 standard deviations of n p (a false alarm once in 3.5 million runs,
// were the hash random; it is fixed, so the test is deterministic).
TEST(MeshResolutionSample, KeepsTheDensityOfTheRaisedScale) {
  const std::size_t n = 100000;
  const std::vector<double> sampling(n, 0.001), raised(n, 0.004);
  const auto expect_share = [&](std::size_t kept, double p) {
    EXPECT_NEAR(double(kept), double(n) * p, 5.0 * std::sqrt(double(n) * p * (1.0 - p)));
  };
  expect_share(mesh_resolution_sample<3>(sampling, raised).size(), 1.0 / 16.0);
  expect_share(mesh_resolution_sample<2>(sampling, raised).size(), 1.0 / 4.0);
  EXPECT_EQ(mesh_resolution_sample<3>(sampling, raised), mesh_resolution_sample<3>(sampling, raised));
}

// Spread evenly: each tenth of the indices (a patch, the points being in Z-order) keeps its
// share, within 5 standard deviations of its own binomial count.
TEST(MeshResolutionSample, SpreadsTheKeptPointsEvenly) {
  const std::size_t n = 100000, parts = 10;
  const std::vector<double> sampling(n, 0.001), raised(n, 0.004);
  const std::vector<Index> kept = mesh_resolution_sample<3>(sampling, raised);
  std::vector<double> count(parts, 0.0);
  for (Index i : kept) count[std::size_t(i) * parts / n] += 1.0;
  const double p = 1.0 / 16.0, m = double(n / parts);
  for (double c : count) EXPECT_NEAR(c, m * p, 5.0 * std::sqrt(m * p * (1.0 - p)));
}

}  // namespace
}  // namespace lsr
