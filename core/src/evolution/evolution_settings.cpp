// SPDX-License-Identifier: BSD-3-Clause
/// @file evolution_settings.cpp
#include "evolution/evolution_settings.h"

#include "lsrecon/core/local_sampling.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lsr::detail {

EvolutionSettings resolve_evolution_settings(const ReconstructionOptions& o, const Eigen::VectorXd& scale,
                                             const Eigen::VectorXd& noise, const std::vector<double>& point_scale,
                                             double spacing, bool from_sphere) {
  EvolutionSettings s;
  StepParameters& step = s.step;
  step.alpha = o.alpha != 0.0 ? o.alpha : (o.initial_front == InitialFront::inside ? -2.0 : 2.0);
  step.time_step = o.time_step > 0.0 ? o.time_step : 0.2 / std::abs(step.alpha);
  if (o.curvature_weight >= 0.0) {
    step.curvature_weight = o.curvature_weight;
  } else {
    // Noise makes bumps of height sigma and width ~2 l; flattening them needs beta kappa >=
    // alpha sigma, i.e. beta ~ 2 |alpha| l^2: the weight grows towards that as sigma nears l.
    step.curvature_weights = std::abs(step.alpha) * scale.cwiseProduct(scale).cwiseProduct(
        (o.curvature_factor + 2.0 * noise.cwiseQuotient(scale).cwiseMin(1.0).array()).matrix());
    step.curvature_weight = std::abs(step.alpha) * o.curvature_factor * spacing * spacing;
  }
  step.solver_tolerance = o.solver_tolerance;
  step.solver = o.solver;
  s.schedule.interval = o.renormalization_interval > 0
                            ? o.renormalization_interval
                            : std::max(1, int(0.4 / (std::abs(step.alpha) * step.time_step) + 1e-9));
  // Tolerances: eps_i at the data, and between samples eps + the largest gap (gap_factor s).
  s.eps.resize(point_scale.size());
  s.reach.resize(point_scale.size());
  for (std::size_t i = 0; i < s.eps.size(); ++i) {
    s.eps[i] = o.tolerance > 0.0 ? o.tolerance : o.tolerance_factor * point_scale[i];
    s.reach[i] = 0.5 * s.eps[i];
  }
  s.median_eps = median(s.eps);
  // Measured against the driving d: over a spanned hole, the distance to the discs.
  const std::size_t nv = std::size_t(scale.size());
  s.front_tolerance.resize(Eigen::Index(nv));
  for (std::size_t v = 0; v < nv; ++v) {
    s.front_tolerance[v] = (o.tolerance > 0.0 ? o.tolerance : o.tolerance_factor * scale[v]) + o.gap_factor * scale[v];
  }
  // Renormalisation band. From the tagged start the front moves at most |alpha| dt interval d
  // <= 0.4 (gap + 1) l between two renormalisations and the fit reads 3 l: 4 l + gap covers
  // both (over a spanned hole the start lies the gap above the discs, as elsewhere above the
  // data). The sphere starts cross the whole box: there, every vertex.
  s.schedule.band = !from_sphere ? (4.0 + o.gap_factor) * scale.maxCoeff() : std::numeric_limits<double>::infinity();
  s.schedule.stall = {o.patience, o.stall_gain,
                      o.near_residual >= 0.0 ? o.near_residual : std::exp(std::abs(step.alpha) * step.time_step),
                      o.stall_stillness};
  s.schedule.rest_past_data = o.rest_past_data && !o.two_sided;
  return s;
}

}  // namespace lsr::detail
