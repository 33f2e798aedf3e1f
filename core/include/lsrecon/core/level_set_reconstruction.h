// SPDX-License-Identifier: BSD-3-Clause
/// @file level_set_reconstruction.h
/// @brief The whole pipeline of the paper (figure 2) as one call: unoriented points in, closed
/// curves (2D) or a closed oriented surface with normals (3D) out, in the input's coordinates.
///
/// The front evolves by du/dt = |grad u| (beta kappa(u) + alpha d(x)). The paper's curvature
/// weight beta = 1 bridges concavities: they stall beta |kappa| / alpha outside the data
/// (DESIGN.md section 9). The default beta = 0.3 h_min^2 keeps that stall below 0.15 h_min for
/// features down to h_min; README.md lists the other measured departures from the paper.
#pragma once

#include "lsrecon/core/adaptive_refinement.h"
#include "lsrecon/core/level_set_extraction.h"
#include "lsrecon/core/progress.h"
#include "lsrecon/core/semi_implicit_step.h"

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace lsr {

/// @brief Where the front starts.
enum class InitialFront {
  enclosing,  ///< a circle / sphere around all the data; alpha > 0 (the front shrinks)
  inside,     ///< a circle / sphere around the data's centroid, inside the shape; alpha < 0
};

/// @brief Parameters. Lengths are relative to the unit box the data is mapped into (the data's
/// bounding ball becomes a ball of radius 0.4); 0 means "choose from the data".
struct ReconstructionOptions {
  /// Finest mesh size; 0: the median spacing of the data or 1.5 times its estimated noise,
  /// whichever is larger, clamped to [1/4096, 1/64] (2D) or [1/512, 1/32] (3D).
  double h_min = 0.0;
  double h_max = 1.0 / 8;     ///< coarsest mesh size
  double grading = 2.0;       ///< see AdaptiveMeshOptions::grading
  double alpha = 0.0;         ///< attraction weight; 0: +2 enclosing, -2 inside
  /// beta >= 0, the smoothness knob; negative: (0.3 + 4 min(1, noise / h_min)) h_min^2.
  double curvature_weight = -1.0;
  /// dt; 0: 0.2 / |alpha|. The front closes in on the data like exp(-alpha t), and the
  /// explicit data term's CFL limit on the graded mesh (sizes ~ c d) is about c / alpha, so dt
  /// is a fraction of 1/alpha, independent of h_min. The paper's 10 h_min equals it at
  /// h_min = 1/100; at h_min = 1/2000 it needed 1000+ steps where this needs 58 (measured).
  double time_step = 0.0;
  double tolerance = 0.0;     ///< eps of the stopping test max |u(x)| <= eps; 0: h_min
  int max_iterations = 1000;
  /// Renormalise every k steps; 0: as rarely as keeps |alpha| dt k <= 0.4, which is 2 at the
  /// default dt (half the dominant cost, same accuracy on sphere, torus and star) and 1 for
  /// large steps (at |alpha| dt = 0.78, k = 2 left islands; measured).
  int renormalization_interval = 0;
  int patience = 5;  ///< stop after this many steps without a better residual (noisy data)
  /// Pin the front at data points it has reached (d := 0 on the vertices of their simplices).
  /// The unsigned d never stops a front that reaches the data, and its P1 interpolant is O(h)
  /// at the data points, so converged parts pass through the data while slower parts (holes,
  /// concavities) still travel; pinning holds them (measured: the torus needs it).
  bool pin_reached_data = true;
  /// Extract the level set through the data, {u = median of u at the data points}, instead of
  /// {u = 0}. The front stops as soon as every point is within eps, so {u = 0} lies up to eps
  /// off the data on the side it came from; the median level removes that bias.
  bool level_through_data = true;
  InitialFront initial_front = InitialFront::enclosing;
  LinearSolver solver = LinearSolver::conjugate_gradient;
  double solver_tolerance = 1e-6;  ///< relative residual of each linear solve
  /// Refuse (lsr::MeshTooLarge) meshes predicted to need more vertices; 0: what fits in 70% of
  /// the machine's memory at the measured peak of about 3 KB per vertex in 3D (3.5 KB
  /// assumed) and 1.5 KB in 2D (2 KB assumed): about 4.8 million 3D vertices in 24 GiB.
  Index max_vertices = 0;
  int threads = 0;  ///< 0: all cores
};

enum class ReconstructionStatus {
  converged,      ///< max |u| on the data fell to the tolerance
  not_converged,  ///< stopped by patience or max_iterations; the best iterate is returned
  cancelled,      ///< the progress callback asked to stop; the best iterate so far, if any
};

/// @brief What came out, and how.
template <int D>
struct ReconstructionResult {
  ReconstructionStatus status = ReconstructionStatus::not_converged;
  LevelSetMesh<D> surface;          ///< in input coordinates; facets oriented outwards
  Points<D> normals;                ///< #surface vertices, unit, outward (from grad u)
  std::vector<std::vector<Index>> loops;  ///< 2D only: closed loops in order
  int iterations = 0;               ///< time steps taken
  int best_iteration = 0;           ///< the step whose u is returned
  double residual = 0.0;            ///< max |u| on the data at best_iteration, input units
  double tolerance = 0.0;           ///< the stopping tolerance, input units
  double output_level = 0.0;        ///< the level of u extracted (0 or the median on the data), input units
  std::vector<double> residual_history;  ///< max |u| on the data per step, input units
  double h_min = 0.0;               ///< the finest mesh size used, unit box
  double noise = 0.0;               ///< estimated noise deviation of the data, input units
  double time_step = 0.0, alpha = 0.0, curvature_weight = 0.0;  ///< the values used
  Index mesh_vertices = 0, mesh_simplices = 0;
  std::size_t input_points = 0, skipped_points = 0;  ///< skipped: NaN / infinite
  long solver_iterations = 0;       ///< linear-solver iterations, summed over the steps
  std::map<std::string, double> seconds;  ///< wall time per stage
};

/// @brief Reconstructs from points (#N, any scale).
/// @throw InvalidInput for too few or degenerate points and options out of range (the message
/// says what to change); MeshTooLarge when the mesh would exceed max_vertices. Cancellation
/// and non-convergence are statuses, not exceptions.
template <int D>
ReconstructionResult<D> reconstruct(const Points<D>& points, const ReconstructionOptions& options = {},
                                    const ProgressCallback& progress = {});

/// @brief A signed distance (or any function negative inside, positive outside, with a regular
/// zero set) in the input's coordinates.
template <int D>
using SignedDistance = std::function<double(const Vec<D>&)>;

/// @brief reconstruct() starting from the zero set of initial (input coordinates) instead of
/// a circle / sphere. options.alpha must be given: > 0 when that zero set encloses the data,
/// < 0 when it lies inside the shape; options.initial_front is ignored. A start that is partly
/// inside and partly outside the data is not supported (an unsigned d cannot attract from both
/// sides; see DESIGN.md section 9).
/// @throw InvalidInput as reconstruct(), or if alpha is 0 or initial has no zero set in the box.
template <int D>
ReconstructionResult<D> reconstruct_from(const Points<D>& points, const SignedDistance<D>& initial,
                                         const ReconstructionOptions& options,
                                         const ProgressCallback& progress = {});

}  // namespace lsr
