// SPDX-License-Identifier: BSD-3-Clause
/// @file level_set_extraction.cpp
/// @brief Marching simplices with combinatorial orientation.
///
/// Orientation needs no geometric predicate: mesh simplices are positively oriented, so the
/// orientation of any ordering of a simplex's vertices is the parity of that permutation.
/// For a lone vertex n opposite the others q1..qD, the facet through the edge points on
/// (n, q1), ..., (n, qD) is a scaled copy of the face (q1..qD) seen from n, whose normal
/// points away from n when (n, q1, ..., qD) is an even permutation.
#include "lsrecon/core/level_set_extraction.h"

#include "lsrecon/core/errors.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_map>

namespace lsr {
namespace {

bool negative(double u) { return u < 0.0; }  // 0 counts as positive

template <int N>
bool even_permutation(const std::array<int, N>& p) {
  int inversions = 0;
  for (int i = 0; i < N; ++i) {
    for (int j = i + 1; j < N; ++j) inversions += p[i] > p[j] ? 1 : 0;
  }
  return inversions % 2 == 0;
}

template <int D>
class Marcher {
 public:
  Marcher(const SimplexMesh<D>& mesh, const std::vector<double>& u, double margin) : mesh_(mesh), u_(u), margin_(margin) {}

  // Output vertex on mesh edge (a, b), created once per edge.
  Index edge_vertex(Index a, Index b) {
    if (a > b) std::swap(a, b);
    const std::uint64_t key = (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b);
    auto [it, inserted] = index_.try_emplace(key, Index(out_.vertices.size()));
    if (inserted) {
      double t = u_[a] / (u_[a] - u_[b]);  // u_a, u_b on opposite sides: denominator != 0
      t = std::clamp(t, margin_, 1.0 - margin_);
      out_.sources.push_back({a, b, t});
      out_.vertices.push_back(edge_point_position(mesh_, out_.sources.back()));
    }
    return it->second;
  }

  void add(std::array<Index, D> facet, bool flip) {
    if (flip) std::swap(facet[0], facet[1]);
    out_.facets.push_back(facet);
  }

  void march(Index s);
  LevelSetMesh<D> take() { return std::move(out_); }

 private:
  const SimplexMesh<D>& mesh_;
  const std::vector<double>& u_;
  double margin_;
  std::unordered_map<std::uint64_t, Index> index_;
  LevelSetMesh<D> out_;
};

template <int D>
void Marcher<D>::march(Index s) {
  const auto& v = mesh_.simplices[s];
  std::array<int, D + 1> order{};  // local indices: negatives first, then positives
  int negatives = 0;
  for (int k = 0; k <= D; ++k) {
    if (negative(u_[v[k]])) order[negatives++] = k;
  }
  if (negatives == 0 || negatives == D + 1) return;
  for (int k = 0, p = negatives; k <= D; ++k) {
    if (!negative(u_[v[k]])) order[p++] = k;
  }
  const bool even = even_permutation<D + 1>(order);
  auto at = [&](int i) { return v[order[i]]; };

  if (negatives == 1 || negatives == D) {
    // A lone vertex: the negative one, or the positive one (last in order).
    const int lone = negatives == 1 ? 0 : D;
    std::array<int, D + 1> fan = order;  // lone vertex first, the others in order
    if (lone == D) std::rotate(fan.begin(), fan.begin() + D, fan.end());
    std::array<Index, D> facet{};
    for (int k = 0; k < D; ++k) facet[k] = edge_vertex(v[fan[0]], v[fan[k + 1]]);
    // Normal away from the lone vertex when `fan` is even; it must point to u > 0.
    const bool fan_even = even_permutation<D + 1>(fan);
    add(facet, negatives == 1 ? !fan_even : fan_even);
    return;
  }
  // D = 3, two negatives (n1, n2) and two positives (p1, p2): a quad on the edges
  // (n1p1, n1p2, n2p2, n2p1), correctly oriented when (n1, n2, p1, p2) is even.
  if constexpr (D == 3) {
    const Index q[4] = {edge_vertex(at(0), at(2)), edge_vertex(at(0), at(3)),
                        edge_vertex(at(1), at(3)), edge_vertex(at(1), at(2))};
    const auto& X = out_.vertices;
    if (split_quad_along_02<3>(X[q[0]], X[q[1]], X[q[2]], X[q[3]])) {
      add({q[0], q[1], q[2]}, !even);
      add({q[0], q[2], q[3]}, !even);
    } else {
      add({q[0], q[1], q[3]}, !even);
      add({q[1], q[2], q[3]}, !even);
    }
  }
}

}  // namespace

template <int D>
LevelSetMesh<D> extract_zero_level_set(const SimplexMesh<D>& mesh, const std::vector<double>& u, double edge_margin) {
  if (u.size() != mesh.vertices.size()) {
    throw InvalidInput("level set field has " + std::to_string(u.size()) + " values for " +
                           std::to_string(mesh.vertices.size()) + " mesh vertices",
                       "pass one value per mesh vertex");
  }
  for (std::size_t i = 0; i < u.size(); ++i) {
    if (!std::isfinite(u[i])) {
      throw InvalidInput("level set field is not finite at vertex " + std::to_string(i),
                         "the solver diverged or the field was not initialised");
    }
  }
  Marcher<D> marcher(mesh, u, std::clamp(edge_margin, 1e-9, 0.25));
  for (Index s = 0; s < Index(mesh.simplices.size()); ++s) marcher.march(s);
  return marcher.take();
}

std::vector<std::vector<Index>> closed_loops(const LevelSetMesh<2>& curves) {
  const Index n = Index(curves.vertices.size());
  std::vector<Index> next(n, -1);
  std::vector<int> incoming(n, 0);
  for (const auto& seg : curves.facets) {
    if (next[seg[0]] >= 0) {
      throw InvalidInput("curve vertex " + std::to_string(seg[0]) + " has two outgoing segments",
                         "closed_loops needs a closed, consistently oriented curve set");
    }
    next[seg[0]] = seg[1];
    ++incoming[seg[1]];
  }
  for (Index i = 0; i < n; ++i) {
    if (next[i] < 0 || incoming[i] != 1) {
      throw InvalidInput("curve vertex " + std::to_string(i) + " is not on a closed loop",
                         "closed_loops needs a closed, consistently oriented curve set");
    }
  }
  std::vector<std::vector<Index>> loops;
  std::vector<char> seen(n, 0);
  for (Index start = 0; start < n; ++start) {
    if (seen[start]) continue;
    loops.emplace_back();
    for (Index i = start; !seen[i]; i = next[i]) {
      seen[i] = 1;
      loops.back().push_back(i);
    }
  }
  return loops;
}

template LevelSetMesh<2> extract_zero_level_set<2>(const SimplexMesh<2>&, const std::vector<double>&, double);
template LevelSetMesh<3> extract_zero_level_set<3>(const SimplexMesh<3>&, const std::vector<double>&, double);

}  // namespace lsr
