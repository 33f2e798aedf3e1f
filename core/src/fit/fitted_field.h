// SPDX-License-Identifier: BSD-3-Clause
/// @file fitted_field.h
/// @brief The fit's field on the mesh: F replaces u on the band of vertices near the front where
/// the two agree or the front is near the data, within what the front decided (merges that join
/// nothing, cut-off voids filled, specks absorbed).
#pragma once

#include "fit/quadric_implicit.h"
#include "geometry/nearest_point_index.h"
#include "lsrecon/core/simplex_geometry.h"

#include <Eigen/Core>

#include <vector>

namespace lsr::detail {

// Past the largest empty disc among random samples (1.45 local scales, local_sampling.h) no
// sample supports the surface: there the fit extrapolates and the front is held by curvature
// alone (so the merge may join there too).
constexpr double kUnsupported = 1.5;

struct FittedField {
  std::vector<double> values;     ///< #V: the field whose zero set is the surface
  std::vector<double> fit_share;  ///< #V near a sealed opening: how far to project onto F; empty without
};

/// @brief What the fit reads of the front that evolved on `mesh` (references: they outlive the fit).
template <int D>
struct FrontToFit {
  const SimplexMesh<D>& mesh;
  const VertexNeighbours& neighbours;
  const Eigen::VectorXd& u;             ///< #V: the front, a signed distance near its zero set
  const Eigen::VectorXd& scale;         ///< #V: the local scale
  const Eigen::VectorXd& distance;      ///< #V: to the nearest data point
  const std::vector<char>& over_hole;   ///< #V: over a spanned hole; empty without
  const std::vector<char>& near_opening;  ///< #V: near a sealed opening; empty without
  const NearestPointIndex<D>& data;
  const Points<D>& normals;             ///< the data's, oriented outwards
  double trust_factor;                  ///< gap factor: beyond it, in local scales, no sample supports F
  int threads;
};

/// @brief The field of the fitted surface on the front's mesh, from the front u and the fit F.
/// Only vertices flagged in `fitted` (all when empty) take F: a tile's fit covers its region
/// alone (tiles/tiled_solve.h).
template <int D>
FittedField fitted_field(const FrontToFit<D>& front, const QuadricImplicit<D>& fit, const std::vector<char>& fitted = {});

}  // namespace lsr::detail
