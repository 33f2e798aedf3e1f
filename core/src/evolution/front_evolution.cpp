// SPDX-License-Identifier: BSD-3-Clause
/// @file front_evolution.cpp
#include "evolution/front_evolution.h"

#include "evolution/drives.h"
#include "evolution/stopping_test.h"

#include "evolution/renormalization.h"
#include "lsrecon/core/errors.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace lsr::detail {

namespace {

std::vector<double> tested_only(const std::vector<double>& values, const std::vector<char>& tested) {
  std::vector<double> out;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (tested[i]) out.push_back(values[i]);
  }
  return out;
}

// The share of the way from the first data residual down to 1 (converged) that `current` has
// covered, on a log scale (the data side falls geometrically); 0 when it started converged.
double covered(double first, double current) {
  if (!(first > 1.0)) return 0.0;
  return std::clamp(std::log(first / std::max(current, 1.0)) / std::log(first), 0.0, 1.0);
}

}  // namespace

template <int D>
FrontEvolution<D>::FrontEvolution(const FrontProblem<D>& problem, const ReconstructionOptions& options,
                                  const FrontSchedule& schedule, StepParameters step)
    : p_(problem), o_(options), schedule_(schedule), step_(std::move(step)),
      best_residual_(std::numeric_limits<double>::infinity()) {}

template <int D>
typename FrontEvolution<D>::TestedScope FrontEvolution<D>::tested_scope() const {
  TestedScope t;
  const std::size_t nv = p_.mesh.vertices.size();
  t.all = p_.tested_points.empty();
  for (std::size_t i = 0; i < p_.at.size(); ++i) {
    if (t.all || p_.tested_points[i]) t.cloud_points += p_.represented.empty() ? 1.0 : double(p_.represented[i]);
  }
  if (t.all) return t;
  t.front_ignored.assign(nv, 0);
  for (std::size_t v = 0; v < nv; ++v) t.front_ignored[v] = !p_.tested_vertices[v] || (!p_.near_hole.empty() && p_.near_hole[v]);
  return t;
}

template <int D>
void FrontEvolution<D>::step(SemiImplicitStepper<D>& stepper, const Eigen::VectorXd& d, Eigen::VectorXd& u, SolverReport& solve) const {
  if (o_.evolution.two_sided) {
    stepper.advance(two_sided_drive(p_.ops, d, p_.away_from_data, u), u, step_, &solve);
  } else if (schedule_.rest_past_data) {
    const Eigen::VectorXd gap = o_.sampling.gap_factor * p_.scale;
    stepper.advance(drive_resting_past_data(p_.ops, d, p_.away_from_data, u, p_.dist, gap, p_.near_hole, step_.alpha), u, step_,
                    &solve);
  } else {
    stepper.advance(d, u, step_, &solve);
  }
}

template <int D>
void FrontEvolution<D>::renormalize_front(Eigen::VectorXd& u, const Eigen::VectorXd& d, const TestedScope& tested,
                                          double& front_distance, double& front_area) const {
  const RenormalizationReport<D> renormalized = renormalize(p_.mesh, p_.neighbours, u, schedule_.band, o_.limits.threads);
  // Against the driving d: a piece of front held by pinned cells has settled, and what it
  // spans is the resolution limit, not a reason to go on. Not near spanned holes: a front that
  // crept past a hole's rim is the fit's to correct (attach_fit).
  front_distance = max_front_distance(renormalized.front, d, p_.front_tolerance, tested.all ? p_.near_hole : tested.front_ignored);
  front_area = front_measure(renormalized.front);
}

template <int D>
bool FrontEvolution<D>::keep_if_best(const Eigen::VectorXd& u, int n, double residual, const std::vector<double>& per_point,
                                     ReconstructionResult<D>& r) {
  if (!(residual < best_residual_)) return false;
  best_residual_ = residual;
  best_ = u;
  best_is_distance_ = n % schedule_.interval == 0;
  r.best_iteration = n;
  r.unreached_points = 0;
  for (std::size_t i = 0; i < per_point.size(); ++i) {
    if (per_point[i] > 1.0) r.unreached_points += p_.represented.empty() ? 1 : std::size_t(p_.represented[i]);
  }
  return true;
}

