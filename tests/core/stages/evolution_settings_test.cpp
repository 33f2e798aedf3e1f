// SPDX-License-Identifier: BSD-3-Clause
/// @file evolution_settings_test.cpp
/// @brief Each automatic default of the evolution, from the options and the local scales.
#include "evolution/evolution_settings.h"

#include <gtest/gtest.h>

#include <cmath>

namespace lsr::detail {
namespace {

TEST(EvolutionSettings, AutomaticDefaultsFollowAlphaAndTheScales) {
  ReconstructionOptions o;
  const Eigen::VectorXd scale = Eigen::VectorXd::Constant(3, 0.01), noise = (Eigen::VectorXd(3) << 0.0, 0.005, 0.05).finished();
  const std::vector<double> point_scale = {0.01, 0.02, 0.03};
  const EvolutionSettings s = resolve_evolution_settings(o, scale, noise, point_scale, 0.01, false);
  EXPECT_EQ(s.step.alpha, 2.0);
  EXPECT_DOUBLE_EQ(s.step.time_step, 0.1);  // 0.2 / |alpha|
  EXPECT_EQ(s.schedule.interval, 2);         // |alpha| dt k <= 0.4
  // beta = |alpha| l^2 (c + 2 min(noise / l, 1)) per vertex: no noise, half a scale, past it.
  const double c = o.evolution.curvature_factor;
  EXPECT_NEAR(s.step.curvature_weights[0], 2.0 * 1e-4 * c, 1e-18);
  EXPECT_NEAR(s.step.curvature_weights[1], 2.0 * 1e-4 * (c + 1.0), 1e-18);
  EXPECT_NEAR(s.step.curvature_weights[2], 2.0 * 1e-4 * (c + 2.0), 1e-18);
  // Tolerances: eps = tolerance_factor l per point, half of it to pin; the front side adds the gap.
  EXPECT_EQ(s.eps, (std::vector<double>{0.01, 0.02, 0.03}));
  EXPECT_EQ(s.reach, (std::vector<double>{0.005, 0.01, 0.015}));
  EXPECT_EQ(s.median_eps, 0.02);
  EXPECT_DOUBLE_EQ(s.front_tolerance[0], (o.stopping.tolerance_factor + o.sampling.gap_factor) * 0.01);
  // The tagged start's band; the sphere starts cross the box: everywhere.
  EXPECT_DOUBLE_EQ(s.schedule.band, (4.0 + o.sampling.gap_factor) * 0.01);
  EXPECT_TRUE(std::isinf(resolve_evolution_settings(o, scale, noise, point_scale, 0.01, true).schedule.band));
  // The stall rule's "near": one free step, exp(|alpha| dt).
  EXPECT_DOUBLE_EQ(s.schedule.stall.near, std::exp(0.2));
}

TEST(EvolutionSettings, AnAnisotropicMeshWidensTheToleranceByItsChordError) {
  ReconstructionOptions o;
  o.mesh.anisotropic = true;
  o.mesh.anisotropic_error = 0.25;
  const Eigen::VectorXd scale = Eigen::VectorXd::Constant(2, 0.01), noise = Eigen::VectorXd::Zero(2);
  const EvolutionSettings s = resolve_evolution_settings(o, scale, noise, {0.01, 0.02}, 0.01, false);
  // A P1 front through the data lies up to the chord error (0.25 local sizes) from it: eps +
  // that at the data and on the front side; the pins' reach stays half of eps.
  const double f = o.stopping.tolerance_factor;
  EXPECT_DOUBLE_EQ(s.eps[0], (f + 0.25) * 0.01);
  EXPECT_DOUBLE_EQ(s.eps[1], (f + 0.25) * 0.02);
  EXPECT_DOUBLE_EQ(s.reach[1], 0.5 * f * 0.02);
  EXPECT_DOUBLE_EQ(s.front_tolerance[0], (f + o.sampling.gap_factor + 0.25) * 0.01);
}

TEST(EvolutionSettings, WhatIsGivenIsKept) {
  ReconstructionOptions o;
  o.start.initial_front = InitialFront::inside;
  o.evolution.time_step = 0.05;
  o.evolution.curvature_weight = 0.3;
  o.stopping.tolerance = 0.004;
  o.evolution.renormalization_interval = 1;
  const Eigen::VectorXd scale = Eigen::VectorXd::Constant(2, 0.01), noise = Eigen::VectorXd::Zero(2);
  const EvolutionSettings s = resolve_evolution_settings(o, scale, noise, {0.01, 0.01}, 0.01, true);
  EXPECT_EQ(s.step.alpha, -2.0);  // grows from inside
  EXPECT_EQ(s.step.time_step, 0.05);
  EXPECT_EQ(s.step.curvature_weight, 0.3);
  EXPECT_EQ(s.step.curvature_weights.size(), 0);
  EXPECT_EQ(s.schedule.interval, 1);
  EXPECT_EQ(s.eps, (std::vector<double>{0.004, 0.004}));
}

}  // namespace
}  // namespace lsr::detail
