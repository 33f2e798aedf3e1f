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

/// @brief The field of the fitted surface on `mesh`, from the front u (a signed distance near
/// its zero set) and the fit F. Only vertices flagged in `fitted` (all when empty) take F: a
/// tile's fit covers its region alone (tiles/tiled_solve.h).
template <int D>
FittedField fitted_field(const SimplexMesh<D>& mesh, const VertexNeighbours& neighbours, const QuadricImplicit<D>& fit,
                         const Eigen::VectorXd& u, const Eigen::VectorXd& scale, const Eigen::VectorXd& distance,
                         double trust_factor, const std::vector<char>& over_hole, const std::vector<char>& near_opening,
                         const NearestPointIndex<D>& data, const Points<D>& normals, int threads,
                         const std::vector<char>& fitted = {});

}  // namespace lsr::detail
