// SPDX-License-Identifier: BSD-3-Clause
/// @file refinement_budget.h
/// @brief The vertex budget of graded refinement: the mesh size predicted from the passes so
/// far, refused before it is allocated if it would exceed the limit, and the forest's room
/// reserved for the passes left; and before any pass, the options checked and the least size
/// the mesh can have refused (internal to adaptive_refinement.cpp).
#pragma once

#include "geometry/nearest_point_index.h"
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
// covered by simplices of size <= h_min, at least one vertex per such cell on average. A point
// whose size is over twice h_min counts in a cell of its own size instead (a power of two at
// least that size): the mesh is coarser there (sparse data, a tile's coarse part).
template <int D>
double occupied_cells(const Points<D>& points, const std::vector<double>& point_size, double h_min) {
  // Coarser cells only lower the count, so clamping keeps a lower bound and the key in 64 bits.
  const double h = std::max(h_min, std::ldexp(1.0, -20));
  std::vector<std::unordered_set<std::uint64_t>> cells(22);  // per level
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double size = point_size.empty() ? 0.0 : point_size[i];
    // Level 0: cells of side h; level l > 0: cells of side 2^-(l - 1), l - 1 < 20.
    const int level = size > 2.0 * h ? 1 + std::max(0, int(std::floor(-std::log2(size)))) : 0;
    const double side = level == 0 ? h : std::ldexp(1.0, -(level - 1));
    const double n = std::ceil(1.0 / side);
    std::uint64_t key = 0;
    for (int d = 0; d < D; ++d) {
      const double c = std::clamp(std::floor(points[i][d] / side), 0.0, n);
      key = key * std::uint64_t(n + 1) + std::uint64_t(c);
    }
    cells[std::size_t(level)].insert(key);
  }
  double count = 0.0;
  for (const auto& c : cells) count += double(c.size());
  return count;
}

// The points' sizes, sorted (max(h_min, point_size)): a pass bisecting simplices of size s
// refines only near the points whose size is below s, so the surface it refines shrinks where
// the sizes are coarser (a tile's coarse part stops at its coarse size).
class RefiningPoints {
 public:
  explicit RefiningPoints(const AdaptiveMeshOptions& o) : sizes_(o.point_size) {
    for (double& s : sizes_) s = std::max(s, o.h_min);
    std::sort(sizes_.begin(), sizes_.end());
  }
  // The share of the points refined at size s among those refined at size `from`; 1 without
  // sizes (every point at h_min) or when none drove the pass at `from` (h_max marks alone).
  double share(double s, double from) const {
    const auto below = [&](double x) { return double(std::lower_bound(sizes_.begin(), sizes_.end(), x) - sizes_.begin()); };
    const double base = below(from);
    return base > 0.0 ? below(s) / base : 1.0;
  }

 private:
  std::vector<double> sizes_;
};

// The passes so far: the vertices after each (the first entry before any) and the largest
// size each bisected. Kuhn bisection cycles through D directions, its sizes falling by
// uneven steps (1.22, 1.41, 1.15 in 3D) that halve them over a cycle: the sizes the passes left
// will bisect are those of the last cycle halved, each pass until they reach h_min.
struct PassHistory {
  std::vector<double> vertices, bisected;
};

template <int D>
double next_bisected(const std::vector<double>& bisected) {
  const std::size_t n = bisected.size();
  return n >= std::size_t(D) ? bisected[n - D] / 2.0 : bisected.back() / std::pow(2.0, 1.0 / D);
}

struct PredictedPass {
  double total, bisected;
};

// Once the fine band follows the data, each pass adds surface_growth = 2^((D-1)/D) times what
// the previous one added on the same surface, times the share of that surface still refined:
// the totals after each pass left, of a count that has reached `now` and grew by `added` a
// pass when the passes bisected size `from`.
template <int D>
std::vector<PredictedPass> predicted_passes(double now, double added, double from, std::vector<double> bisected, double h_min,
                                            const RefiningPoints& points) {
  const double surface_growth = std::pow(2.0, double(D - 1) / D);
  std::vector<PredictedPass> passes;
  double g = surface_growth;
  for (double size = next_bisected<D>(bisected); size > h_min * (1.0 + 1e-9); size = next_bisected<D>(bisected)) {
    now += added * g * points.share(size, from);
    passes.push_back({now, size});
    bisected.push_back(size);
    g *= surface_growth;
  }
  return passes;
}

