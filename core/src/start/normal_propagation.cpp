// SPDX-License-Identifier: BSD-3-Clause
/// @file normal_propagation.cpp
#include "start/normal_propagation.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <queue>
#include <tuple>

namespace lsr::detail {

template <int D>
PropagatedSenses propagate_senses(const Points<D>& points, const Points<D>& normals, const LargeVector<Index>& knn, int k,
                                  const std::vector<double>& noise) {
  const std::size_t n = normals.size();
  // n_q against n_p reflected in the plane bisecting the chord e (unit, p to q): the normals of
  // a sphere (circle) are each other's mirror images there, and on a plane it is n_p . n_q.
  // The chord's offset along n_p within two deviations of the difference of two noisy offsets
  // is noise, not a second sheet: it is taken off (within a band the noise fills, neighbours
  // across it would otherwise read as sheets facing each other).
  const auto agreement = [&](std::size_t p, std::size_t q) {
    Vec<D> e = points[q] - points[p];
    if (!noise.empty()) {
      const double h = e.dot(normals[p]), spread = 2.0 * std::hypot(noise[p], noise[q]);
      e -= (h - std::copysign(std::max(std::abs(h) - spread, 0.0), h)) * normals[p];
    }
    if (e.squaredNorm() == 0.0) return normals[p].dot(normals[q]);
    e.normalize();
    return normals[p].dot(normals[q]) - 2.0 * normals[p].dot(e) * normals[q].dot(e);
  };
  // The graph made symmetric: a point is joined to its k nearest and to those that list it.
  std::vector<Index> offsets(n + 1, 0);
  for (std::size_t p = 0; p < n; ++p) {
    for (int j = 0; j < k; ++j) {
      const auto q = std::size_t(knn[p * std::size_t(k) + std::size_t(j)]);
      if (q == p) continue;
      ++offsets[p + 1];
      ++offsets[q + 1];
    }
  }
  for (std::size_t p = 0; p < n; ++p) offsets[p + 1] += offsets[p];
  std::vector<Index> adjacent(static_cast<std::size_t>(offsets[n]));
  std::vector<Index> fill(offsets.begin(), offsets.end() - 1);
  for (std::size_t p = 0; p < n; ++p) {
    for (int j = 0; j < k; ++j) {
      const auto q = std::size_t(knn[p * std::size_t(k) + std::size_t(j)]);
      if (q == p) continue;
      adjacent[std::size_t(fill[p]++)] = Index(q);
      adjacent[std::size_t(fill[q]++)] = Index(p);
    }
  }
  // Prim's algorithm from the lowest unvisited index of each part; ties by index, so the
  // result does not depend on the heap's order.
  PropagatedSenses out;
  out.sense.assign(n, 0);
  out.part.assign(n, -1);
  using Edge = std::tuple<double, Index, Index>;  // weight, to, from
  std::priority_queue<Edge, std::vector<Edge>, std::greater<>> heap;
  const auto push_edges = [&](std::size_t p) {
    for (Index e = offsets[p]; e < offsets[p + 1]; ++e) {
      const auto q = std::size_t(adjacent[std::size_t(e)]);
      if (out.sense[q] == 0) heap.emplace(1.0 - std::abs(agreement(p, q)), Index(q), Index(p));
    }
  };
  for (std::size_t seed = 0; seed < n; ++seed) {
    if (out.sense[seed] != 0) continue;
    out.sense[seed] = 1;
    out.part[seed] = out.parts;
    push_edges(seed);
    while (!heap.empty()) {
      const auto [weight, to, from] = heap.top();
      heap.pop();
      const auto q = std::size_t(to), p = std::size_t(from);
      if (out.sense[q] != 0) continue;
      out.sense[q] = agreement(p, q) * out.sense[p] >= 0.0 ? 1 : -1;
      out.part[q] = out.parts;
      push_edges(q);
    }
    ++out.parts;
  }
  return out;
}

template PropagatedSenses propagate_senses<2>(const Points<2>&, const Points<2>&, const LargeVector<Index>&, int,
                                              const std::vector<double>&);
template PropagatedSenses propagate_senses<3>(const Points<3>&, const Points<3>&, const LargeVector<Index>&, int,
                                              const std::vector<double>&);

}  // namespace lsr::detail
