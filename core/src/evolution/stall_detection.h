// SPDX-License-Identifier: BSD-3-Clause
/// @file stall_detection.h
/// @brief When to stop a front that no longer converges. A free front closes its gap to the
/// data by the factor exp(-|alpha| dt) (0.82 at the defaults) per step. One held at the tip of
/// a concave crease or by pins at a slit stands still while its residual creeps (0.1-1% per
/// step); waiting until not even that
/// happens costs up to 20-40 steps. A front that creeps while it still sweeps volume is not
/// held: a membrane thinning to a pinch (a start through a torus's hole) or a noisy front
/// eating into its outliers (2-4% per step) must go on. Nor is a still front whose
/// bulk of points still comes closer (a bridge thinning to a pinch), but one whose residual
/// creeps only at a few stragglers is (a million-point scan's registration layers).
#pragma once

#include "lsrecon/core/level_set_extraction.h"

#include <Eigen/Core>

#include <vector>

namespace lsr {

/// @brief The rule; see StallDetector::stalled.
struct StallRule {
  int patience = 5;          ///< the window, in steps
  double gain = 0.05;        ///< a best residual that fell by less over the window crept
  double near = 1.22;        ///< a best residual within this (in tolerances) is one free step from converging
  double stillness = 0.01;   ///< mean front displacement over the window, in local spacings, below which it stood still
  /// The bulk of the data: all but the worst 1 - bulk_share of the points. On a million points
  /// the best residual is set by a few stragglers (of registration layers, of the noise) that a
  /// still front reaches one by one, 0.1-0.2 tolerances a step, for 20 steps or more, while the
  /// bulk's residual stands; a bridge thinning to a pinch moves a patch of points (tens at
  /// 20k), which this share keeps in view.
  double bulk_share = 0.999;
};

class StallDetector {
 public:
  explicit StallDetector(const StallRule& rule) : rule_(rule) {}

  /// @brief After each step: the best residual so far, whether this step improved it, and the
  /// front's mean displacement during the step in local spacings (front_displacement(); +inf
  /// when unknown). Stalled: no better residual for `patience` steps; or the front stood still
  /// over the window while the best residual crept (fell by less than `gain`) or had already
  /// been within `near` of converging at the window's start.
  bool stalled(double best_residual, bool improved, double displacement, double quantile = 0.0);

 private:
  StallRule rule_;
  std::vector<double> best_, displacement_, bulk_;  // bulk_: its best so far
  int since_improvement_ = 0;
};

/// @brief The residual of the bulk: the bulk_share quantile of the points' residuals.
double bulk_residual(std::vector<double> residuals, double bulk_share);

/// @brief Surface measure of a front (length in 2D, area in 3D).
template <int D>
double front_measure(const LevelSetMesh<D>& front);

/// @brief Mean displacement of the front between two iterates, in local spacings: the measure
/// of the lumped cells of the vertices whose sign changed (|B_i| / (D + 1)), each divided by the
/// vertex's local spacing, over the front's measure.
double front_displacement(const Eigen::VectorXd& before, const Eigen::VectorXd& after, const Eigen::VectorXd& ball_measure,
                          const Eigen::VectorXd& spacing, int dimension, double front_measure);

}  // namespace lsr