// Refuses a mesh predicted to exceed the vertex limit before allocating it; the suggested
// resolution is the finest the same model fits within the limit, less 10%. What a pass adds
// depends on its direction too (it swung 2.5x over each cycle on a sphere): the growth is read
// over the last D passes, their mean taken as added mid-cycle.
template <int D>
void check_predicted_size(const PassHistory& history, const AdaptiveMeshOptions& o, const RefiningPoints& points) {
  const std::vector<double>& counts = history.vertices;
  const std::size_t cycle = std::min<std::size_t>(D, counts.size() - 1);
  const double mean = (counts.back() - counts[counts.size() - 1 - cycle]) / double(cycle);
  const double added = mean * std::pow(2.0, double(D - 1) / D * (double(cycle) - 1.0) / 2.0);
  const double from = history.bisected[history.bisected.size() - cycle];
  const std::vector<PredictedPass> passes = predicted_passes<D>(counts.back(), added, from, history.bisected, o.h_min, points);
  const double predicted = passes.empty() ? counts.back() : passes.back().total;
  if (predicted <= double(o.max_vertices)) return;
  const auto fitting = std::size_t(std::upper_bound(passes.begin(), passes.end(), double(o.max_vertices),
                                                    [](double v, const PredictedPass& p) { return v < p.total; }) -
                                   passes.begin());
  const double last_fitting = fitting == 0 ? history.bisected.back() : passes[fitting - 1].bisected;
  const double feasible = std::floor(0.9 * std::pow(2.0, 1.0 / D) / last_fitting);
  throw MeshTooLarge("a mesh at resolution " + std::to_string(int(1.0 / o.h_min)) +
                         " is predicted to need about " + std::to_string(std::int64_t(predicted)) +
                         " vertices (limit " + std::to_string(o.max_vertices) + ")",
                     feasible);
}

// Room for the nodes the passes left will add, reserved while the forest is small: grown by
// doubling, it moved in the last passes, and a move first-touches the whole new copy.
// Reserved only when the next pass may not fit (the predictions of successive passes differ
// by up to 1.5x: reserving each time would move the forest each time), then for all passes
// left with a margin. Capacity never used is address space only, its pages never touched; a
// reservation the system refuses is skipped.
template <int D>
void reserve_predicted(KuhnBisectionForest<D>& forest, Index first_new, const PassHistory& history, double h_min,
                       const RefiningPoints& points) {
  const double nodes = double(forest.simplices().size());
  const std::vector<PredictedPass> passes =
      predicted_passes<D>(nodes, nodes - double(first_new), history.bisected.back(), history.bisected, h_min, points);
  if (passes.empty() || double(forest.simplices().capacity()) >= passes.front().total) return;
  try {
    forest.reserve(std::size_t(1.25 * passes.back().total));
  } catch (const std::bad_alloc&) {
  }
}

// The size most of the data asks for: what the size predictions assume (h_min alone would
// over-predict a mesh whose sizes follow a coarser local sampling).
inline double typical_size(const AdaptiveMeshOptions& o) {
  if (o.point_size.empty()) return o.h_min;
  std::vector<double> s = o.point_size;
  std::nth_element(s.begin(), s.begin() + s.size() / 10, s.end());
  return std::max(o.h_min, s[s.size() / 10]);
}

// Cells per side of the background grid: it already meets h_max (cells at most h_max wide).
inline int background_cells(double h_max) { return 1 << int(std::ceil(std::log2(1.0 / h_max) - 1e-9)); }

// The options checked against the data, and the mesh's predicted size against max_vertices
// (MeshTooLarge, with the resolution that would fit): the options with h_min the typical size.
template <int D>
AdaptiveMeshOptions checked_prediction(const NearestPointIndex<D>& data, const AdaptiveMeshOptions& o) {
  validate(o);
  if (!o.point_size.empty() && o.point_size.size() != data.points().size()) {
    throw InvalidInput("point_size has " + std::to_string(o.point_size.size()) + " entries for " +
                           std::to_string(data.points().size()) + " points",
                       "pass one size per data point, or none");
  }
  if (o.region_lo.size() != o.region_hi.size() || !(o.region_lo.empty() || o.region_lo.size() == std::size_t(D))) {
    throw InvalidInput("the region has " + std::to_string(o.region_lo.size()) + " and " + std::to_string(o.region_hi.size()) +
                           " coordinates",
                       "pass " + std::to_string(D) + " coordinates for each corner, or none");
  }
  AdaptiveMeshOptions predicted = o;
  predicted.h_min = typical_size(o);
  const double resolution = 1.0 / predicted.h_min;
  const double limit = double(o.max_vertices);
  const double lower_bound = occupied_cells<D>(data.points(), o.point_size, predicted.h_min);
  if (lower_bound > limit) {
    throw MeshTooLarge("a mesh at resolution " + std::to_string(int(resolution)) + " needs over " +
                           std::to_string(std::int64_t(lower_bound)) + " vertices (limit " +
                           std::to_string(o.max_vertices) + ")",
                       // occupied cells scale like resolution^(D-1) on a surface
                       std::floor(0.8 * resolution * std::pow(limit / lower_bound, 1.0 / (D - 1))));
  }

  if (std::pow(background_cells(o.h_max) + 1.0, D) > limit) {
    throw MeshTooLarge("the background grid for h_max = " + std::to_string(o.h_max) +
                           " alone needs more than " + std::to_string(o.max_vertices) + " vertices",
                       resolution);
  }
  return predicted;
}

}  // namespace lsr::detail
