// SPDX-License-Identifier: BSD-3-Clause
/// @file tile_core.cpp
#include "mesh/tile_core.h"

namespace lsr {

template <int D>
TileCore<D> select_simplices(const SimplexMesh<D>& mesh, const std::vector<char>& keep) {
  TileCore<D> out;
  std::vector<Index> renumbered(mesh.vertices.size(), -1);
  for (std::size_t s = 0; s < mesh.simplices.size(); ++s) {
    if (!keep[s]) continue;
    out.mesh.simplices.push_back(mesh.simplices[s]);
    for (Index v : mesh.simplices[s]) renumbered[std::size_t(v)] = 0;
  }
  for (std::size_t v = 0; v < renumbered.size(); ++v) {
    if (renumbered[v] < 0) continue;
    renumbered[v] = Index(out.vertex.size());
    out.vertex.push_back(Index(v));
    out.mesh.vertices.push_back(mesh.vertices[v]);
  }
  for (auto& s : out.mesh.simplices) {
    for (Index& v : s) v = renumbered[std::size_t(v)];
  }
  return out;
}

template <int D>
TileCore<D> tile_core(const SimplexMesh<D>& mesh, const Vec<D>& lo, const Vec<D>& hi) {
  std::vector<char> keep(mesh.simplices.size(), 0);
  for (std::size_t i = 0; i < keep.size(); ++i) {
    Vec<D> c = Vec<D>::Zero();
    for (Index v : mesh.simplices[i]) c += mesh.vertices[std::size_t(v)];
    c /= double(D + 1);
    keep[i] = ((c - lo).array() >= 0.0).all() && ((hi - c).array() > 0.0).all();
  }
  return select_simplices(mesh, keep);
}

template TileCore<2> select_simplices<2>(const SimplexMesh<2>&, const std::vector<char>&);
template TileCore<3> select_simplices<3>(const SimplexMesh<3>&, const std::vector<char>&);
template TileCore<2> tile_core<2>(const SimplexMesh<2>&, const Vec<2>&, const Vec<2>&);
template TileCore<3> tile_core<3>(const SimplexMesh<3>&, const Vec<3>&, const Vec<3>&);

}  // namespace lsr
