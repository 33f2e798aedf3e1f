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
  Index band_vertices = 0;   ///< vertices given their distance (those closer than the band)
};

/// @brief Replaces u (#V) by the signed distance to {u = 0} on vertices within `band` of it
/// and on the vertices of the simplices it crosses, by +-band beyond, keeping the sign of u
/// (0 counts as positive). Leaves u alone when it has no zero set.
///
/// Each vertex gets the exact point-to-segment / point-to-triangle distance to a facet that
/// closest-facet propagation finds: the vertices of the crossed simplices start with their own
/// facets, then every vertex takes the nearest of its neighbours' facets until nothing
/// improves, outwards up to the band. Exact wherever the closest facet of a vertex is the
/// closest of one of its neighbours (everywhere but within about an edge of the medial axis);
/// the work grows with the band, not with the mesh.
/// @param neighbours the mesh's vertex_neighbours()
/// @param band width of the band; infinity for every vertex
/// @param threads threads for the distance evaluations, 0 for all cores
template <int D>
RenormalizationReport<D> renormalize(const SimplexMesh<D>& mesh, const VertexNeighbours& neighbours,
                                     Eigen::VectorXd& u, double band, int threads = 0);

/// @brief The same, building the mesh's neighbours first (for one-off calls).
template <int D>
RenormalizationReport<D> renormalize(const SimplexMesh<D>& mesh, Eigen::VectorXd& u, double band,
                                     int threads = 0);

}  // namespace lsr
