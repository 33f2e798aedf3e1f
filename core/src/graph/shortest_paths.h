// SPDX-License-Identifier: BSD-3-Clause
/// @file shortest_paths.h
/// @brief Path lengths over a graph's edges (Dijkstra), each edge as long as the distance
/// between its ends: the one weighted flood of the core (from the box walls through the
/// flooded mesh, from a rim over the unsupported surface).
#pragma once

#include "lsrecon/core/types.h"

#include <functional>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

namespace lsr::detail {

/// @brief Per vertex, the length of the shortest path from a source through passable vertices;
/// +infinity where none reaches. The graph is given as adjacency lists: v's neighbours are
/// next[first[v]] to next[first[v + 1] - 1]. Equal lengths are taken by vertex index, so the
/// result does not depend on the order of the lists' sources.
/// @param positions #V vertex positions (the edges' lengths)
/// @param sources #V where paths start (length 0)
/// @param passable #V the vertices a path may enter
template <class Positions, class First, class Next>
std::vector<double> shortest_paths(const Positions& positions, const First& first, const Next& next,
                                   const std::vector<char>& sources, const std::vector<char>& passable) {
  const std::size_t nv = positions.size();
  std::vector<double> length(nv, std::numeric_limits<double>::infinity());
  using Entry = std::pair<double, Index>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
  for (std::size_t v = 0; v < nv; ++v) {
    if (!sources[v]) continue;
    length[v] = 0.0;
    queue.emplace(0.0, Index(v));
  }
  while (!queue.empty()) {
    const auto [lv, v] = queue.top();
    queue.pop();
    if (lv > length[std::size_t(v)]) continue;  // a stale entry
    for (auto k = first[std::size_t(v)]; k < first[std::size_t(v) + 1]; ++k) {
      const auto w = std::size_t(next[std::size_t(k)]);
      if (!passable[w]) continue;
      const double lw = lv + (positions[w] - positions[std::size_t(v)]).norm();
      if (lw < length[w]) {
        length[w] = lw;
        queue.emplace(lw, Index(w));
      }
    }
  }
  return length;
}

}  // namespace lsr::detail
