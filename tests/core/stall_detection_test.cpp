// SPDX-License-Identifier: BSD-3-Clause
/// @file stall_detection_test.cpp
#include "evolution/stall_detection.h"

#include "evolution/p1_operators.h"
#include "lsrecon/core/simplex_geometry.h"
#include "lsrecon/testdata/analytic_shapes.h"
#include "mesh/adaptive_refinement.h"
#include "mesh/kuhn_bisection.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace lsr {
namespace {

const double kPi = std::acos(-1.0);

// Steps until the detector says stalled (0: never within `steps`), feeding a best residual that
// falls by `factor` per step from `start` and a constant displacement.
int steps_to_stall(double start, double factor, double displacement, int steps = 60) {
  StallDetector detector(StallRule{});
  double residual = start;
  for (int n = 1; n <= steps; ++n) {
    residual *= factor;
    if (detector.stalled(residual, factor < 1.0, displacement)) return n;
  }
  return 0;
}

TEST(StallDetection, AFreeFrontNeverStalls) {
  // exp(-|alpha| dt) per step, sweeping a fifth of a spacing per step.
  EXPECT_EQ(steps_to_stall(50.0, 0.82, 0.2, 20), 0);
}

TEST(StallDetection, NoBetterResidualForTheWindowStalls) {
  EXPECT_EQ(steps_to_stall(3.0, 1.0, 1.0), 5);  // moving or not: the patience rule
}

TEST(StallDetection, ACreepingStillFrontStallsAfterOneWindow) {
  // 0.5% per step (a crease tip) while the front sweeps a thousandth of a spacing per step.
  EXPECT_EQ(steps_to_stall(2.0, 0.995, 1e-3), 6);
}

TEST(StallDetection, ACreepingFrontThatStillSweepsGoesOn) {
  // The membrane over a torus's hole thinning to a pinch: 0.5% per step, 0.01 spacing per step.
  EXPECT_EQ(steps_to_stall(2.0, 0.995, 0.01), 0);
}

TEST(StallDetection, ANoisyFrontEatingIntoItsOutliersGoesOn) {
  // 3% per step (> 5% per window) with a still front: the bridge of the noisy two spheres.
  EXPECT_EQ(steps_to_stall(5.0, 0.97, 1e-4, 30), 0);
}

// Steps until stalled for a still front (1e-4 spacings a step) whose best residual falls 4% a
// step (no creep by itself) while the bulk's residual falls by bulk_factor a step, alternating
// 2% up and down with the renormalisations.
int steps_to_stall_with_bulk(double bulk_factor, int steps = 40) {
  StallDetector detector(StallRule{});
  double best = 8.0, bulk = 2.8;  // best stays above `near` over the 40 steps
  for (int n = 1; n <= steps; ++n) {
    best *= 0.96;
    bulk *= bulk_factor;
    if (detector.stalled(best, true, 1e-4, bulk * (n % 2 ? 1.02 : 0.98))) return n;
  }
  return 0;
}

TEST(StallDetection, StragglersCreepingAboveAStillBulkStall) {
  // The 1M-point sphere scan: the bulk (all but the worst 0.1%) stands from step 23 while the
  // best residual, set by single stragglers, creeps 0.1-0.2 tolerances a step.
  EXPECT_EQ(steps_to_stall_with_bulk(1.0), 6);
  // The noisy two spheres: the bridge's patch of points falls with the best residual.
  EXPECT_EQ(steps_to_stall_with_bulk(0.97), 0);
}

TEST(StallDetection, TheBulkIsAQuantileOfTheResiduals) {
  std::vector<double> residuals(1000);
  for (std::size_t i = 0; i < residuals.size(); ++i) residuals[i] = double((i * 389) % 1000);  // 0..999, shuffled
  EXPECT_EQ(bulk_residual(residuals, 0.999), 998.0);  // rank floor(0.999 * 999) = 998
  EXPECT_EQ(bulk_residual(residuals, 0.5), 499.0);
  EXPECT_EQ(bulk_residual({}, 0.999), 0.0);
}

TEST(StallDetection, AStillFrontOneFreeStepFromConvergingStalls) {
  // Falling 3% per step from within exp(0.2) = 1.22 tolerances: held, not travelling. Within
  // `near` from step 1, so the window starting there ends at step 6.
  EXPECT_EQ(steps_to_stall(1.2, 0.97, 1e-4), 6);
  // From farther away the same creep goes on until it gets within 1.22 and a window passes.
  const int n = steps_to_stall(2.0, 0.97, 1e-4);
  EXPECT_EQ(n, int(std::ceil(std::log(1.22 / 2.0) / std::log(0.97))) + 5);
}

TEST(StallDetection, UnknownDisplacementNeverCountsAsStill) {
  EXPECT_EQ(steps_to_stall(2.0, 0.995, std::numeric_limits<double>::infinity()), 0);
}

// A sphere of radius r shrunk by delta sweeps the shell 4/3 pi (r^3 - (r - delta)^3), i.e. a mean
// displacement of (r^3 - (r - delta)^3) / (3 r^2) over its area. The lumped cells of the
// vertices that changed sign approximate the shell to within a cell layer, h / delta relative
// at most, the front's measure the sphere's to O(h^2).
TEST(FrontDisplacement, ShrinkingSphereSweepsItsShell) {
  const int n = 64;
  const double h = 1.0 / n, r = 0.3, delta = 4 * h, spacing = 0.01;
  const AdaptiveMesh<3> m = leaf_mesh(KuhnBisectionForest<3>(n));
  const P1Operators<3> ops = assemble_p1_operators(m.mesh, compute_simplex_geometry(m.mesh));
  const Vec<3> c(0.5, 0.5, 0.5);
  Eigen::VectorXd before(Eigen::Index(m.mesh.vertices.size())), after(before.size());
  for (Eigen::Index v = 0; v < before.size(); ++v) {
    before[v] = (m.mesh.vertices[std::size_t(v)] - c).norm() - r;
    after[v] = before[v] + delta;
  }
  const std::vector<double> values(before.data(), before.data() + before.size());
  const double area = front_measure(extract_zero_level_set(m.mesh, values));
  EXPECT_NEAR(area, 4 * kPi * r * r, 4 * kPi * r * r * 2 * h * h / (r * r));
  const double expected = (std::pow(r, 3) - std::pow(r - delta, 3)) / (3 * r * r) / spacing;
  const double got = front_displacement(before, after, ops.ball_measure, Eigen::VectorXd::Constant(before.size(), spacing), 3, area);
  EXPECT_NEAR(got, expected, expected * h / delta);
  // Nothing moved: zero; no front yet: unknown.
  EXPECT_EQ(front_displacement(before, before, ops.ball_measure, Eigen::VectorXd::Constant(before.size(), spacing), 3, area), 0.0);
  EXPECT_TRUE(std::isinf(front_displacement(before, after, ops.ball_measure, Eigen::VectorXd::Constant(before.size(), spacing), 3, 0.0)));
}

}  // namespace
}  // namespace lsr
