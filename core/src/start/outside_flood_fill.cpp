// SPDX-License-Identifier: BSD-3-Clause
/// @file outside_flood_fill.cpp
#include "start/outside_flood_fill.h"

#include "graph/disjoint_sets.h"

namespace lsr {

template <int D>
bool on_wall(const Vec<D>& x) {
  for (int k = 0; k < D; ++k) {
    if (x[k] <= 0.0 || x[k] >= 1.0) return true;
  }
  return false;
}

template <int D>
std::vector<Index> vertex_components(const SimplexMesh<D>& mesh, const std::vector<char>& member) {
  const std::size_t n = mesh.vertices.size();
  detail::DisjointSets sets(n);
  for (const auto& s : mesh.simplices) {
    for (int i = 0; i <= D; ++i) {
      if (!member[s[i]]) continue;
      for (int j = i + 1; j <= D; ++j) {
        if (member[s[j]]) sets.unite(s[i], s[j]);
      }
    }
  }
  std::vector<Index> root(n, -1);
  for (std::size_t v = 0; v < n; ++v) {
    if (member[v]) root[v] = sets.find(Index(v));
  }
  return root;
}

template <int D>
std::vector<char> flood_from_walls(const SimplexMesh<D>& mesh, const std::vector<char>& passable) {
  return flood_from_walls(mesh, vertex_components(mesh, passable));
}

template <int D>
std::vector<char> flood_from_walls(const SimplexMesh<D>& mesh, const std::vector<Index>& root) {
  std::vector<char> root_reached(root.size(), 0);
  for (std::size_t v = 0; v < root.size(); ++v) {
    if (root[v] >= 0 && on_wall<D>(mesh.vertices[v])) root_reached[root[v]] = 1;
  }
  std::vector<char> reached(root.size(), 0);
  for (std::size_t v = 0; v < root.size(); ++v) reached[v] = root[v] >= 0 && root_reached[root[v]];
  return reached;
}

template std::vector<Index> vertex_components<2>(const SimplexMesh<2>&, const std::vector<char>&);
template std::vector<Index> vertex_components<3>(const SimplexMesh<3>&, const std::vector<char>&);
template bool on_wall<2>(const Vec<2>&);
template bool on_wall<3>(const Vec<3>&);
template std::vector<char> flood_from_walls<2>(const SimplexMesh<2>&, const std::vector<char>&);
template std::vector<char> flood_from_walls<3>(const SimplexMesh<3>&, const std::vector<char>&);
template std::vector<char> flood_from_walls<2>(const SimplexMesh<2>&, const std::vector<Index>&);
template std::vector<char> flood_from_walls<3>(const SimplexMesh<3>&, const std::vector<Index>&);

}  // namespace lsr
