// SPDX-License-Identifier: BSD-3-Clause
/// @file mpi_tile_exchange.h
/// @brief The sampling stage (lsrecon/core/tile_exchange.h) shared among the ranks of an MPI
/// communicator (Debian's Open MPI): each rank holds its run of the cloud and a halo, and the
/// ranks exchange points and values with point-to-point messages. Rank 0 carries on with the
/// mesh, the front and the fit. A separate library (lsrecon::adapters_mpi), so that
/// lsrecon::adapters needs no MPI.
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
  /// The sizes by MPI_Alltoall, the bytes by MPI_Isend / MPI_Irecv in pieces of at most 1 GiB
  /// (MPI counts are ints).
  void all_to_all(std::vector<std::vector<unsigned char>>& buffers) const override;

 private:
  MPI_Comm comm_;
  int rank_ = 0;
  int size_ = 1;
};

}  // namespace lsr::adapters
