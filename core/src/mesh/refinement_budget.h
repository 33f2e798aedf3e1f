// SPDX-License-Identifier: BSD-3-Clause
/// @file refinement_budget.h
/// @brief The vertex budget of graded refinement: the mesh size predicted from the passes so
/// far, refused before it is allocated if it would exceed the limit, and the forest's room
/// reserved for the passes left (internal to adaptive_refinement.cpp).
#pragma once

#include "lsrecon/core/errors.h"
#include "mesh/adaptive_refinement.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <exception>
#include <new>
#include <string>
#include <unordered_set>
#include <vector>

namespace lsr::detail {

// A finite check that reads like the bound it enforces.
inline bool in_range(double x, double lo, double hi) { return std::isfinite(x) && x > lo && x < hi; }

// Lower bound on the vertices needed: every grid cell of side h_min holding a data point is
// covered by simplices of size <= h_min, at least one vertex per such cell on average.
template <int D>
double occupied_cells(const Points<D>& points, double h_min) {
  // Coarser cells only lower the count, so clamping keeps a lower bound and the key in 64 bits.
  const double h = std::max(h_min, std::ldexp(1.0, -20));
  std::unordered_set<std::uint64_t> cells;
  const double n = std::ceil(1.0 / h);
  for (const auto& p : points) {
    std::uint64_t key = 0;
    for (int d = 0; d < D; ++d) {
      const double c = std::clamp(std::floor(p[d] / h), 0.0, n);
      key = key * std::uint64_t(n + 1) + std::uint64_t(c);
    }
    cells.insert(key);
  }
  return double(cells.size());
}

// Once the fine band follows the data, each pass (one bisection level, sizes / 2^(1/D)) adds
// surface_growth = 2^((D-1)/D) times what the previous one added: the totals after each level
// left down to h_min, of a count that has reached `now` and grew by `added` in the last pass.
template <int D>
std::vector<double> predicted_totals(double now, double added, double finest_now, double h_min) {
  const double surface_growth = std::pow(2.0, double(D - 1) / D);
  const int levels_left = int(std::max(0.0, std::ceil(D * std::log2(finest_now / h_min) - 1e-9)));
  std::vector<double> totals;
  double g = surface_growth;
  for (int k = 1; k <= levels_left; ++k, g *= surface_growth) {
    now += added * g;
    totals.push_back(now);
  }
  return totals;
}

// Refuses a mesh predicted to exceed the vertex limit before allocating it; the suggested
// resolution is the finest the same model fits within the limit, less 10%.
template <int D>
void check_predicted_size(double vertices, double added, double finest_now,
                          const AdaptiveMeshOptions& o) {
  const std::vector<double> totals = predicted_totals<D>(vertices, added, finest_now, o.h_min);
  const double predicted = totals.empty() ? vertices : totals.back();
  if (predicted <= double(o.max_vertices)) return;
  const auto fitting_levels = double(std::upper_bound(totals.begin(), totals.end(), double(o.max_vertices)) - totals.begin());
  const double feasible = std::floor(0.9 * std::pow(2.0, fitting_levels / D) / finest_now);
  throw MeshTooLarge("a mesh at resolution " + std::to_string(int(1.0 / o.h_min)) +
                         " is predicted to need about " + std::to_string(std::int64_t(predicted)) +
                         " vertices (limit " + std::to_string(o.max_vertices) + ")",
                     feasible);
}

// Room for the nodes the passes left will add, reserved while the forest is small: grown by
// doubling, it moved in the last passes, and a move first-touches the whole new copy (measured
// on the 200k sphere, seven runs each: bisection 1.36-2.17 s grown, 0.99-1.79 s reserved).
// Reserved only when the next pass may not fit (the predictions of successive passes differ
// by up to 1.5x: reserving each time would move the forest each time), then for all passes
// left with a margin. Capacity never used is address space only, its pages never touched; a
// reservation the system refuses is skipped.
template <int D>
void reserve_predicted(KuhnBisectionForest<D>& forest, Index first_new, double finest_next, double h_min) {
  const double nodes = double(forest.simplices().size());
  const std::vector<double> totals = predicted_totals<D>(nodes, nodes - double(first_new), finest_next, h_min);
  if (totals.empty() || double(forest.simplices().capacity()) >= totals.front()) return;
  try {
    forest.reserve(std::size_t(1.25 * totals.back()));
  } catch (const std::bad_alloc&) {
  }
}

}  // namespace lsr::detail
