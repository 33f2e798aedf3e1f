// SPDX-License-Identifier: BSD-3-Clause
/// @file unsupported_fairing.cpp
#include "surface/unsupported_fairing.h"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <algorithm>
#include <utility>

namespace lsr {

template <int D>
EdgeGraph edge_graph(const LevelSetMesh<D>& surface) {
  const std::size_t n = surface.vertices.size();
  // Each edge once: a closed surface's edge lies on two facets.
  std::vector<std::pair<Index, Index>> edges;
  edges.reserve(surface.facets.size() * D);
  for (const auto& f : surface.facets) {
    for (int i = 0; i < (D == 3 ? 3 : 1); ++i) {
      const Index a = f[std::size_t(i)], b = f[std::size_t((i + 1) % D)];
      edges.emplace_back(std::min(a, b), std::max(a, b));
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  EdgeGraph g{std::vector<std::size_t>(n + 1, 0), std::vector<Index>(2 * edges.size())};
  for (const auto& [a, b] : edges) {
    ++g.first[std::size_t(a) + 1];
    ++g.first[std::size_t(b) + 1];
  }
  for (std::size_t v = 0; v < n; ++v) g.first[v + 1] += g.first[v];
  std::vector<std::size_t> fill(g.first.begin(), g.first.end() - 1);
  for (const auto& [a, b] : edges) {
    g.next[fill[std::size_t(a)]++] = b;
    g.next[fill[std::size_t(b)]++] = a;
  }
  return g;
}

void grow_over_edges(const EdgeGraph& g, std::vector<char>& flags, const std::vector<char>& allowed) {
  std::vector<std::size_t> stack;
  for (std::size_t v = 0; v < flags.size(); ++v) {
    if (flags[v]) stack.push_back(v);
  }
  while (!stack.empty()) {
    const std::size_t v = stack.back();
    stack.pop_back();
    for (std::size_t k = g.first[v]; k < g.first[v + 1]; ++k) {
      const auto w = std::size_t(g.next[k]);
      if (allowed[w] && !flags[w]) {
        flags[w] = 1;
        stack.push_back(w);
      }
    }
  }
}

template <int D>
std::size_t fair_unsupported(LevelSetMesh<D>& surface, const EdgeGraph& g, const std::vector<char>& free, double step) {
  const std::size_t n = surface.vertices.size();
  std::vector<Index> column(n, -1);
  Index unknowns = 0;
  for (std::size_t v = 0; v < n; ++v) {
    if (free[v]) column[v] = unknowns++;
  }
  if (unknowns == 0) return 0;
  const auto& first = g.first;
  const auto& next = g.next;

  // Row v of (I + t L^2) x = x0, L = degree - adjacency: x_v + t sum over w in {v} and v's
  // neighbours of L(v, w) L(w, :) x; the fixed vertices' terms go to the right-hand side.
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::MatrixXd rhs(unknowns, D);
  const auto add = [&](Index row, std::size_t u, double c) {
    if (column[u] >= 0) {
      entries.emplace_back(row, column[u], c);
    } else {
      rhs.row(row) -= c * surface.vertices[u].transpose();
    }
  };
  const auto add_row_of_l = [&](Index row, std::size_t w, double c) {  // c L(w, :)
    add(row, w, c * double(first[w + 1] - first[w]));
    for (std::size_t k = first[w]; k < first[w + 1]; ++k) add(row, std::size_t(next[k]), -c);
  };
  for (std::size_t v = 0; v < n; ++v) {
    const Index row = column[v];
    if (row < 0) continue;
    rhs.row(row) = surface.vertices[v].transpose();
    entries.emplace_back(row, row, 1.0);
    add_row_of_l(row, v, step * double(first[v + 1] - first[v]));
    for (std::size_t k = first[v]; k < first[v + 1]; ++k) add_row_of_l(row, std::size_t(next[k]), -step);
  }
  Eigen::SparseMatrix<double> m(unknowns, unknowns);
  m.setFromTriplets(entries.begin(), entries.end());  // duplicates summed
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(m);
  if (solver.info() != Eigen::Success) return 0;
  const Eigen::MatrixXd x = solver.solve(rhs);
  if (!x.allFinite()) return 0;
  for (std::size_t v = 0; v < n; ++v) {
    if (column[v] >= 0) surface.vertices[v] = x.row(column[v]).transpose();
  }
  return std::size_t(unknowns);
}

template EdgeGraph edge_graph<2>(const LevelSetMesh<2>&);
template EdgeGraph edge_graph<3>(const LevelSetMesh<3>&);
template std::size_t fair_unsupported<2>(LevelSetMesh<2>&, const EdgeGraph&, const std::vector<char>&, double);
template std::size_t fair_unsupported<3>(LevelSetMesh<3>&, const EdgeGraph&, const std::vector<char>&, double);

}  // namespace lsr
