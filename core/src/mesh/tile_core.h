// SPDX-License-Identifier: BSD-3-Clause
/// @file tile_core.h
/// @brief A tile's own part of a mesh: the simplices whose centroid lies in its core box. The
/// cores of a grid of tiles (half-open boxes covering [0,1]^D) partition every mesh of the box,
/// so tiles whose meshes agree in their cores (adaptive_refinement.h: the region) hold the
/// whole mesh between them, each simplex once.
#pragma once

#include "lsrecon/core/simplex_geometry.h"

#include <vector>

namespace lsr {

template <int D>
struct TileCore {
  SimplexMesh<D> mesh;        ///< the core's simplices over the vertices they use
  std::vector<Index> vertex;  ///< core vertex -> vertex of the tile's mesh
};

/// @brief The simplices of `mesh` flagged in `keep` (#simplices), in their order, over the
/// vertices they use in the mesh's order.
template <int D>
TileCore<D> select_simplices(const SimplexMesh<D>& mesh, const std::vector<char>& keep);

/// @brief The simplices of `mesh` whose centroid x has lo <= x < hi, in their order, over
/// their vertices in the mesh's order.
template <int D>
TileCore<D> tile_core(const SimplexMesh<D>& mesh, const Vec<D>& lo, const Vec<D>& hi);

}  // namespace lsr
