// SPDX-License-Identifier: BSD-3-Clause
/// @file evolution_settings.h
/// @brief The automatic defaults of the evolution, resolved in one place from the options and
/// the local scales: alpha, dt, the curvature weights, the renormalisation schedule, the
/// stopping tolerances and the stall rule.
#pragma once

#include "evolution/front_evolution.h"

#include "evolution/semi_implicit_step.h"
#include "lsrecon/core/level_set_reconstruction.h"

#include <Eigen/Core>

#include <vector>

namespace lsr::detail {

struct EvolutionSettings {
  StepParameters step;
  FrontSchedule schedule;
  std::vector<double> eps;          ///< #N: |u(x_i)| <= eps_i at every data point
  std::vector<double> reach;        ///< #N: a point is pinned once the front is this near
  double median_eps = 0.0;
  Eigen::VectorXd front_tolerance;  ///< #V: the front within this of the (driving) data
};

/// @brief From the options (0 or negative: automatic) and, per mesh vertex, the local scale and
/// noise; per data point its scale; `spacing` the median one. `from_sphere`: the start is a
/// circle / sphere (or the caller's) that crosses the whole box, rather than the tagged start.
EvolutionSettings resolve_evolution_settings(const ReconstructionOptions& o, const Eigen::VectorXd& scale,
                                             const Eigen::VectorXd& noise, const std::vector<double>& point_scale,
                                             double spacing, bool from_sphere);

}  // namespace lsr::detail
