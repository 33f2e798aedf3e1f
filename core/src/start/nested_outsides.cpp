// SPDX-License-Identifier: BSD-3-Clause
/// @file nested_outsides.cpp
#include "start/nested_outsides.h"

#include <algorithm>
#include <deque>
#include <tuple>
#include <utility>

namespace lsr::detail {

template <int D>
std::vector<char> nested_outsides(const SimplexMesh<D>& mesh, const VertexNeighbours& neighbours,
                                  const std::vector<Index>& region, const std::vector<char>& reached,
                                  const Points<D>& points, const Points<D>& normals, const std::vector<Index>& nearest) {
  const std::size_t nv = mesh.vertices.size();
  std::vector<char> out(nv, 0);
  std::size_t enclosed_regions = 0;  // free, not flooded: one is inside the data, depth 2 needs two
  for (std::size_t v = 0; v < nv; ++v) enclosed_regions += region[v] == Index(v) && !reached[v];
  if (enclosed_regions < 2) return out;

  // (point, region, side) for every free vertex on a band's edge, the side along the normal.
  std::vector<std::tuple<Index, Index, int>> faces;
  for (std::size_t v = 0; v < nv; ++v) {
    if (region[v] < 0) continue;
    bool edge = false;
    for (Index k = neighbours.offsets[v]; k < neighbours.offsets[v + 1] && !edge; ++k) {
      edge = region[std::size_t(neighbours.neighbours[std::size_t(k)])] < 0;
    }
    if (!edge) continue;
    const auto p = std::size_t(nearest[v]);
    const double s = (mesh.vertices[v] - points[p]).dot(normals[p]);
    if (s != 0.0) faces.emplace_back(Index(p), region[v], s > 0.0 ? 1 : -1);
  }
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());

  // Regions across a sheet from each other: facing a point from opposite sides.
  std::vector<std::pair<Index, Index>> pairs;
  for (std::size_t i = 0; i < faces.size();) {
    std::size_t j = i;
    while (j < faces.size() && std::get<0>(faces[j]) == std::get<0>(faces[i])) ++j;
    for (std::size_t a = i; a < j; ++a) {
      for (std::size_t b = i; b < j; ++b) {
        const Index r = std::get<1>(faces[a]), q = std::get<1>(faces[b]);
        if (r != q && std::get<2>(faces[a]) != std::get<2>(faces[b])) pairs.emplace_back(r, q);
      }
    }
    i = j;
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());

  // Depths: breadth first from the flood's regions.
  constexpr int kUnseen = -1;
  std::vector<int> depth(nv, kUnseen);
  std::deque<Index> queue;
  for (std::size_t v = 0; v < nv; ++v) {
    const Index r = region[v];
    if (r >= 0 && reached[v] && depth[std::size_t(r)] == kUnseen) {
      depth[std::size_t(r)] = 0;
      queue.push_back(r);
    }
  }
  while (!queue.empty()) {
    const auto r = std::size_t(queue.front());
    queue.pop_front();
    const auto across = std::equal_range(pairs.begin(), pairs.end(), std::make_pair(Index(r), Index(0)),
                                         [](const auto& x, const auto& y) { return x.first < y.first; });
    for (auto it = across.first; it != across.second; ++it) {
      const Index q = it->second;
      if (depth[std::size_t(q)] != kUnseen) continue;
      depth[std::size_t(q)] = depth[r] + 1;
      queue.push_back(q);
    }
  }
  for (std::size_t v = 0; v < nv; ++v) {
    const Index r = region[v];
    if (r < 0 || reached[v]) continue;
    const int d = depth[std::size_t(r)];
    out[v] = d > 0 && d % 2 == 0;
  }
  return out;
}

template std::vector<char> nested_outsides<2>(const SimplexMesh<2>&, const VertexNeighbours&, const std::vector<Index>&,
                                              const std::vector<char>&, const Points<2>&, const Points<2>&,
                                              const std::vector<Index>&);
template std::vector<char> nested_outsides<3>(const SimplexMesh<3>&, const VertexNeighbours&, const std::vector<Index>&,
                                              const std::vector<char>&, const Points<3>&, const Points<3>&,
                                              const std::vector<Index>&);

}  // namespace lsr::detail
