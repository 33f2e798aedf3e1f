// SPDX-License-Identifier: BSD-3-Clause
/// @file front_evolution.h
/// @brief The time loop of the paper's figure 2: step, pin the data reached, renormalise on
/// schedule, test stopping on both sides, keep the best iterate, stop on convergence or a stall.
#pragma once

#include "evolution/pinning.h"
#include "stage_clock.h"

#include "evolution/p1_operators.h"
#include "evolution/semi_implicit_step.h"
#include "evolution/stall_detection.h"
#include "lsrecon/core/level_set_reconstruction.h"
#include "lsrecon/core/progress.h"
#include "lsrecon/core/simplex_geometry.h"
#include "mesh/point_location.h"

#include <Eigen/Core>

#include <functional>
#include <vector>

namespace lsr::detail {

/// @brief What the loop reads and never changes (all #V per mesh vertex, #N per data point).
template <int D>
struct FrontProblem {
  const SimplexMesh<D>& mesh;
  const VertexNeighbours& neighbours;
  const P1Operators<D>& ops;
  const std::vector<Location<D>>& at;  ///< #N: where each data point lies in the mesh
  const VertexCells& cells;            ///< the vertices each data point holds once reached
  const std::vector<double>& eps;      ///< #N: the data side's tolerance
  const std::vector<double>& reach;    ///< #N: how near the front must come to pin a point
  const Eigen::VectorXd& front_tolerance;  ///< #V: the front side's tolerance
  const Eigen::VectorXd& scale;        ///< #V: local scale
  const std::vector<double>& dist;     ///< #V: distance to the data
  const Points<D>& away_from_data;     ///< #V unit directions away from the nearest point; empty unless a drive reads them
  const std::vector<char>& near_hole;  ///< #V: within a hole's radius of a spanned hole; empty without holes
  /// #N: the points of the cloud each data point stands for (mesh_resolution_data.h), which the
  /// unreached count adds up; empty: one each
  const std::vector<Index>& represented;
  /// #N and #V: the points and the front the stopping test reads (a tile's own, tiled_solve.h);
  /// empty: all
  const std::vector<char>& tested_points;
  const std::vector<char>& tested_vertices;
};

/// @brief How often to renormalise, where, and what the stall rule is: the loop's schedule.
struct FrontSchedule {
  int interval = 2;       ///< renormalise every `interval` steps
  double band = 0.0;      ///< ... within this distance of the front (renormalization.h)
  StallRule stall;
  bool rest_past_data = false;  ///< the one-sided drive at rest past the data (drives.h)
};

template <int D>
class FrontEvolution {
 public:
  FrontEvolution(const FrontProblem<D>& problem, const ReconstructionOptions& options, const FrontSchedule& schedule,
                 StepParameters step);

  /// @brief Evolves from `u`, driven by `d` (zeroed where data points are pinned), until the
  /// stopping test passes, the front stalls, max_iterations pass or the progress callback
  /// cancels. Fills the loop's fields of `r`: status, stalled, iterations, best_iteration,
  /// unreached_points, residual_history (in input units: times `median_eps` / `box_scale`),
  /// solver_iterations. On the first stall short of the stopping test, if given, the loop
  /// goes on from `restart()` (a field renormalised near its front); the best iterate stays
  /// the best of both.
  using Restart = std::function<Eigen::VectorXd()>;
  void run(Eigen::VectorXd u, Eigen::VectorXd& d, ReconstructionResult<D>& r, const Progress& progress, StageClock& clock,
           double median_eps, double box_scale, const Restart& restart = {});

  /// @brief The iterate with the lowest residual.
  Eigen::VectorXd& best() { return best_; }
  /// @brief Its residual, in tolerances (<= 1: converged).
  double best_residual() const { return best_residual_; }
  /// @brief Whether it was renormalised (a signed distance near the front) when kept.
  bool best_is_distance() const { return best_is_distance_; }

 private:
  /// The points the stopping test reads (a tile's own), how many cloud points they stand for,
  /// and the vertices whose front it ignores (near spanned holes; in a tile, also beyond it).
  struct TestedScope {
    bool all = true;
    double cloud_points = 0.0;
    std::vector<char> front_ignored;  ///< #V; empty when all are tested
  };
  TestedScope tested_scope() const;
  /// One semi-implicit step of u driven by d, the drive the options choose (drives.h).
  void step(SemiImplicitStepper<D>& stepper, const Eigen::VectorXd& d, Eigen::VectorXd& u, SolverReport& solve) const;
  /// Renormalises u near its front and measures the front against the data: its largest
  /// distance past the tolerance (stopping_test.h) and its measure (the displacement's denominator).
  void renormalize_front(Eigen::VectorXd& u, const Eigen::VectorXd& d, const TestedScope& tested, double& front_distance,
                         double& front_area) const;
  /// Keeps u as the best iterate if its residual is the lowest yet; returns whether it was.
  bool keep_if_best(const Eigen::VectorXd& u, int n, double residual, const std::vector<double>& per_point,
                    ReconstructionResult<D>& r);

  const FrontProblem<D>& p_;
  const ReconstructionOptions& o_;
  FrontSchedule schedule_;
  StepParameters step_;
  Eigen::VectorXd best_;
  double best_residual_;
  bool best_is_distance_ = false;
};

}  // namespace lsr::detail
