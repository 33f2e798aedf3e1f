// SPDX-License-Identifier: BSD-3-Clause
/// @file mpi_tile_exchange.cpp
#include "lsrecon/adapters/mpi_tile_exchange.h"

#include "lsrecon/core/errors.h"

#include <climits>
#include <string>

namespace lsr::adapters {
namespace {

void check(int code, const char* what) {
  if (code == MPI_SUCCESS) return;
  char text[MPI_MAX_ERROR_STRING];
  int length = 0;
  MPI_Error_string(code, text, &length);
  throw Error(std::string(what) + " failed: " + std::string(text, std::size_t(length)), "check the MPI installation and the ranks' network");
}

}  // namespace

MpiTileExchange::MpiTileExchange(MPI_Comm comm) : comm_(comm) {
  check(MPI_Comm_rank(comm_, &rank_), "MPI_Comm_rank");
  check(MPI_Comm_size(comm_, &size_), "MPI_Comm_size");
}

int MpiTileExchange::worker() const { return rank_; }
int MpiTileExchange::workers() const { return size_; }

void MpiTileExchange::share(void* values, std::size_t bytes_per_point, const std::vector<std::size_t>& begin) const {
  std::vector<int> count(static_cast<std::size_t>(size_)), offset(static_cast<std::size_t>(size_));
  for (std::size_t w = 0; w < std::size_t(size_); ++w) {
    if (begin[w + 1] - begin[w] > std::size_t(INT_MAX) || begin[w] > std::size_t(INT_MAX)) {
      throw ResourceLimit("more than 2^31 - 1 points to gather over MPI", "split the cloud into parts of fewer points");
    }
    count[w] = int(begin[w + 1] - begin[w]);
    offset[w] = int(begin[w]);
  }
  MPI_Datatype point;
  check(MPI_Type_contiguous(int(bytes_per_point), MPI_BYTE, &point), "MPI_Type_contiguous");
  check(MPI_Type_commit(&point), "MPI_Type_commit");
  const int code = MPI_Allgatherv(MPI_IN_PLACE, 0, MPI_DATATYPE_NULL, values, count.data(), offset.data(), point, comm_);
  MPI_Type_free(&point);
  check(code, "MPI_Allgatherv");
}

}  // namespace lsr::adapters
