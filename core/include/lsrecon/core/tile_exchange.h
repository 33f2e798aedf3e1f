// SPDX-License-Identifier: BSD-3-Clause
/// @file tile_exchange.h
/// @brief Workers (MPI ranks, say) that share the sampling stage: nearest neighbours, local
/// PCA and height fields, empty discs, rims (two thirds of a 10M-point scan's time). Each worker
/// passes reconstruct() its share of the cloud (consecutive runs of the input, in worker order);
/// the workers sort the cloud along its Z-order curve among them, each keeps a run of it plus
/// a margin of its neighbours (the halo), estimates its own points and exchanges the values the
/// others' halos read. Worker 0 then receives the cloud's sampling and carries on with the mesh,
/// the front and the fit. Every point's result is what one process computes (the same
/// neighbours, the same arithmetic), so the output does not depend on the workers.
/// docs/how-it-works.md, "Tiles and MPI", says what is shared and what is not yet.
#pragma once

#include <cstddef>
#include <vector>

namespace lsr {

/// @brief How workers exchange bytes. The default is one worker, which has nothing to send.
class TileExchange {
 public:
  virtual ~TileExchange() = default;
  /// This worker, in [0, workers()). Worker 0 carries on past the shared stages.
  virtual int worker() const { return 0; }
  virtual int workers() const { return 1; }
  /// All to all: buffers has workers() entries, buffers[v] the bytes for worker v (this
  /// worker's own entry included); afterwards buffers[v] holds the bytes worker v sent this
  /// one. Called by every worker in the same order.
  virtual void all_to_all(std::vector<std::vector<unsigned char>>& /*buffers*/) const {}
};

}  // namespace lsr
