// SPDX-License-Identifier: BSD-3-Clause
/// @file unsupported_parts.cpp
#include "surface/unsupported_parts.h"

#include "geometry/nearest_point_index.h"
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

template std::size_t drop_unsupported_parts<2>(const SimplexMesh<2>&, const LevelSetMesh<2>&, const Points<2>&,
                                               std::vector<double>&, int);
template std::size_t drop_unsupported_parts<3>(const SimplexMesh<3>&, const LevelSetMesh<3>&, const Points<3>&,
                                               std::vector<double>&, int);

}  // namespace lsr
