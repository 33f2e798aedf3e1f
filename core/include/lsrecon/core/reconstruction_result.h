// SPDX-License-Identifier: BSD-3-Clause
/// @file reconstruction_result.h
/// @brief What reconstruct() returns: the surface (or curves), its normals, the status, and
/// the values the automatic options took.
#pragma once

#include "lsrecon/core/level_set_extraction.h"
#include "lsrecon/core/level_set_volume_mesh.h"
#include "lsrecon/core/types.h"

#include <map>
#include <string>
#include <vector>

namespace lsr {

enum class ReconstructionStatus {
  converged,      ///< data and front within tolerance (up to StoppingOptions::unreached_fraction of stalled points)
  not_converged,  ///< stopped by patience or max_iterations; the best iterate is returned
  cancelled,      ///< the progress callback asked to stop; the best iterate so far, if any
  shared,         ///< a worker other than 0 of LimitOptions::exchange: its share done, no surface
};

/// @brief What came out, and how.
template <int D>
struct ReconstructionResult {
  ReconstructionStatus status = ReconstructionStatus::not_converged;
  LevelSetMesh<D> surface;          ///< in input coordinates; facets oriented outwards
  Points<D> normals;                ///< #surface vertices, unit, outward (from grad u)
  /// #surface vertices: each vertex's distance to the nearest data point, input units (to the
  /// sample the solver read: where the cloud is denser than the mesh, within a mesh size of
  /// the nearest input point). Large where the surface is a guess (a side no view saw, a
  /// spanned hole): trim by it, as PoissonRecon's users trim by its density.
  std::vector<double> distance_to_data;
  /// With OutputOptions::volume_mesh: the box split into inside and outside along the
  /// surface, in input coordinates; its interface vertices are the surface's.
  VolumeMesh<D> volume;
  std::vector<std::vector<Index>> loops;  ///< 2D only: closed loops in order
  int iterations = 0;               ///< time steps taken
  int best_iteration = 0;           ///< the step whose u is returned
  bool stalled = false;             ///< stopped by the stall rules (see StoppingOptions::patience), not by max_iterations
  /// Worst distance between data and front at best_iteration relative to its local tolerance,
  /// times `tolerance`: input units, and converged exactly when residual <= tolerance.
  double residual = 0.0;
  double tolerance = 0.0;           ///< the median stopping tolerance, input units
  /// Points farther than their tolerance from the front at best_iteration. A converged run may
  /// leave up to StoppingOptions::unreached_fraction of the points where the front stalled (tips of sharp
  /// concave creases, slits between close sheets); the fit places the surface there.
  std::size_t unreached_points = 0;
  double output_level = 0.0;        ///< without OutputOptions::fit_surface: the level of u extracted, input units
  /// #input points: outward unit normal of each input point (PCA of its neighbours, oriented
  /// by grad u; where the cloud is denser than the mesh, the points the mesh's sample left out
  /// as their nearest kept point); NaN for skipped points. Feed these to normal-based methods
  /// such as Poisson. Empty when LimitOptions::exchange's workers shared the cloud (no process
  /// holds every point).
  Points<D> point_normals;
  double spacing = 0.0;             ///< median local sampling spacing, input units
  std::vector<double> residual_history;  ///< max |u| on the data per step, input units
  double h_min = 0.0;               ///< the finest mesh size used, unit box
  bool tagged_start = false;        ///< the start was the tagged front (else a circle / sphere)
  /// cavities the tagged start's flood entered through an opening narrower than the hole radius
  /// and gave back (cavity_sealing.h): an open end that a sampling hole made
  int sealed_cavities = 0;
  /// data points the tagged start's flood reached from both sides; when they are many (an
  /// open scan: an unseen underside, a single view) the sides the flood entered round the
  /// sheets were closed (docs/how-it-works.md: Open sides), else 0
  Index open_side_points = 0;
  double noise = 0.0;               ///< estimated noise deviation of the data, input units
  bool scan_lines = false;          ///< 3D: the cloud was read as scan lines (SamplingOptions::scan_lines)
  double time_step = 0.0, alpha = 0.0, curvature_weight = 0.0;  ///< the values used
  Index mesh_vertices = 0, mesh_simplices = 0;
  std::size_t input_points = 0, skipped_points = 0;  ///< skipped: NaN / infinite
  std::size_t outlier_points = 0;  ///< isolated points left out (see SamplingOptions::outlier_factor)
  /// copies of another input point (equal coordinates) merged into it: they share its normal
  std::size_t duplicate_points = 0;
  long solver_iterations = 0;       ///< linear-solver iterations, summed over the steps
  std::map<std::string, double> seconds;  ///< wall time per stage
  std::vector<std::string> stages;        ///< the keys of `seconds` in the order they first ran
};

}  // namespace lsr
