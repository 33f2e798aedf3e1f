// SPDX-License-Identifier: BSD-3-Clause
/// @file two_sided_attraction_test.cpp
/// @brief Starts that cross the data (paper figure 8 and its 3D analogue): with two-sided
/// attraction the front comes onto the data from both sides and converges to the right shape;
/// the one-sided term alone cannot.
#include "lsrecon/core/level_set_reconstruction.h"
#include "lsrecon/testdata/shape_corpus.h"
#include "surface/surface_topology.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace lsr {
namespace {

// A unit circle sampled with one random point per arc of equal length (jittered, not a lattice).
Points<2> jittered_circle(int n) {
  std::mt19937 random(5);
  std::uniform_real_distribution<double> jitter(0.0, 1.0);
  Points<2> p;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * kPi * (i + jitter(random)) / n;
    p.emplace_back(std::cos(a), std::sin(a));
  }
  return p;
}

TEST(TwoSidedAttraction, AStartAcrossACircleConvergesOntoIt) {
  const Points<2> points = jittered_circle(2000);
  // Figure 8: a start partly inside, partly outside the data.
  const SignedDistance<2> start = [](const Vec<2>& p) { return (p - Vec<2>(0.5, 0.0)).norm() - 1.0; };
  ReconstructionOptions o;
  o.evolution.two_sided = true;
  const ReconstructionResult<2> r = reconstruct_from<2>(points, start, o);
  ASSERT_EQ(r.status, ReconstructionStatus::converged);
  ASSERT_EQ(r.loops.size(), 1u);
  for (const auto& v : r.surface.vertices) EXPECT_LE(std::abs(v.norm() - 1.0), r.tolerance);
  // One-sided, the part inside the circle is pushed further in: the run cannot converge.
  o.evolution.two_sided = false;
  o.evolution.alpha = 2.0;
  EXPECT_NE(reconstruct_from<2>(points, start, o).status, ReconstructionStatus::converged);
}

TEST(TwoSidedAttraction, ASphereThroughATorusBecomesTheTorus) {
  const TestShape torus = make_test_shape("torus");  // major radius 1, minor 0.4, axis z
  const Points<3> points = sample_test_shape(torus, 5000).points;
  // Through the outer half of the tube: the ball holds the hole and the inner half of the tube.
  const SignedDistance<3> start = [](const Vec<3>& p) { return p.norm() - 1.2; };
  ReconstructionOptions o;
  o.evolution.two_sided = true;
  const ReconstructionResult<3> r = reconstruct_from<3>(points, start, o);
  ASSERT_EQ(r.status, ReconstructionStatus::converged);
  const SurfaceTopology t = analyze_surface(r.surface.vertices, r.surface.facets);
  EXPECT_TRUE(t.watertight);
  EXPECT_EQ(t.components, 1);
  EXPECT_EQ(t.genus, std::vector<int>{1});
  for (const auto& v : r.surface.vertices) ASSERT_LE(std::abs(torus.sdf(v)), r.tolerance);
}

}  // namespace
}  // namespace lsr
