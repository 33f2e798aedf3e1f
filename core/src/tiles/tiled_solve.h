// SPDX-License-Identifier: BSD-3-Clause
/// @file tiled_solve.h
/// @brief Stages 4 to 8 in tiles (LimitOptions::solve_tiles): the unit box cut into k^D core
/// boxes; each tile meshes its core plus a margin at the data's sizes and the rest of the box
/// at a coarse size, runs the front on that mesh alone (its own tagged start: the coarse part
/// carries the inside/outside decision to its walls), with the fit puts the fit's field in its
/// region, and keeps the field's shell in its core. The shells' zero sets are welded into one
/// surface, every seam vertex taking its owner tile's value. One tile's mesh is held at a time;
/// workers (LimitOptions::exchange) share the tiles. docs/how-it-works.md, "Tiles and MPI".
#pragma once

#include "lsrecon/core/level_set_extraction.h"
#include "lsrecon/core/level_set_reconstruction.h"
#include "lsrecon/core/progress.h"
#include "sampling/sampled_data.h"
#include "stage_clock.h"

namespace lsr::detail {

/// @brief The core box of tile `t` of k^D (half-open; the last along an axis reaches past 1)
/// and its region, the core widened by `margin` (clipped to the box).
template <int D>
struct TileBox {
  Vec<D> lo, hi;
  Vec<D> region_lo, region_hi;
};

template <int D>
TileBox<D> tile_box(int t, int k, double margin);

/// @brief The welded field of the tiles (the fit's, or the front's at one level), and each data
/// point's normal oriented by its owner tile's front (for the fit).
template <int D>
struct TiledFront {
  LevelSetMesh<D> surface;  ///< unit box; `sources` empty
  Points<D> normals;        ///< #N, unit box
  double level = 0.0;       ///< the level extracted: the median of u at the data, or 0 (with the fit; unit box)
  Index seam_mismatches = 0;  ///< seam vertices no owner gave a value for (0 when the meshes agree)
};

/// @brief The front in o.limits.solve_tiles^D tiles, from u0 (`custom_start` or options.start's).
/// Fills r's mesh and loop fields with the largest tile's mesh, the most steps, the worst status
/// and residual; r.status is cancelled (and the surface empty) if a tile was, and shared on
/// workers other than 0 (their tiles sent to worker 0).
template <int D>
TiledFront<D> solve_in_tiles(const SampledData<D>& sampled, const ReconstructionOptions& o, double hole_radius, Index max_vertices,
                             const SignedDistance<D>* custom_start, ReconstructionResult<D>& r, const Progress& progress, StageClock& clock);

}  // namespace lsr::detail
