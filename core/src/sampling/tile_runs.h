// SPDX-License-Identifier: BSD-3-Clause
/// @file tile_runs.h
/// @brief Which points a worker of the sampling stage computes, in which tiles, and how it shares
/// the per-point results (lsrecon/core/tile_exchange.h, docs/how-it-works.md "Tiles and MPI"):
/// with a halo, each worker gets its halo's.
#pragma once

#include "lsrecon/core/tile_exchange.h"
#include "lsrecon/core/types.h"
#include "sampling/cloud_halo.h"
#include "sampling/local_sampling.h"
#include "sampling/worker_collectives.h"

#include <algorithm>
#include <vector>

namespace lsr {

// This worker's points [first(), end()) in tiles [cuts[j], cuts[j + 1]): every point in one
// process, or the run of a halo.
struct TileRuns {
  std::vector<std::size_t> cuts;
  const CloudHalo* halo = nullptr;

  TileRuns(std::size_t n, const SamplingTiles& t) : halo(t.halo) {
    const std::size_t first = halo ? halo->first : 0, end = halo ? halo->end : n;
    const std::size_t tiles = std::size_t(std::max(t.tiles, 1));
    for (std::size_t j = 0; j <= tiles; ++j) cuts.push_back(first + j * (end - first) / tiles);
  }
  std::size_t first() const { return cuts.front(); }
  std::size_t end() const { return cuts.back(); }
  const TileExchange* exchange() const { return halo ? halo->exchange : nullptr; }
  // The global index of this worker's local point i, and the cloud's size.
  std::size_t global(std::size_t i) const { return halo ? i - halo->first + halo->global_first : i; }
  std::size_t global_size(std::size_t n) const { return halo ? halo->global_size : n; }
  // The values (plain data) the neighbours of this worker's points read.
  template <class T, class A>
  void share(std::vector<T, A>& values) const {
    if (halo) halo->share(values);
  }
  long sum(long mine) const { return sum_over_workers(exchange(), mine); }
  // The median of every point's value.
  double median(const std::vector<double>& values) const { return median_over_workers(exchange(), values.data() + first(), end() - first()); }
};

// The points [first, end) as queries: p itself when that is all of them.
template <int D>
const Points<D>& run_of(const Points<D>& p, std::size_t first, std::size_t end, Points<D>& copy) {
  if (first == 0 && end == p.size()) return p;
  copy.assign(p.begin() + long(first), p.begin() + long(end));
  return copy;
}

}  // namespace lsr
