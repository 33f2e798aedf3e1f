// SPDX-License-Identifier: BSD-3-Clause
/// @file renormalization.h
/// @brief Renormalisation (paper section 6.3): replace u by the signed distance to its own
/// piecewise-linear zero set, so that |grad u| stays close to 1.
#pragma once

#include "lsrecon/core/level_set_extraction.h"

#include <Eigen/Core>

namespace lsr {

/// @brief What renormalize() did.
template <int D>
struct RenormalizationReport {
  LevelSetMesh<D> front;     ///< the zero set the distances were measured to
  Index band_vertices = 0;   ///< vertices given their exact distance
};

/// @brief Replaces u (#V) by the signed distance to {u = 0} on vertices within `band` of it
/// and by +-band beyond, keeping the sign of u (0 counts as positive). Distances are exact
/// point-to-segment / point-to-triangle distances to the nearest facets (a kd-tree over the
/// facet centroids proposes the candidates). Leaves u alone when it has no zero set.
/// @param gradient_norm #V: |grad u| per vertex; |u| / |grad u| estimates the distance that
/// picks the vertices to compute (those below 2 band).
/// @param threads threads for the queries, 0 for all cores
template <int D>
RenormalizationReport<D> renormalize(const SimplexMesh<D>& mesh, Eigen::VectorXd& u,
                                  const Eigen::VectorXd& gradient_norm, double band,
                                  int threads = 0);

}  // namespace lsr
