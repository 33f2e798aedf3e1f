// SPDX-License-Identifier: BSD-3-Clause
/// @file mpi_tile_exchange.cpp
#include "lsrecon/adapters/mpi_tile_exchange.h"

#include "lsrecon/core/errors.h"

#include <algorithm>
#include <cstdint>
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

void MpiTileExchange::all_to_all(std::vector<std::vector<unsigned char>>& buffers) const {
  const std::size_t ranks = std::size_t(size_);
  std::vector<std::uint64_t> out_size(ranks), in_size(ranks);
  for (std::size_t v = 0; v < ranks; ++v) out_size[v] = buffers[v].size();
  check(MPI_Alltoall(out_size.data(), 1, MPI_UINT64_T, in_size.data(), 1, MPI_UINT64_T, comm_), "MPI_Alltoall");
  constexpr std::size_t kPiece = std::size_t(1) << 30;
  std::vector<std::vector<unsigned char>> in(ranks);
  std::vector<MPI_Request> requests;
  for (std::size_t v = 0; v < ranks; ++v) {
    if (v == std::size_t(rank_)) continue;
    in[v].resize(in_size[v]);
    for (std::size_t at = 0, piece = 0; at < in[v].size(); at += kPiece, ++piece) {
      requests.emplace_back();
      check(MPI_Irecv(in[v].data() + at, int(std::min(kPiece, in[v].size() - at)), MPI_BYTE, int(v), int(piece), comm_, &requests.back()),
            "MPI_Irecv");
    }
    for (std::size_t at = 0, piece = 0; at < buffers[v].size(); at += kPiece, ++piece) {
      requests.emplace_back();
      check(MPI_Isend(buffers[v].data() + at, int(std::min(kPiece, buffers[v].size() - at)), MPI_BYTE, int(v), int(piece), comm_,
                      &requests.back()),
            "MPI_Isend");
    }
  }
  check(MPI_Waitall(int(requests.size()), requests.data(), MPI_STATUSES_IGNORE), "MPI_Waitall");
  for (std::size_t v = 0; v < ranks; ++v) {
    if (v != std::size_t(rank_)) buffers[v] = std::move(in[v]);
  }
}

}  // namespace lsr::adapters
