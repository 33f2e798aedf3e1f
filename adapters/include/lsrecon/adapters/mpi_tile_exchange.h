// SPDX-License-Identifier: BSD-3-Clause
/// @file mpi_tile_exchange.h
/// @brief The tiles of the sampling stage (lsrecon/core/tile_exchange.h) shared among the ranks
/// of an MPI communicator (Debian's Open MPI): each rank estimates its own run of points, then
/// an all-gather gives every rank all of them. Rank 0 carries on with the mesh, the front and
/// the fit. A separate library (lsrecon::adapters_mpi), so that lsrecon::adapters needs no MPI.
#pragma once

#include "lsrecon/core/tile_exchange.h"

#include <mpi.h>

namespace lsr::adapters {

class MpiTileExchange : public TileExchange {
 public:
  /// comm: the ranks that share the tiles; MPI must be initialised, and stay so while this lives.
  explicit MpiTileExchange(MPI_Comm comm = MPI_COMM_WORLD);
  int worker() const override;
  int workers() const override;
  /// MPI_Allgatherv in place, counted in points (a contiguous type of bytes_per_point bytes), so
  /// that no count overflows MPI's int below 2^31 points per rank.
  void share(void* values, std::size_t bytes_per_point, const std::vector<std::size_t>& begin) const override;

 private:
  MPI_Comm comm_;
  int rank_ = 0;
  int size_ = 1;
};

}  // namespace lsr::adapters
