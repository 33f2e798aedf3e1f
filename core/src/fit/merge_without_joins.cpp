// SPDX-License-Identifier: BSD-3-Clause
/// @file merge_without_joins.cpp
#include "fit/merge_without_joins.h"

#include "graph/disjoint_sets.h"
#include "start/outside_flood_fill.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <utility>

namespace lsr {
namespace {

// Union-find over the few (<= ~60) vertices of one link, by position in `link`.
struct LinkSets {
  std::vector<Index> link;
  detail::DisjointSets parts;
  int slot(Index v) {
    const auto it = std::find(link.begin(), link.end(), v);
    if (it != link.end()) return int(it - link.begin());
    link.push_back(v);
    return int(parts.add());
  }
};

// The simplices containing each candidate, CSR by candidate slot.
template <int D>
void candidate_stars(const SimplexMesh<D>& mesh, const std::vector<Index>& slot, std::size_t count,
                     std::vector<Index>& offsets, std::vector<Index>& stars) {
  offsets.assign(count + 1, 0);
  for (const auto& s : mesh.simplices) {
    for (Index v : s) {
      if (slot[v] >= 0) ++offsets[slot[v] + 1];
    }
  }
  for (std::size_t c = 0; c < count; ++c) offsets[c + 1] += offsets[c];
  stars.resize(std::size_t(offsets[count]));
  std::vector<Index> fill(offsets.begin(), offsets.end() - 1);
  for (std::size_t s = 0; s < mesh.simplices.size(); ++s) {
    for (Index v : mesh.simplices[s]) {
      if (slot[v] >= 0) stars[fill[slot[v]]++] = Index(s);
    }
  }
}

}  // namespace

template <int D>
std::size_t absorb_small_parts(const SimplexMesh<D>& mesh, const VertexNeighbours& neighbours,
                               const Eigen::VectorXd& width, std::vector<double>& values) {
  const std::size_t nv = mesh.vertices.size();
  const auto near = [&](Index v) { return std::abs(values[v]) < width[v]; };
  const auto side = [&](Index v) { return values[v] < 0.0; };
  std::vector<char> seen(nv, 0);
  std::vector<Index> part;
  std::size_t absorbed = 0;
  for (std::size_t start = 0; start < nv; ++start) {
    if (seen[start] || !near(Index(start))) continue;
    // The part of `start` among the near vertices; narrow if it reaches no far vertex of its
    // side, no wall, and its box is smaller than the widest width in it.
    const bool negative = side(Index(start));
    part.assign(1, Index(start));
    seen[start] = 1;
    bool narrow = true;
    Vec<D> low = mesh.vertices[start], high = low;
    double widest = 0.0;
    for (std::size_t k = 0; k < part.size(); ++k) {
      const Index v = part[k];
      low = low.cwiseMin(mesh.vertices[v]);
      high = high.cwiseMax(mesh.vertices[v]);
      widest = std::max(widest, width[v]);
      narrow = narrow && !on_wall<D>(mesh.vertices[v]);
      for (Index j = neighbours.offsets[v]; j < neighbours.offsets[v + 1]; ++j) {
        const Index w = neighbours.neighbours[j];
        if (side(w) != negative) continue;
        if (!near(w)) {
          narrow = false;
        } else if (!seen[w]) {
          seen[w] = 1;
          part.push_back(w);
        }
      }
    }
    if (!narrow || (high - low).norm() >= widest) continue;
    for (Index v : part) values[v] = negative ? -values[v] : -std::max(values[v], std::numeric_limits<double>::min());
    absorbed += part.size();
  }
  return absorbed;
}

template <int D>
std::size_t fill_cut_off_voids(const SimplexMesh<D>& mesh, const Eigen::VectorXd& reference,
                               std::vector<double>& values) {
  const std::size_t nv = values.size();
  std::vector<char> open(nv);
  for (std::size_t v = 0; v < nv; ++v) open[v] = values[v] >= 0.0;
  const std::vector<char> outside = flood_from_walls(mesh, open);
  std::vector<char> enclosed(nv);
  bool any = false;
  for (std::size_t v = 0; v < nv; ++v) any |= (enclosed[v] = open[v] && !outside[v]) != 0;
  if (!any) return 0;
  for (std::size_t v = 0; v < nv; ++v) open[v] = reference[Eigen::Index(v)] >= 0.0;
  const std::vector<char> was_outside = flood_from_walls(mesh, open);
  const std::vector<Index> part = vertex_components(mesh, enclosed);
  std::vector<char> cut_off(nv, 0);
  for (std::size_t v = 0; v < nv; ++v) {
    if (enclosed[v] && was_outside[v]) cut_off[std::size_t(part[v])] = 1;
  }
  std::size_t filled = 0;
  for (std::size_t v = 0; v < nv; ++v) {
    if (enclosed[v] && cut_off[std::size_t(part[v])]) {
      values[v] = -std::max(values[v], std::numeric_limits<double>::min());
      ++filled;
    }
  }
  return filled;
}

template <int D>
LinkPieces link_pieces(const SimplexMesh<D>& mesh, const std::vector<Index>& star, Index v,
                       const std::vector<char>& negative) {
  thread_local LinkSets sets;
  sets.link.clear();
  sets.parts.clear();
  for (Index s : star) {
    int others[D], n = 0;
    for (Index w : mesh.simplices[s]) {
      if (w != v) others[n++] = sets.slot(w);
    }
    for (int i = 0; i < D; ++i) {
      for (int j = i + 1; j < D; ++j) {
        if (negative[sets.link[others[i]]] == negative[sets.link[others[j]]]) sets.parts.unite(others[i], others[j]);
      }
    }
  }
  LinkPieces pieces;
  for (std::size_t i = 0; i < sets.link.size(); ++i) {
    if (sets.parts.find(Index(i)) == Index(i)) ++(negative[sets.link[i]] ? pieces.negative : pieces.non_negative);
  }
  return pieces;
}

template <int D>
std::size_t merge_without_joins(const SimplexMesh<D>& mesh, const Eigen::VectorXd& reference,
                                std::vector<double>& values, const std::vector<char>& may_join) {
  const std::size_t nv = values.size();
  std::vector<char> negative(nv);
  std::vector<Index> slot(nv, -1), candidates;
  for (std::size_t v = 0; v < nv; ++v) {
    negative[v] = reference[Eigen::Index(v)] < 0.0;
    if (negative[v] != (values[v] < 0.0)) {
      slot[v] = Index(candidates.size());
      candidates.push_back(Index(v));
    }
  }
  if (candidates.empty()) return 0;
  std::vector<Index> offsets, stars;
  candidate_stars<D>(mesh, slot, candidates.size(), offsets, stars);
  std::vector<Index> star;
  const auto star_of = [&](Index c) -> const std::vector<Index>& {
    star.assign(stars.begin() + offsets[c], stars.begin() + offsets[c + 1]);
    return star;
  };
  // Most confident first; ties by index, so the result does not depend on anything else.
  using Entry = std::pair<double, Index>;
  const auto lower_priority = [](const Entry& a, const Entry& b) {
    return a.first != b.first ? a.first < b.first : a.second > b.second;
  };
  std::priority_queue<Entry, std::vector<Entry>, decltype(lower_priority)> queue(lower_priority),
      changes(lower_priority);
  std::vector<char> flipped(nv, 0), queued(nv, 0);
  for (Index v : candidates) {
    if (!on_wall<D>(mesh.vertices[v])) {
      queued[v] = 1;
      queue.emplace(std::abs(values[v]), v);
    }
  }
  // Whether v may flip; `later`: it changes the topology (a cut or a join), which waits.
  const auto allowed = [&](Index v, bool& later) {
    const LinkPieces pieces = link_pieces<D>(mesh, star_of(slot[v]), v, negative);
    const int own = negative[v] ? pieces.negative : pieces.non_negative;
    const int other = negative[v] ? pieces.non_negative : pieces.negative;
    later = own > 1 || other > 1;
    return other == 1 || (other > 1 && !may_join.empty() && may_join[v]);
  };
  const auto flip = [&](Index v) {
    flipped[v] = 1;
    negative[v] = !negative[v];
    for (Index s : star) {  // star_of(v), from allowed(v): their links changed
      for (Index w : mesh.simplices[s]) {
        if (slot[w] >= 0 && !flipped[w] && !queued[w] && !on_wall<D>(mesh.vertices[w])) {
          queued[w] = 1;
          queue.emplace(std::abs(values[w]), w);
        }
      }
    }
  };
  // Cuts and joins wait until no other flip is left: a part moving sideways through a thin
  // spot is otherwise cut before it regrows on the other side, and may not be joined again.
  // Then the most confident of them, and what it frees.
  for (bool changed = true; changed;) {
    while (!queue.empty()) {
      const Index v = queue.top().second;
      queue.pop();
      queued[v] = 0;
      bool later = false;
      if (flipped[v] || !allowed(v, later)) continue;
      if (later) {
        changes.emplace(std::abs(values[v]), v);
      } else {
        flip(v);
      }
    }
    changed = false;
    while (!changes.empty() && !changed) {
      const Index v = changes.top().second;
      changes.pop();
      bool later = false;
      if (flipped[v] || !allowed(v, later)) continue;  // a neighbour's flip will bring it back
      flip(v);
      changed = true;
    }
  }
  std::size_t kept = 0;
  for (Index v : candidates) {
    if (!flipped[v]) {
      values[v] = reference[v];
      ++kept;
    }
  }
  return kept;
}

template std::size_t absorb_small_parts<2>(const SimplexMesh<2>&, const VertexNeighbours&, const Eigen::VectorXd&,
                                           std::vector<double>&);
template std::size_t absorb_small_parts<3>(const SimplexMesh<3>&, const VertexNeighbours&, const Eigen::VectorXd&,
                                           std::vector<double>&);
template std::size_t fill_cut_off_voids<2>(const SimplexMesh<2>&, const Eigen::VectorXd&, std::vector<double>&);
template std::size_t fill_cut_off_voids<3>(const SimplexMesh<3>&, const Eigen::VectorXd&, std::vector<double>&);
template LinkPieces link_pieces<2>(const SimplexMesh<2>&, const std::vector<Index>&, Index, const std::vector<char>&);
template LinkPieces link_pieces<3>(const SimplexMesh<3>&, const std::vector<Index>&, Index, const std::vector<char>&);
template std::size_t merge_without_joins<2>(const SimplexMesh<2>&, const Eigen::VectorXd&, std::vector<double>&,
                                            const std::vector<char>&);
template std::size_t merge_without_joins<3>(const SimplexMesh<3>&, const Eigen::VectorXd&, std::vector<double>&,
                                            const std::vector<char>&);

}  // namespace lsr
