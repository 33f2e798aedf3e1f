// SPDX-License-Identifier: BSD-3-Clause
/// @file front_on_mesh.h
/// @brief Stages 5 to 8 of the paper's figure 2 on a given mesh: the distance and scales at its
/// vertices, the P1 operators, the settings, the attraction and u0, then the time loop; what
/// the fit and the extraction read after it.
#pragma once

#include "evolution/p1_operators.h"
#include "lsrecon/core/level_set_reconstruction.h"
#include "lsrecon/core/progress.h"
#include "mesh/adaptive_refinement.h"
#include "mesh/point_location.h"
#include "mesh/vertex_fields.h"
#include "sampling/sampled_data.h"
#include "stage_clock.h"

#include <Eigen/Core>

#include <array>
#include <vector>

namespace lsr::detail {

/// @brief The best iterate of the time loop and what the later stages read beside it.
template <int D>
struct FrontOnMesh {
  VertexFields<D> at_vertex;
  std::vector<Location<D>> at;  ///< #N: where each data point lies in the mesh
  VertexNeighbours neighbours;
  P1Operators<D> ops;
  double band = 0.0;                 ///< the renormalisation's band
  std::vector<char> over_hole;       ///< #V: the discs nearer than the points; empty without discs
  std::vector<char> near_opening;    ///< #V: see attach_fit; empty without
  Eigen::VectorXd best;              ///< the best iterate
  bool best_is_distance = false;     ///< it was renormalised
};

/// @brief Whether x lies in the closed box [lo, hi] (a tile's region, its faces included).
template <int D>
bool in_closed_box(const Vec<D>& x, const Vec<D>& lo, const Vec<D>& hi) {
  return ((x - lo).array() >= 0.0).all() && ((hi - x).array() >= 0.0).all();
}

/// @brief Evolves the front from u0 (the caller's `custom_start`, or options.start's) on
/// `adaptive`'s mesh, whose forest locates the data and is then released (an anisotropic mesh
/// has none: the mesh alone locates). `point_scale` is the data's, raised to the mesh's sizes.
/// Fills the settings' and the loop's fields of `r`. With `tested` (a tile's core box, lo and
/// hi), the stopping test reads the data points in it and the front over its vertices only.
template <int D>
FrontOnMesh<D> front_on_mesh(const SampledData<D>& sampled, const std::vector<double>& point_scale, AdaptiveMesh<D>& adaptive,
                             const ReconstructionOptions& o, double hole_radius, const SignedDistance<D>* custom_start,
                             ReconstructionResult<D>& r, const Progress& progress, StageClock& clock,
                             const std::array<Vec<D>, 2>* tested = nullptr);

}  // namespace lsr::detail
