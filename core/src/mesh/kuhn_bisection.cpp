// SPDX-License-Identifier: BSD-3-Clause
/// @file kuhn_bisection.cpp
/// @brief Kuhn background triangulation and recursive conforming bisection.
#include "mesh/kuhn_bisection.h"

#include "lsrecon/core/errors.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

namespace lsr {
namespace {

// The closure recursion depth is bounded by a small multiple of the level difference between
// neighbours; this guard turns a broken invariant into an error instead of a stack overflow.
constexpr int kMaxClosureDepth = 4096;

}  // namespace

template <int D>
const std::array<std::array<int, D>, KuhnBisectionForest<D>::kRootsPerCell>&
KuhnBisectionForest<D>::permutations() {
  static const auto table = [] {
    std::array<std::array<int, D>, kRootsPerCell> perms{};
    std::array<int, D> p{};
    std::iota(p.begin(), p.end(), 0);
    int k = 0;
    do {
      perms[k++] = p;
    } while (std::next_permutation(p.begin(), p.end()));
    return perms;
  }();
  return table;
}

template <int D>
KuhnBisectionForest<D>::KuhnBisectionForest(int cells_per_axis) : cells_(cells_per_axis) {
  if (cells_per_axis < 1 || std::pow(cells_per_axis + 1.0, D) > double(1 << 30)) {
    throw InvalidInput("Kuhn grid with " + std::to_string(cells_per_axis) + " cells per axis",
                       "use between 1 and 1000 cells per axis (h_max between 1e-3 and 1)");
  }
  const int n = cells_per_axis;
  const int stride = n + 1;
  Index grid_vertices = 1;
  for (int d = 0; d < D; ++d) grid_vertices *= stride;
  vertices_.resize(grid_vertices);
  for (Index i = 0; i < grid_vertices; ++i) {
    Index rest = i;
    for (int d = 0; d < D; ++d) {
      vertices_[i][d] = double(rest % stride) / n;
      rest /= stride;
    }
  }

  Index cells = 1;
  for (int d = 0; d < D; ++d) cells *= n;
  simplices_.reserve(std::size_t(cells) * kRootsPerCell);
  for (Index c = 0; c < cells; ++c) {
    std::array<int, D> corner{};
    Index rest = c;
    for (int d = 0; d < D; ++d) {
      corner[d] = rest % n;
      rest /= n;
    }
    for (const auto& perm : permutations()) {
      ForestSimplex<D> s;
      std::array<int, D> x = corner;
      for (int k = 0; k <= D; ++k) {
        if (k > 0) ++x[perm[k - 1]];
        Index id = 0;
        for (int d = D - 1; d >= 0; --d) id = id * stride + x[d];
        s.v[k] = id;
      }
      simplices_.push_back(s);
    }
  }
  leaf_count_ = Index(simplices_.size());
  level_size_.push_back(measured_size(0));
  for (std::size_t v = 0; v < vertices_.size(); ++v) leaves_at_vertex_.add_vertex();
  for (Index s = 0; s < leaf_count_; ++s) {
    for (Index v : simplices_[s].v) leaves_at_vertex_.push(v, s);
  }
}

template <int D>
double KuhnBisectionForest<D>::measured_size(Index s) const {
  const auto& v = simplices_[s].v;
  double longest2 = 0.0;
  for (int i = 0; i <= D; ++i) {
    for (int j = i + 1; j <= D; ++j) {
      longest2 = std::max(longest2, (vertices_[v[i]] - vertices_[v[j]]).squaredNorm());
    }
  }
  return std::sqrt(longest2 / D);
}

template <int D>
bool KuhnBisectionForest<D>::contains(Index s, Index vertex) const {
  // Without early exit: four compares cost less than the branches of a search.
  const auto& v = simplices_[s].v;
  bool found = false;
  for (int i = 0; i <= D; ++i) found |= v[i] == vertex;
  return found;
}

template <int D>
bool KuhnBisectionForest<D>::has_refinement_edge(Index s, Index a, Index b) const {
  const auto& t = simplices_[s];
  const Index x = t.v[0];
  const Index y = t.v[t.tag];
  return (x == a && y == b) || (x == b && y == a);
}

template <int D>
void KuhnBisectionForest<D>::refine(Index s) {
  if (leaves_at_vertex_.empty()) {
    throw std::logic_error("KuhnBisectionForest::refine after finish_refinement");
  }
  refine(s, 0);
}

template <int D>
void KuhnBisectionForest<D>::refine(Index s, int depth) {
  if (depth > kMaxClosureDepth) {
    throw std::logic_error("bisection closure did not terminate (matching condition broken)");
  }
  // Bisect first every leaf around the refinement edge whose own refinement edge differs;
  // afterwards the whole patch around the edge shares it and is bisected at once.
  for (;;) {
    if (!is_leaf(s)) return;  // a nested closure already bisected s
    const Index a = simplices_[s].v[0];
    const Index b = simplices_[s].v[simplices_[s].tag];
    Index blocker = -1;
    for (Index t : leaves_at_vertex_.leaves(a)) {
      if (contains(t, b) && !has_refinement_edge(t, a, b)) {
        blocker = t;
        break;
      }
    }
    if (blocker < 0) break;
    refine(blocker, depth + 1);
  }

  const Index a = simplices_[s].v[0];
  const Index b = simplices_[s].v[simplices_[s].tag];
  patch_.clear();  // reused: nothing below recurses
  for (Index t : leaves_at_vertex_.leaves(a)) {
    if (contains(t, b)) patch_.push_back(t);
  }
  const Index z = Index(vertices_.size());
  vertices_.push_back(0.5 * (vertices_[a] + vertices_[b]));
  leaves_at_vertex_.add_vertex();
  for (Index t : patch_) bisect(t, z);
}

template <int D>
void KuhnBisectionForest<D>::bisect(Index s, Index z) {
  const ForestSimplex<D> parent = simplices_[s];
  const int g = parent.tag;
  ForestSimplex<D> c0;
  ForestSimplex<D> c1;
  c0.tag = c1.tag = std::uint8_t(g > 1 ? g - 1 : D);
  c0.level = c1.level = std::uint8_t(parent.level + 1);
  c0.parent = c1.parent = s;
  for (int i = 0; i <= D; ++i) {
    if (i < g) {
      c0.v[i] = parent.v[i];
      c1.v[i] = parent.v[i + 1];
    } else if (i == g) {
      c0.v[i] = c1.v[i] = z;
    } else {
      c0.v[i] = c1.v[i] = parent.v[i];
    }
  }
  const Index first = Index(simplices_.size());
  simplices_[s].first_child = first;
  simplices_.push_back(c0);
  simplices_.push_back(c1);
  ++leaf_count_;
  if (c0.level >= level_size_.size()) level_size_.push_back(measured_size(first));

  for (Index v : parent.v) leaves_at_vertex_.erase(v, s);
  for (Index v : c0.v) leaves_at_vertex_.push(v, first);
  for (Index v : c1.v) leaves_at_vertex_.push(v, first + 1);
}

template <int D>
void KuhnBisectionForest<D>::finish_refinement() {
  leaves_at_vertex_.clear();
}

template class KuhnBisectionForest<2>;
template class KuhnBisectionForest<3>;

}  // namespace lsr
