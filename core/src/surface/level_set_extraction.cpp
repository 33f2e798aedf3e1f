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
#include "lsrecon/core/large_array_allocator.h"
#include "thread_count.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <omp.h>

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

// The output vertices: one per crossed mesh edge (a < b), numbered in the order of a, then b.
// The crossed edges are listed per block of simplices, bucketed by a (a counting sort), then
// each bucket is sorted and made unique on its own: in parallel, without a hash map.
template <int D>
class EdgeVertices {
 public:
  EdgeVertices(const SimplexMesh<D>& mesh, const std::vector<double>& u, long block, double margin, int threads,
               LevelSetMesh<D>& out)
      : first_(u.size() + 1, 0) {
    const long ns = long(mesh.simplices.size());
    const long blocks = (ns + block - 1) / block;
    std::vector<std::vector<std::pair<Index, Index>>> edges(static_cast<std::size_t>(blocks));
#pragma omp parallel for schedule(static) num_threads(threads)
    for (long k = 0; k < blocks; ++k) {
      for (long s = k * block; s < std::min(ns, (k + 1) * block); ++s) {
        const auto& v = mesh.simplices[std::size_t(s)];
        for (int i = 0; i <= D; ++i) {
          for (int j = 0; j <= D; ++j) {
            if (v[i] < v[j] && negative(u[v[i]]) != negative(u[v[j]])) edges[std::size_t(k)].push_back({v[i], v[j]});
          }
        }
      }
    }
    LargeVector<Index> start(u.size() + 1, 0);
    for (const auto& list : edges) {
      for (const auto& e : list) ++start[std::size_t(e.first) + 1];
    }
    for (std::size_t a = 0; a < u.size(); ++a) start[a + 1] += start[a];
    ends_.resize(std::size_t(start.back()));
    {
      LargeVector<Index> fill(start.begin(), start.end() - 1);
      for (const auto& list : edges) {
        for (const auto& e : list) ends_[std::size_t(fill[std::size_t(e.first)]++)] = e.second;
      }
    }
    const long nv = long(u.size());
#pragma omp parallel for schedule(static) num_threads(threads)
    for (long a = 0; a < nv; ++a) {
      auto first = ends_.begin() + start[std::size_t(a)], last = ends_.begin() + start[std::size_t(a) + 1];
      std::sort(first, last);
      first_[std::size_t(a) + 1] = Index(std::unique(first, last) - first);
    }
    for (std::size_t a = 0; a < u.size(); ++a) first_[a + 1] += first_[a];
    // Packed: row a holds its unique ends at first_[a] ..
    for (std::size_t a = 0; a < u.size(); ++a) {
      std::copy_n(ends_.begin() + start[a], first_[a + 1] - first_[a], ends_.begin() + first_[a]);
    }
    ends_.resize(std::size_t(first_.back()));
    out.vertices.resize(ends_.size());
    out.sources.resize(ends_.size());
#pragma omp parallel for schedule(static) num_threads(threads)
    for (long a = 0; a < nv; ++a) {
      for (Index k = first_[std::size_t(a)]; k < first_[std::size_t(a) + 1]; ++k) {
        const Index b = ends_[std::size_t(k)];
        const double t = u[a] / (u[a] - u[b]);  // opposite signs: the denominator is not 0
        out.sources[std::size_t(k)] = {Index(a), b, std::clamp(t, margin, 1.0 - margin)};
        out.vertices[std::size_t(k)] = edge_point_position(mesh, out.sources[std::size_t(k)]);
      }
    }
  }

  // The output vertex on the crossed mesh edge (a, b).
  Index at(Index a, Index b) const {
    if (a > b) std::swap(a, b);
    const auto first = ends_.begin() + first_[std::size_t(a)], last = ends_.begin() + first_[std::size_t(a) + 1];
    return first_[std::size_t(a)] + Index(std::lower_bound(first, last, b) - first);
  }

 private:
  LargeVector<Index> first_;  // #V + 1: the crossed edges (a, .) are first_[a] .. first_[a + 1] - 1
  LargeVector<Index> ends_;   // their other ends b, sorted per a
};