template <int D>
void FrontEvolution<D>::run(Eigen::VectorXd u, Eigen::VectorXd& d, ReconstructionResult<D>& r, const Progress& progress,
                            StageClock& clock, double median_eps, double box_scale, const Restart& restart) {
  const ReconstructionOptions& o = o_;
  const int interval = schedule_.interval;
  const std::size_t nv = p_.mesh.vertices.size();
  double front_distance = std::numeric_limits<double>::infinity();
  std::vector<char> pinned(p_.at.size(), 0), held(nv, 0);
  step_.held = &held;
  double first_residual = std::numeric_limits<double>::infinity();
  StallDetector stall(schedule_.stall);
  double front_area = 0.0;  // of the last renormalised front: the displacement's denominator
  double progress_fraction = 0.0;
  best_ = u;
  bool best_front_ok = false;
  bool restarted = false;
  // A tile's test reads its own points and front only.
  const TestedScope tested = tested_scope();
  const bool all_tested = tested.all;
  try {
    // Its vectors are kept from step to step, released before each renormalisation (the
    // loop's peak) and freed before the fit.
    SemiImplicitStepper<D> stepper(p_.ops);
    Eigen::VectorXd before;
    for (int n = 1; n <= o.stopping.max_iterations; ++n) {
      progress.update("solve", progress_fraction);
      SolverReport solve;
      before = u;
      step(stepper, d, u, solve);
      const double displacement = front_displacement(before, u, p_.ops.ball_measure, p_.scale, D, front_area);
      r.solver_iterations += solve.iterations;
      clock.end("solve");
      if (o.evolution.pin_reached_data && !o.evolution.two_sided) pin_reached_data(p_.at, p_.cells, u, step_.alpha, p_.reach, pinned, d, held);
      if (n % interval == 0) {
        stepper.release();  // the renormalisation is the loop's memory peak
        renormalize_front(u, d, tested, front_distance, front_area);
        clock.end("renormalize");
      }
      std::vector<double> per_point = data_residuals(p_.at, u, p_.eps);
      for (std::size_t i = 0; i < per_point.size() && !all_tested; ++i) per_point[i] = p_.tested_points[i] ? per_point[i] : 0.0;
      const double data_residual = *std::max_element(per_point.begin(), per_point.end());
      // Converged when every data point is within its eps of the front and the front within
      // its tolerance of the data; the residual is the worse of the two, in tolerances.
      const double residual = std::max(data_residual, front_distance);
      r.residual_history.push_back(residual * median_eps / box_scale);
      // The data side falls geometrically (the front side can drop at once when a bubble
      // vanishes): progress is the fraction of log(first) it has covered, never receding.
      if (!std::isfinite(first_residual)) first_residual = data_residual;
      progress_fraction = std::max(progress_fraction, covered(first_residual, data_residual));
      r.iterations = n;
      if (keep_if_best(u, n, residual, per_point, r)) best_front_ok = front_distance <= 1.0;
      clock.end("stopping test");
      // Within tolerance; or, if asked, as good as a stall would leave it (below) without
      // waiting for the stall.
      const bool few_unreached = best_front_ok && double(r.unreached_points) <= o.stopping.unreached_fraction * tested.cloud_points;
      if (best_residual_ <= 1.0 || (o.stopping.stop_when_few_unreached && r.best_iteration == n && few_unreached)) {
        r.status = ReconstructionStatus::converged;
        break;
      }
      r.stalled = stall.stalled(best_residual_, r.best_iteration == n, displacement,
                                bulk_residual(all_tested ? per_point : tested_only(per_point, p_.tested_points), schedule_.stall.bulk_share));
      if (r.stalled) {
        // Stalled: the front no longer gets closer to the last points. Curvature holds it short
        // of the tip of a sharp concave crease, pinned cells short of a slit between close
        // sheets; the fit places the surface there. A few such points do not make the run fail.
        if (few_unreached) {
          r.status = ReconstructionStatus::converged;
          break;
        }
        if (!restart || restarted) break;
        // Once: on from the restart's field, its residual read afresh.
        restarted = true;
        r.stalled = false;
        u = restart();
        stall = StallDetector(schedule_.stall);
        front_distance = std::numeric_limits<double>::infinity();
      }
    }
  } catch (const Cancelled&) {
    r.status = ReconstructionStatus::cancelled;
  }
}

template class FrontEvolution<2>;
template class FrontEvolution<3>;

}  // namespace lsr::detail
