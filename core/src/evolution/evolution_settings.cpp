// SPDX-License-Identifier: BSD-3-Clause
/// @file evolution_settings.cpp
#include "evolution/evolution_settings.h"

#include "sampling/local_sampling.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lsr::detail {

EvolutionSettings resolve_evolution_settings(const ReconstructionOptions& o, const Eigen::VectorXd& scale,
                                             const Eigen::VectorXd& noise, const std::vector<double>& point_scale,
                                             double spacing, bool from_sphere) {
  EvolutionSettings s;
  StepParameters& step = s.step;
  const AutomaticDefaults automatic = automatic_defaults(3);  // alpha and dt: the same in 2D
  step.alpha = o.evolution.alpha != 0.0 ? o.evolution.alpha
                                        : (o.start.initial_front == InitialFront::inside ? -automatic.alpha : automatic.alpha);
  step.time_step = o.evolution.time_step > 0.0 ? o.evolution.time_step : automatic.time_step_factor / std::abs(step.alpha);
  if (o.evolution.curvature_weight >= 0.0) {
    step.curvature_weight = o.evolution.curvature_weight;
  } else {
    // Noise makes bumps of height sigma and width ~2 l; flattening them needs beta kappa >=
    // alpha sigma, i.e. beta ~ 2 |alpha| l^2: the weight grows towards that as sigma nears l.
    step.curvature_weights = std::abs(step.alpha) * scale.cwiseProduct(scale).cwiseProduct(
        (o.evolution.curvature_factor + 2.0 * noise.cwiseQuotient(scale).cwiseMin(1.0).array()).matrix());
    step.curvature_weight = std::abs(step.alpha) * o.evolution.curvature_factor * spacing * spacing;
  }
  step.solver_tolerance = o.evolution.solver_tolerance;
  step.solver = o.evolution.solver;
  s.schedule.interval = o.evolution.renormalization_interval > 0
                            ? o.evolution.renormalization_interval
                            : std::max(1, int(0.4 / (std::abs(step.alpha) * step.time_step) + 1e-9));
  // Tolerances: eps_i at the data, and between samples eps + the largest gap (gap_factor s).
  // An anisotropic mesh is built to let a P1 level set lie up to its chord error from the
  // smooth one (anisotropic_error local sizes): a front on the data reads up to that much.
  const double chord = o.mesh.anisotropic ? o.mesh.anisotropic_error : 0.0;
  s.eps.resize(point_scale.size());
  s.reach.resize(point_scale.size());
  for (std::size_t i = 0; i < s.eps.size(); ++i) {
    const double eps = o.stopping.tolerance > 0.0 ? o.stopping.tolerance : o.stopping.tolerance_factor * point_scale[i];
    s.eps[i] = eps + chord * point_scale[i];
    s.reach[i] = 0.5 * eps;
  }
  s.median_eps = median(s.eps);
  // Against the driving d: over a spanned hole, the distance to the discs.
  const std::size_t nv = std::size_t(scale.size());
  s.front_tolerance.resize(Eigen::Index(nv));
  for (std::size_t v = 0; v < nv; ++v) {
    s.front_tolerance[v] = (o.stopping.tolerance > 0.0 ? o.stopping.tolerance : o.stopping.tolerance_factor * scale[v]) +
                           (o.sampling.gap_factor + chord) * scale[v];
  }
  // Renormalisation band. From the tagged start the front moves at most |alpha| dt interval d
  // <= 0.4 (gap + 1) l between two renormalisations and the fit reads 3 l: 4 l + gap covers
  // both (over a spanned hole the start lies the gap above the discs, as elsewhere above the
  // data). The sphere starts cross the whole box: there, every vertex.
  s.schedule.band = !from_sphere ? (4.0 + o.sampling.gap_factor) * scale.maxCoeff() : std::numeric_limits<double>::infinity();
  s.schedule.stall = {o.stopping.patience, o.stopping.stall_gain,
                      o.stopping.near_residual >= 0.0 ? o.stopping.near_residual : std::exp(std::abs(step.alpha) * step.time_step),
                      o.stopping.stall_stillness};
  s.schedule.rest_past_data = o.evolution.rest_past_data && !o.evolution.two_sided;
  return s;
}

}  // namespace lsr::detail
