// SPDX-License-Identifier: BSD-3-Clause
/// @file unsupported_parts.cpp
#include "surface/unsupported_parts.h"

#include "geometry/nearest_point_index.h"
#include "graph/disjoint_sets.h"
#include "start/outside_flood_fill.h"

#include <algorithm>
#include <limits>

namespace lsr {

template <int D>
std::size_t drop_unsupported_parts(const SimplexMesh<D>& mesh, const LevelSetMesh<D>& surface,
                                   const Points<D>& points, std::vector<double>& values, int threads) {
  const std::size_t nv = values.size();
  if (surface.vertices.empty() || points.empty()) return 0;
  // One labelling for both signs: no edge joins a negative to a non-negative vertex in it.
  std::vector<char> negative(nv);
  for (std::size_t v = 0; v < nv; ++v) negative[v] = values[v] < 0.0;
  std::vector<Index> part = vertex_components(mesh, negative);
  std::vector<char> non_negative(nv);
  for (std::size_t v = 0; v < nv; ++v) non_negative[v] = !negative[v];
  const std::vector<Index> outer = vertex_components(mesh, non_negative);
  std::vector<char> outside(nv, 0);  // by root
  for (std::size_t v = 0; v < nv; ++v) {
    if (outer[v] >= 0) {
      part[v] = outer[v];
      if (on_wall<D>(mesh.vertices[v])) outside[std::size_t(outer[v])] = 1;
    }
  }
  std::vector<char> is_root(nv, 0);
  std::size_t parts = 0;
  for (std::size_t v = 0; v < nv; ++v) {
    const std::size_t p = std::size_t(part[v]);
    if (!outside[p] && !is_root[p]) parts += (is_root[p] = 1);
  }
  if (parts <= 1) return 0;  // the one solid (or nothing) bounds all the data

  std::vector<double> distance;
  std::vector<Index> nearest;
  NearestPointIndex<D>(surface.vertices).query(points, distance, &nearest, threads);
  std::vector<Index> owned(nv, 0);  // by root
  for (Index i : nearest) {
    const EdgePoint& e = surface.sources[std::size_t(i)];
    ++owned[std::size_t(part[e.a])];
    ++owned[std::size_t(part[e.b])];
  }
  std::size_t flipped = 0;
  for (std::size_t v = 0; v < nv; ++v) {
    const std::size_t p = std::size_t(part[v]);
    if (outside[p] || owned[p] > D) continue;
    values[v] = negative[v] ? -values[v] : -std::max(values[v], std::numeric_limits<double>::min());
    ++flipped;
  }
  return flipped;
}

template <int D>
std::size_t drop_unsupported_pieces(LevelSetMesh<D>& surface, const Points<D>& points, int threads) {
  const std::size_t nv = surface.vertices.size();
  if (nv == 0 || points.empty()) return 0;
  detail::DisjointSets sets(nv);
  for (const auto& f : surface.facets) {
    for (int k = 1; k < D; ++k) sets.unite(f[0], f[std::size_t(k)]);
  }
  const auto find = [&](Index v) { return sets.find(v); };
  std::vector<Index> owned(nv, 0);  // by root
  std::size_t pieces = 0;
  for (std::size_t v = 0; v < nv; ++v) pieces += find(Index(v)) == Index(v);
  if (pieces <= 1) return 0;
  std::vector<double> distance;
  std::vector<Index> nearest;
  NearestPointIndex<D>(surface.vertices).query(points, distance, &nearest, threads);
  for (Index i : nearest) ++owned[std::size_t(find(i))];
  std::vector<Index> renumbered(nv, -1);
  Points<D> kept;
  std::size_t dropped = 0;
  for (std::size_t v = 0; v < nv; ++v) {
    const Index p = find(Index(v));
    if (owned[std::size_t(p)] > D) {
      renumbered[v] = Index(kept.size());
      kept.push_back(surface.vertices[v]);
    } else {
      dropped += p == Index(v);
    }
  }
  if (dropped == 0) return 0;
  std::vector<std::array<Index, D>> facets;
  for (auto f : surface.facets) {
    if (renumbered[std::size_t(f[0])] < 0) continue;
    for (Index& v : f) v = renumbered[std::size_t(v)];
    facets.push_back(f);
  }
  surface.vertices = std::move(kept);
  surface.facets = std::move(facets);
  return dropped;
}

template std::size_t drop_unsupported_pieces<2>(LevelSetMesh<2>&, const Points<2>&, int);
template std::size_t drop_unsupported_pieces<3>(LevelSetMesh<3>&, const Points<3>&, int);
template std::size_t drop_unsupported_parts<2>(const SimplexMesh<2>&, const LevelSetMesh<2>&, const Points<2>&,
                                               std::vector<double>&, int);
template std::size_t drop_unsupported_parts<3>(const SimplexMesh<3>&, const LevelSetMesh<3>&, const Points<3>&,
                                               std::vector<double>&, int);

}  // namespace lsr
