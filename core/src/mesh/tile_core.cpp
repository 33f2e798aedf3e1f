// SPDX-License-Identifier: BSD-3-Clause
/// @file tile_core.cpp
#include "mesh/tile_core.h"

namespace lsr {

template <int D>
TileCore<D> tile_core(const SimplexMesh<D>& mesh, const Vec<D>& lo, const Vec<D>& hi) {
  TileCore<D> out;
  std::vector<char> used(mesh.vertices.size(), 0);
  for (const auto& s : mesh.simplices) {
    Vec<D> c = Vec<D>::Zero();
    for (Index v : s) c += mesh.vertices[std::size_t(v)];
    c /= double(D + 1);
    if (((c - lo).array() < 0.0).any() || ((hi - c).array() <= 0.0).any()) continue;
    out.mesh.simplices.push_back(s);
    for (Index v : s) used[std::size_t(v)] = 1;
  }
  std::vector<Index> renumbered(mesh.vertices.size(), -1);
  for (std::size_t v = 0; v < used.size(); ++v) {
    if (!used[v]) continue;
    renumbered[v] = Index(out.vertex.size());
    out.vertex.push_back(Index(v));
    out.mesh.vertices.push_back(mesh.vertices[v]);
  }
  for (auto& s : out.mesh.simplices) {
    for (Index& v : s) v = renumbered[std::size_t(v)];
  }
  return out;
}

template TileCore<2> tile_core<2>(const SimplexMesh<2>&, const Vec<2>&, const Vec<2>&);
template TileCore<3> tile_core<3>(const SimplexMesh<3>&, const Vec<3>&, const Vec<3>&);

}  // namespace lsr
