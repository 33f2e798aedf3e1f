// SPDX-License-Identifier: BSD-3-Clause
/// @file surface_topology.cpp
#include "surface/surface_topology.h"

#include "graph/disjoint_sets.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <map>
#include <unordered_map>

namespace lsr {
namespace {

std::uint64_t edge_key(Index a, Index b) {
  if (a > b) std::swap(a, b);
  return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b);
}

struct EdgeUse {
  int count = 0;
  int forward = 0;  // uses as a -> b with a < b
  Index first_face = -1;
};

}  // namespace

SurfaceTopology analyze_surface(const Points<3>& vertices,
                                const std::vector<std::array<Index, 3>>& triangles) {
  SurfaceTopology t;
  const std::size_t nf = triangles.size();
  std::unordered_map<std::uint64_t, EdgeUse> edges;
  edges.reserve(nf * 2);
  detail::DisjointSets faces(nf);
  for (std::size_t f = 0; f < nf; ++f) {
    const auto& tri = triangles[f];
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) ++t.degenerate_triangles;
    for (int k = 0; k < 3; ++k) {
      const Index a = tri[k];
      const Index b = tri[(k + 1) % 3];
      EdgeUse& e = edges[edge_key(a, b)];
      ++e.count;
      e.forward += a < b ? 1 : 0;
      if (e.first_face < 0) {
        e.first_face = Index(f);
      } else {
        faces.unite(Index(f), e.first_face);
      }
    }
    const Vec<3>& p = vertices[tri[0]];
    t.signed_volume += p.dot(vertices[tri[1]].cross(vertices[tri[2]])) / 6.0;
  }
  t.watertight = nf > 0;
  t.edge_manifold = true;
  t.oriented = true;
  for (const auto& [key, e] : edges) {
    t.watertight = t.watertight && e.count == 2;
    t.edge_manifold = t.edge_manifold && e.count <= 2;
    t.oriented = t.oriented && e.forward <= 1 && e.count - e.forward <= 1;
  }

  // Vertex manifoldness: the triangles around a vertex, linked through shared edges at that
  // vertex, must form a single fan.
  std::vector<std::vector<std::size_t>> around(vertices.size());
  for (std::size_t f = 0; f < nf; ++f) {
    for (Index v : triangles[f]) around[v].push_back(f);
  }
  t.vertex_manifold = true;
  for (std::size_t v = 0; v < around.size() && t.vertex_manifold; ++v) {
    const auto& fan = around[v];
    if (fan.size() < 2) continue;
    detail::DisjointSets local(fan.size());
    std::map<Index, std::size_t> by_other;  // other endpoint of an edge at v -> a face using it
    for (std::size_t i = 0; i < fan.size(); ++i) {
      for (Index w : triangles[fan[i]]) {
        if (w == Index(v)) continue;
        auto [it, inserted] = by_other.emplace(w, i);
        if (!inserted) local.unite(Index(i), Index(it->second));
      }
    }
    for (std::size_t i = 1; i < fan.size(); ++i) {
      if (local.find(Index(i)) != 0) t.vertex_manifold = false;
    }
  }

  // Components and per-component Euler characteristic V - E + F.
  std::map<std::size_t, std::array<long, 3>> vef;  // component root -> (V, E, F)
  std::vector<std::size_t> vertex_component(vertices.size(), SIZE_MAX);
  for (std::size_t f = 0; f < nf; ++f) {
    const auto c = std::size_t(faces.find(Index(f)));
    ++vef[c][2];
    for (Index v : triangles[f]) vertex_component[v] = c;
  }
  for (std::size_t v = 0; v < vertices.size(); ++v) {
    if (vertex_component[v] != SIZE_MAX) ++vef[vertex_component[v]][0];
  }
  for (const auto& [key, e] : edges) ++vef[std::size_t(faces.find(e.first_face))][1];
  t.components = int(vef.size());
  for (const auto& [root, c] : vef) t.genus.push_back(int((2 - (c[0] - c[1] + c[2])) / 2));
  return t;
}

}  // namespace lsr
