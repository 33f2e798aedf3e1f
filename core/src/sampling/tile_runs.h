// SPDX-License-Identifier: BSD-3-Clause
/// @file tile_runs.h
/// @brief Which points a worker of the sampling stage computes, in which tiles, and how it shares
/// the per-point results (lsrecon/core/tile_exchange.h, docs/how-it-works.md "Tiles and MPI").
#pragma once

#include "lsrecon/core/tile_exchange.h"
#include "lsrecon/core/types.h"
#include "sampling/local_sampling.h"

#include <algorithm>
#include <numeric>
#include <vector>

namespace lsr {

// The tiles of n points among the workers (tile_exchange.h): worker w owns the points
// [begin[w], begin[w + 1]), this worker's tiles are [cuts[j], cuts[j + 1]).
struct TileRuns {
  std::vector<std::size_t> begin;
  std::vector<std::size_t> cuts;
  const TileExchange* exchange = nullptr;

  TileRuns(std::size_t n, const SamplingTiles& t) : exchange(t.exchange) {
    const std::size_t workers = exchange ? std::size_t(exchange->workers()) : 1;
    const std::size_t w = exchange ? std::size_t(exchange->worker()) : 0;
    const std::size_t tiles = std::max({std::size_t(std::max(t.tiles, 1)), workers});
    const auto tile_begin = [&](std::size_t j) { return j * n / tiles; };
    for (std::size_t v = 0; v <= workers; ++v) begin.push_back(tile_begin(v * tiles / workers));
    for (std::size_t j = w * tiles / workers; j <= (w + 1) * tiles / workers; ++j) cuts.push_back(tile_begin(j));
  }
  std::size_t first() const { return cuts.front(); }
  std::size_t end() const { return cuts.back(); }
  std::size_t workers() const { return begin.size() - 1; }
  // Every worker's points' values (plain data) to every worker.
  template <class T, class A>
  void share(std::vector<T, A>& values) const {
    if (workers() > 1) exchange->share(values.data(), sizeof(T), begin);
  }
  // The sum of every worker's value.
  long sum(long mine) const {
    if (workers() == 1) return mine;
    std::vector<long> each(workers(), 0);
    std::vector<std::size_t> slot(workers() + 1);
    for (std::size_t v = 0; v < slot.size(); ++v) slot[v] = v;
    each[std::size_t(exchange->worker())] = mine;
    exchange->share(each.data(), sizeof(long), slot);
    return std::accumulate(each.begin(), each.end(), 0L);
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
