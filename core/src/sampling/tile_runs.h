// SPDX-License-Identifier: BSD-3-Clause
/// @file tile_runs.h
/// @brief Which points a worker of the sampling stage computes, in which tiles, and how it shares
/// the per-point results (lsrecon/core/tile_exchange.h, docs/how-it-works.md "Tiles and MPI"):
/// with the whole cloud, every worker gets every point's; with a halo, each gets its halo's.
#pragma once

#include "lsrecon/core/tile_exchange.h"
#include "lsrecon/core/types.h"
#include "sampling/cloud_halo.h"
#include "sampling/local_sampling.h"
#include "sampling/worker_collectives.h"

#include <algorithm>
#include <vector>

namespace lsr {

// This worker's points [first(), end()) in tiles [cuts[j], cuts[j + 1]).
struct TileRuns {
  std::vector<std::size_t> begin;  // whole cloud: worker w owns [begin[w], begin[w + 1])
  std::vector<std::size_t> cuts;
  const TileExchange* exchange = nullptr;
  const CloudHalo* halo = nullptr;

  TileRuns(std::size_t n, const SamplingTiles& t) : exchange(t.exchange), halo(t.halo) {
    const std::size_t workers = workers_of(exchange), w = worker_of(exchange);
    if (halo) {
      const std::size_t tiles = std::max<std::size_t>(1, std::size_t(std::max(t.tiles, 1)) / workers);
      for (std::size_t j = 0; j <= tiles; ++j) cuts.push_back(halo->first + j * (halo->end - halo->first) / tiles);
      return;
    }
    const std::size_t tiles = std::max({std::size_t(std::max(t.tiles, 1)), workers});
    const auto tile_begin = [&](std::size_t j) { return j * n / tiles; };
    for (std::size_t v = 0; v <= workers; ++v) begin.push_back(tile_begin(v * tiles / workers));
    for (std::size_t j = w * tiles / workers; j <= (w + 1) * tiles / workers; ++j) cuts.push_back(tile_begin(j));
  }
  std::size_t first() const { return cuts.front(); }
  std::size_t end() const { return cuts.back(); }
  // The global index of this worker's local point i, and the cloud's size.
  std::size_t global(std::size_t i) const { return halo ? i - halo->first + halo->global_first : i; }
  std::size_t global_size(std::size_t n) const { return halo ? halo->global_size : n; }
  // The values (plain data) this worker's points' neighbours read.
  template <class T, class A>
  void share(std::vector<T, A>& values) const {
    if (halo) return halo->share(values);
    const std::size_t workers = workers_of(exchange), me = worker_of(exchange);
    if (workers == 1) return;
    const std::vector<T> mine(values.begin() + long(first()), values.begin() + long(end()));
    const std::vector<std::vector<T>> in = exchange_values(exchange, std::vector<std::vector<T>>(workers, mine));
    for (std::size_t u = 0; u < workers; ++u) {
      if (u != me) std::copy(in[u].begin(), in[u].end(), values.begin() + long(begin[u]));
    }
  }
  long sum(long mine) const { return sum_over_workers(exchange, mine); }
  // The median of every point's value.
  double median(const std::vector<double>& values) const {
    return median_over_workers(exchange, values.data() + first(), end() - first());
  }
};

// The points [first, end) as queries: p itself when that is all of them.
template <int D>
const Points<D>& run_of(const Points<D>& p, std::size_t first, std::size_t end, Points<D>& copy) {
  if (first == 0 && end == p.size()) return p;
  copy.assign(p.begin() + long(first), p.begin() + long(end));
  return copy;
}

}  // namespace lsr
