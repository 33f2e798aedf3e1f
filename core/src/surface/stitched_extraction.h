// SPDX-License-Identifier: BSD-3-Clause
/// @file stitched_extraction.h
/// @brief The zero set of a field solved in tiles, as one surface: each tile extracts its
/// core (tile_core.h) and the pieces are welded where their edges coincide.
///
/// Two tiles' cores share the faces of their seam, so a seam edge is crossed in both pieces.
/// The pieces meet there when both tiles read the same values at the edge's ends: each vertex's
/// value is its owner's, one tile's (the caller's exchange). Then the welded surface is closed
/// and manifold wherever the pieces are, as the extraction of the whole mesh is; it is that
/// extraction, up to the numbering and the last bits of seam points' coordinates.
#pragma once

#include "geometry/coordinate_hash.h"
#include "lsrecon/core/level_set_extraction.h"

#include <array>
#include <unordered_map>
#include <vector>

namespace lsr {

/// @brief One tile: its core's simplices and a value per core vertex (the owner's on the seams).
template <int D>
struct TileField {
  SimplexMesh<D> core;
  std::vector<double> u;
};

/// @brief {u = 0} over tiles added one at a time: the surface grows by each tile's piece,
/// welded to the earlier pieces by the coordinates of its points' edge ends, so that only the
/// surface and the welding map are held, not the tiles. A point is placed on its edge from the
/// end that is lower in lexicographic order, so the same edge gives the same point in every tile
/// (with other values at its ends, the first tile's point; with other signs, an edge crossed in
/// one tile only: a hole). Vertices are numbered as the tiles first reach them, in order; facets
/// follow the tiles. `sources` stays empty (the edges are the tiles').
template <int D>
class StitchedSurface {
 public:
  explicit StitchedSurface(double edge_margin = 1e-9, int threads = 0);
  /// @throw InvalidInput as extract_zero_level_set.
  void add(const TileField<D>& tile);
  LevelSetMesh<D> take() { return std::move(out_); }

 private:
  using EdgeKey = std::array<double, 2 * D>;
  double edge_margin_;
  int threads_;
  LevelSetMesh<D> out_;
  std::unordered_map<EdgeKey, Index, CoordinateHash<2 * D>> welded_;
};

/// @brief {u = 0} over the tiles (StitchedSurface, every tile in order).
/// @throw InvalidInput as extract_zero_level_set, for any tile.
template <int D>
LevelSetMesh<D> stitched_zero_level_set(const std::vector<TileField<D>>& tiles, double edge_margin = 1e-9, int threads = 0);

}  // namespace lsr
