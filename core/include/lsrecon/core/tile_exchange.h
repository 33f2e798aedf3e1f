// SPDX-License-Identifier: BSD-3-Clause
/// @file tile_exchange.h
/// @brief Tiles: the per-point work of the sampling stage (nearest neighbours, local PCA and
/// height fields, empty discs, rims: two thirds of a 10M-point scan's time) split into runs of
/// consecutive points along the data's Z-order curve, each a compact piece of space. Workers
/// (MPI ranks, say) each compute their own run of tiles; TileExchange::share then gives every
/// worker the whole per-point result, and worker 0 carries on with the mesh, the front and
/// the fit. Every point's result is what one process computes (the same neighbours, the same
/// arithmetic), so the output does not depend on the tiles or the workers. docs/how-it-works.md,
/// "Tiles and MPI", says what is shared and what is not yet.
#pragma once

#include <cstddef>
#include <vector>

namespace lsr {

/// @brief How workers share per-point results. The default is one worker, which has nothing
/// to share.
class TileExchange {
 public:
  virtual ~TileExchange() = default;
  /// This worker, in [0, workers()). Worker 0 carries on past the shared stages.
  virtual int worker() const { return 0; }
  virtual int workers() const { return 1; }
  /// A gather to all: values holds bytes_per_point bytes for each point, and worker w has
  /// filled those of the points [begin[w], begin[w + 1]) (begin has workers() + 1 entries).
  /// Afterwards every worker holds every point's. Called by every worker in the same order.
  virtual void share(void* /*values*/, std::size_t /*bytes_per_point*/, const std::vector<std::size_t>& /*begin*/) const {}
};

}  // namespace lsr