// Facets of a simplex: 0, 1 (a lone vertex) or, in 3D, 2 (a quad).
template <int D>
int facet_count(const SimplexMesh<D>& mesh, const std::vector<double>& u, Index s) {
  int negatives = 0;
  for (Index v : mesh.simplices[s]) negatives += negative(u[v]);
  return negatives == 0 || negatives == D + 1 ? 0 : (negatives == 1 || negatives == D ? 1 : 2);
}

// Writes simplex s's facets from `out` on.
template <int D>
void march(const SimplexMesh<D>& mesh, const std::vector<double>& u, const EdgeVertices<D>& edges,
           const Points<D>& X, Index s, std::array<Index, D>* out) {
  const auto& v = mesh.simplices[s];
  std::array<int, D + 1> order{};  // local indices: negatives first, then positives
  int negatives = 0;
  for (int k = 0; k <= D; ++k) {
    if (negative(u[v[k]])) order[negatives++] = k;
  }
  for (int k = 0, p = negatives; k <= D; ++k) {
    if (!negative(u[v[k]])) order[p++] = k;
  }
  const bool even = even_permutation<D + 1>(order);
  auto at = [&](int i) { return v[order[i]]; };
  auto add = [&](std::array<Index, D> facet, bool flip) {
    if (flip) std::swap(facet[0], facet[1]);
    *out++ = facet;
  };

  if (negatives == 1 || negatives == D) {
    // A lone vertex: the negative one, or the positive one (last in order).
    const int lone = negatives == 1 ? 0 : D;
    std::array<int, D + 1> fan = order;  // lone vertex first, the others in order
    if (lone == D) std::rotate(fan.begin(), fan.begin() + D, fan.end());
    std::array<Index, D> facet{};
    for (int k = 0; k < D; ++k) facet[k] = edges.at(v[fan[0]], v[fan[k + 1]]);
    // Normal away from the lone vertex when `fan` is even; it must point to u > 0.
    const bool fan_even = even_permutation<D + 1>(fan);
    add(facet, negatives == 1 ? !fan_even : fan_even);
    return;
  }
  // D = 3, two negatives (n1, n2) and two positives (p1, p2): a quad on the edges
  // (n1p1, n1p2, n2p2, n2p1), correctly oriented when (n1, n2, p1, p2) is even.
  if constexpr (D == 3) {
    const Index q[4] = {edges.at(at(0), at(2)), edges.at(at(0), at(3)), edges.at(at(1), at(3)), edges.at(at(1), at(2))};
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
LevelSetMesh<D> extract_zero_level_set(const SimplexMesh<D>& mesh, const std::vector<double>& u, double edge_margin,
                                       int threads) {
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
  threads = detail::thread_count(threads);
  // Facets in simplex order: counted per fixed block of simplices, then written in parallel.
  constexpr long kBlock = 16384;
  LevelSetMesh<D> out;
  const EdgeVertices<D> edges(mesh, u, kBlock, std::clamp(edge_margin, 1e-9, 0.25), threads, out);
  const long ns = long(mesh.simplices.size());
  const long blocks = (ns + kBlock - 1) / kBlock;
  std::vector<Index> first(std::size_t(blocks) + 1, 0);
#pragma omp parallel for schedule(static) num_threads(threads)
  for (long b = 0; b < blocks; ++b) {
    Index n = 0;
    for (long s = b * kBlock; s < std::min(ns, (b + 1) * kBlock); ++s) n += facet_count(mesh, u, Index(s));
    first[std::size_t(b) + 1] = n;
  }
  for (std::size_t b = 0; b < std::size_t(blocks); ++b) first[b + 1] += first[b];
  out.facets.resize(std::size_t(first.back()));
#pragma omp parallel for schedule(static) num_threads(threads)
  for (long b = 0; b < blocks; ++b) {
    std::array<Index, D>* next = out.facets.data() + first[std::size_t(b)];
    for (long s = b * kBlock; s < std::min(ns, (b + 1) * kBlock); ++s) {
      const int n = facet_count(mesh, u, Index(s));
      if (n == 0) continue;
      march<D>(mesh, u, edges, out.vertices, Index(s), next);
      next += n;
    }
  }
  return out;
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

template LevelSetMesh<2> extract_zero_level_set<2>(const SimplexMesh<2>&, const std::vector<double>&, double, int);
template LevelSetMesh<3> extract_zero_level_set<3>(const SimplexMesh<3>&, const std::vector<double>&, double, int);

}  // namespace lsr
