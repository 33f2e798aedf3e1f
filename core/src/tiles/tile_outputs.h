// SPDX-License-Identifier: BSD-3-Clause
/// @file tile_outputs.h
/// @brief What a solved tile gives the weld (tiles/tiled_solve.h), and its way from the workers
/// that solved the tiles to worker 0 (lsrecon/core/tile_exchange.h): each worker solves every
/// workers()-th tile, worker 0 welds them all, in tile order, so that the output does not
/// depend on the workers.
#pragma once

#include "lsrecon/core/level_set_reconstruction.h"
#include "lsrecon/core/tile_exchange.h"
#include "surface/stitched_extraction.h"

#include <array>
#include <cstddef>
#include <vector>

namespace lsr::detail {

/// @brief A tile's loop and mesh fields (ReconstructionResult's), and the sizes of its arrays;
/// plain bytes, sent as such.
struct TileSummary {
  int tile = 0;
  ReconstructionStatus status = ReconstructionStatus::not_converged;
  bool stalled = false, tagged_start = false;
  int iterations = 0, best_iteration = 0, sealed_cavities = 0;
  double residual = 0.0, tolerance = 0.0, h_min = 0.0, time_step = 0.0, alpha = 0.0, curvature_weight = 0.0;
  std::size_t unreached_points = 0;
  Index mesh_vertices = 0, mesh_simplices = 0, open_side_points = 0;
  long solver_iterations = 0;
  std::size_t owned_points = 0, seam_vertices = 0, shell_vertices = 0, shell_simplices = 0;
};

template <int D>
struct SeamValue {
  std::array<double, D> x;
  double u;
};

template <int D>
struct TileOutput {
  TileSummary summary;
  Points<D> normals;               ///< the data points in its core, in order: normals oriented by its front
  std::vector<double> on_data;     ///< and u there
  std::vector<SeamValue<D>> seam;  ///< its vertices that other tiles' cores read, with its values
  TileField<D> shell;              ///< its core simplices near the front, with its values
};

template <int D>
TileSummary tile_summary(const ReconstructionResult<D>& r, int tile);

/// @brief Adds a tile's fields to the whole result: the largest mesh, the most steps, the
/// worst status and residual.
template <int D>
void add_tile_summary(ReconstructionResult<D>& r, const TileSummary& t, bool first);

/// @brief Worker 0 gets every worker's tiles (`mine`, each summary's sizes set), in tile order;
/// the other workers get none. One worker: `mine` unchanged.
template <int D>
std::vector<TileOutput<D>> gather_tile_outputs(const TileExchange* x, std::vector<TileOutput<D>> mine);

}  // namespace lsr::detail
