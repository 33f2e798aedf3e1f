// SPDX-License-Identifier: BSD-3-Clause
/// @file cavity_sealing.cpp
#include "start/cavity_sealing.h"

#include "start/outside_flood_fill.h"

#include <queue>
#include <utility>

namespace lsr {
namespace {

// Per vertex, whether a data-free ball centred on a `centre` vertex covers it. Each vertex
// keeps the ball that reaches past it the farthest (its witness) and hands it on to its
// neighbours, best first: exact wherever the mesh paths inside a ball reach its vertices,
// which a mesh finer than the balls (sized by the data, coarser only far from it) ensures.
template <int D>
std::vector<char> covered_by_balls(const SimplexMesh<D>& mesh, const VertexNeighbours& n, const Eigen::VectorXd& clearance,
                                   const std::vector<char>& centre, const std::vector<char>& domain) {
  const std::size_t nv = mesh.vertices.size();
  std::vector<double> reach(nv, 0.0);
  std::vector<Index> witness(nv, -1);
  std::priority_queue<std::pair<double, Index>> queue;  // ties by index: deterministic
  for (std::size_t v = 0; v < nv; ++v) {
    if (!centre[v]) continue;
    reach[v] = clearance[Eigen::Index(v)];
    witness[v] = Index(v);
    queue.emplace(reach[v], Index(v));
  }
  while (!queue.empty()) {
    const auto [r, v] = queue.top();
    queue.pop();
    if (r < reach[std::size_t(v)]) continue;  // a stale entry
    const Index c = witness[std::size_t(v)];
    for (Index k = n.offsets[std::size_t(v)]; k < n.offsets[std::size_t(v) + 1]; ++k) {
      const Index w = n.neighbours[std::size_t(k)];
      if (!domain[std::size_t(w)] || centre[std::size_t(w)]) continue;
      const double left = clearance[c] - (mesh.vertices[std::size_t(w)] - mesh.vertices[std::size_t(c)]).norm();
      if (left <= reach[std::size_t(w)]) continue;
      reach[std::size_t(w)] = left;
      witness[std::size_t(w)] = c;
      queue.emplace(left, w);
    }
  }
  std::vector<char> covered(nv);
  for (std::size_t v = 0; v < nv; ++v) covered[v] = centre[v] || reach[v] > 0.0;
  return covered;
}

}  // namespace

template <int D>
SealedCavities seal_cavities(const SimplexMesh<D>& mesh, const VertexNeighbours& neighbours,
                             const Eigen::VectorXd& clearance, double radius, std::vector<char>& reached) {
  SealedCavities out;
  if (radius <= 0.0) return out;
  const std::size_t nv = mesh.vertices.size();
  std::vector<char> fat(nv);
  for (std::size_t v = 0; v < nv; ++v) fat[v] = reached[v] && clearance[Eigen::Index(v)] > radius;
  const std::vector<char> outside = flood_from_walls(mesh, fat);
  bool suspect = false;
  for (std::size_t v = 0; v < nv && !suspect; ++v) suspect = fat[v] && !outside[v];
  if (!suspect) return out;  // every fat vertex reached is joined to the walls: no cavity
  const std::vector<char> covered = covered_by_balls(mesh, neighbours, clearance, outside, reached);
  std::vector<char> rest(nv);
  for (std::size_t v = 0; v < nv; ++v) rest[v] = reached[v] && !covered[v];
  const std::vector<Index> part = vertex_components(mesh, rest);
  std::vector<char> cavity(nv, 0);
  for (std::size_t v = 0; v < nv; ++v) {
    if (rest[v] && fat[v]) cavity[std::size_t(part[v])] = 1;
  }
  std::vector<char> given_back(nv, 0);
  for (std::size_t v = 0; v < nv; ++v) {
    if (!rest[v] || !cavity[std::size_t(part[v])]) continue;
    out.count += part[v] == Index(v);
    given_back[v] = 1;
    reached[v] = 0;
  }
  if (out.count == 0) return out;
  out.mouth.assign(nv, 0);
  for (std::size_t v = 0; v < nv; ++v) {
    if (!given_back[v]) continue;
    for (Index k = neighbours.offsets[v]; k < neighbours.offsets[v + 1] && !out.mouth[v]; ++k) {
      out.mouth[v] = reached[std::size_t(neighbours.neighbours[std::size_t(k)])];
    }
  }
  return out;
}

template SealedCavities seal_cavities<2>(const SimplexMesh<2>&, const VertexNeighbours&, const Eigen::VectorXd&,
                                         double, std::vector<char>&);
template SealedCavities seal_cavities<3>(const SimplexMesh<3>&, const VertexNeighbours&, const Eigen::VectorXd&,
                                         double, std::vector<char>&);

}  // namespace lsr
