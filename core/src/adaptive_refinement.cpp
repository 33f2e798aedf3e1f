// SPDX-License-Identifier: BSD-3-Clause
/// @file adaptive_refinement.cpp
/// @brief Pass-by-pass graded refinement: each pass tests the simplices created by the last
/// one and bisects those larger than the sizing function allows.
#include "lsrecon/core/adaptive_refinement.h"

#include "lsrecon/core/z_order.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cmath>
#include <limits>
#include <string>
#include <unordered_set>

#include <omp.h>

namespace lsr {
namespace {

// A finite check that reads like the bound it enforces.
bool in_range(double x, double lo, double hi) { return std::isfinite(x) && x > lo && x < hi; }

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
// surface_growth = 2^((D-1)/D) times the vertices the previous one added. Predicts the final
// count from the last pass and refuses before allocating; the suggested resolution is the
// finest the same model fits within the limit, less 10%.
template <int D>
void check_predicted_size(double vertices, double added, double finest_now,
                          const AdaptiveMeshOptions& o) {
  const double surface_growth = std::pow(2.0, double(D - 1) / D);
  const double levels_left = std::max(0.0, std::ceil(D * std::log2(finest_now / o.h_min) - 1e-9));
  double predicted = vertices;
  double fitting_levels = 0.0;
  double g = surface_growth;
  for (double k = 1; k <= levels_left; ++k, g *= surface_growth) {
    predicted += added * g;
    if (predicted <= double(o.max_vertices)) fitting_levels = k;
  }
  if (predicted <= double(o.max_vertices)) return;
  const double feasible = std::floor(0.9 * std::pow(2.0, fitting_levels / D) / finest_now);
  throw MeshTooLarge("a mesh at resolution " + std::to_string(int(1.0 / o.h_min)) +
                         " is predicted to need about " + std::to_string(std::int64_t(predicted)) +
                         " vertices (limit " + std::to_string(o.max_vertices) + ")",
                     feasible);
}

template <int D>
struct Candidates {
  std::vector<Index> nodes;
  Points<D> centroids;
  std::vector<double> radii;
  std::vector<double> sizes;
};

// The leaves created since `first` that a further bisection could concern: no simplex of size
// h_min or less is ever bisected (every local size is at least h_min), so those need no
// distance query. Measured in parallel, listed in node order.
template <int D>
Candidates<D> leaves_from(const KuhnBisectionForest<D>& forest, Index first, double h_min, int threads) {
  const auto& simplices = forest.simplices();
  const long n = long(simplices.size()) - long(first);
  Candidates<D> all;
  all.centroids.resize(std::size_t(std::max(0L, n)));
  all.radii.assign(all.centroids.size(), 0.0);
  all.sizes.assign(all.centroids.size(), 0.0);
#pragma omp parallel for schedule(static) num_threads(threads > 0 ? threads : omp_get_max_threads())
  for (long i = 0; i < n; ++i) {
    const Index s = first + Index(i);
    if (!forest.is_leaf(s)) continue;
    all.sizes[std::size_t(i)] = forest.size(s);
    if (all.sizes[std::size_t(i)] <= h_min) continue;
    Vec<D> centroid = Vec<D>::Zero();
    for (Index v : simplices[s].v) centroid += forest.vertices()[v];
    centroid /= double(D + 1);
    double r = 0.0;
    for (Index v : simplices[s].v) r = std::max(r, (forest.vertices()[v] - centroid).norm());
    all.centroids[std::size_t(i)] = centroid;
    all.radii[std::size_t(i)] = r;
  }
  Candidates<D> c;
  for (long i = 0; i < n; ++i) {
    if (all.sizes[std::size_t(i)] <= h_min) continue;  // inner nodes have size 0 here
    c.nodes.push_back(first + Index(i));
    c.centroids.push_back(all.centroids[std::size_t(i)]);
    c.radii.push_back(all.radii[std::size_t(i)]);
    c.sizes.push_back(all.sizes[std::size_t(i)]);
  }
  return c;
}

// Any data point bounds the distance from above: a candidate whose parent's witness point is
// within its marking distance, and which is larger than every local size, is marked whatever
// its nearest point (it inherits the witness).
template <int D>
std::vector<char> certainly_marked(const KuhnBisectionForest<D>& forest, const Candidates<D>& cand,
                                   const std::vector<Index>& witness, const Points<D>& points, double grading,
                                   double largest_local, int threads) {
  const long n = long(cand.nodes.size());
  std::vector<char> certain(cand.nodes.size(), 0);
#pragma omp parallel for schedule(static) num_threads(threads > 0 ? threads : omp_get_max_threads())
  for (long i = 0; i < n; ++i) {
    const std::size_t c = std::size_t(i);
    const Index parent = forest.simplices()[cand.nodes[c]].parent;
    const Index w = parent >= 0 ? witness[std::size_t(parent)] : -1;
    if (w < 0 || cand.sizes[c] <= largest_local) continue;
    const double upper = (cand.centroids[c] - points[std::size_t(w)]).norm();
    certain[c] = cand.sizes[c] > grading * (upper - cand.radii[c]) * (1.0 + 1e-12);
  }
  return certain;
}

// The size most of the data asks for: what the size predictions assume (h_min alone would
// over-predict a mesh whose sizes follow a coarser local sampling).
double typical_size(const AdaptiveMeshOptions& o) {
  if (o.point_size.empty()) return o.h_min;
  std::vector<double> s = o.point_size;
  std::nth_element(s.begin(), s.begin() + s.size() / 10, s.end());
  return std::max(o.h_min, s[s.size() / 10]);
}

}  // namespace

void validate(const AdaptiveMeshOptions& o) {
  if (!in_range(o.h_min, 0.0, 1.0)) {
    throw InvalidInput("h_min = " + std::to_string(o.h_min) + " is outside (0, 1)",
                       "h_min is relative to the unit box: try 1/128 (resolution 128)");
  }
  if (!(std::isfinite(o.h_max) && o.h_max >= o.h_min && o.h_max <= 1.0)) {
    throw InvalidInput("h_max = " + std::to_string(o.h_max) + " is outside [h_min, 1]",
                       "use h_max between h_min and 1, e.g. 1/8");
  }
  if (!(std::isfinite(o.grading) && o.grading > 0.0 && o.grading <= 100.0)) {
    throw InvalidInput("grading = " + std::to_string(o.grading) + " is outside (0, 100]",
                       "use a grading around 1 (smaller widens the fine band)");
  }
  if (o.max_vertices <= 0) {
    throw InvalidInput("max_vertices must be positive", "pass a positive count (lsr::reconstruct sets it from max_memory)");
  }
}

template <int D>
AdaptiveMesh<D> build_adaptive_mesh(const NearestPointIndex<D>& data,
                                    const AdaptiveMeshOptions& o, const Progress& progress) {
  validate(o);
  if (!o.point_size.empty() && o.point_size.size() != data.points().size()) {
    throw InvalidInput("point_size has " + std::to_string(o.point_size.size()) + " entries for " +
                           std::to_string(data.points().size()) + " points",
                       "pass one size per data point, or none");
  }
  AdaptiveMeshOptions predicted = o;
  predicted.h_min = typical_size(o);
  const double resolution = 1.0 / predicted.h_min;
  const double limit = double(o.max_vertices);
  const double lower_bound = occupied_cells<D>(data.points(), predicted.h_min);
  if (lower_bound > limit) {
    throw MeshTooLarge("a mesh at resolution " + std::to_string(int(resolution)) + " needs over " +
                           std::to_string(std::int64_t(lower_bound)) + " vertices (limit " +
                           std::to_string(o.max_vertices) + ")",
                       // occupied cells scale like resolution^(D-1) on a surface
                       std::floor(0.8 * resolution * std::pow(limit / lower_bound, 1.0 / (D - 1))));
  }

  // The background grid already meets h_max: cells are at most h_max wide.
  const int cells = 1 << int(std::ceil(std::log2(1.0 / o.h_max) - 1e-9));
  if (std::pow(cells + 1.0, D) > limit) {
    throw MeshTooLarge("the background grid for h_max = " + std::to_string(o.h_max) +
                           " alone needs more than " + std::to_string(o.max_vertices) + " vertices",
                       resolution);
  }
  KuhnBisectionForest<D> forest(cells);
  int passes = 0;
  // One pass per bisection level from the background cells down to h_min.
  const double expected_passes = std::max(1.0, std::ceil(D * std::log2(1.0 / (cells * o.h_min))));
  Candidates<D> cand = leaves_from(forest, 0, o.h_min, o.threads);
  std::vector<double> dist, bound;
  std::vector<Index> nearest;
  std::vector<Index> witness;  // per forest node: a data point near it, or -1
  const double largest_local =
      o.point_size.empty() ? o.h_min : std::max(o.h_min, *std::max_element(o.point_size.begin(), o.point_size.end()));
  while (!cand.nodes.empty()) {
    progress.update("mesh", std::min(1.0, passes / expected_passes));
    // A simplex is marked when a point is near (within its radius + size / grading) and its size
    // exceeds that point's local size. Children certain to be marked skip the search; the others
    // search for their nearest point only within that bound (exact where it matters, much
    // faster far out).
    const std::size_t nc = cand.nodes.size();
    witness.resize(forest.simplices().size(), -1);
    const std::vector<char> certain = certainly_marked(forest, cand, witness, data.points(), o.grading, largest_local, o.threads);
    Points<D> searched;
    bound.clear();
    for (std::size_t i = 0; i < nc; ++i) {
      if (certain[i]) continue;
      searched.push_back(cand.centroids[i]);
      bound.push_back(cand.sizes[i] > o.h_max ? std::numeric_limits<double>::infinity()
                                              : cand.radii[i] + cand.sizes[i] / o.grading);
    }
    data.query_within(searched, bound, dist, nearest, o.threads);
    const Index first_new = Index(forest.simplices().size());
    const Index vertices_before = Index(forest.vertices().size());
    double largest_marked = 0.0;
    std::vector<Index> marked;
    for (std::size_t i = 0, q = 0; i < nc; ++i) {
      const Index node = cand.nodes[i];
      const double size = cand.sizes[i];
      bool mark = true;
      if (certain[i]) {
        witness[std::size_t(node)] = witness[std::size_t(forest.simplices()[node].parent)];
      } else {
        const bool near = nearest[q] >= 0;  // a point within the bound
        const double dist_lower = near ? std::max(0.0, dist[q] - cand.radii[i]) : 0.0;
        const double local = !near || o.point_size.empty() ? o.h_min : std::max(o.h_min, o.point_size[nearest[q]]);
        mark = size > o.h_max || (near && size > local && size > o.grading * dist_lower);
        witness[std::size_t(node)] = nearest[q];
        ++q;
      }
      if (mark) {
        marked.push_back(node);
        largest_marked = std::max(largest_marked, size);
      }
    }
    if (marked.empty()) break;
    for (Index s : marked) {
      if (forest.is_leaf(s)) forest.refine(s);
    }
    ++passes;

    check_predicted_size<D>(double(forest.vertices().size()),
                            double(forest.vertices().size()) - vertices_before,
                            largest_marked / std::pow(2.0, 1.0 / D), predicted);
    cand = leaves_from(forest, first_new, o.h_min, o.threads);
  }
  AdaptiveMesh<D> out = leaf_mesh(std::move(forest));
  out.stats.passes = passes;
  return out;
}

template <int D>
AdaptiveMesh<D> leaf_mesh(KuhnBisectionForest<D> refined) {
  AdaptiveMesh<D> out;
  out.forest = std::move(refined);
  auto& forest = out.forest;
  forest.finish_refinement();
  // New index of each forest vertex: its rank in Z-order.
  std::vector<Index> rank(forest.vertices().size());
  {
    const std::vector<Index> order = z_order<D>(forest.vertices());
    for (std::size_t r = 0; r < order.size(); ++r) rank[std::size_t(order[r])] = Index(r);
  }
  out.mesh.vertices.resize(rank.size());
  for (std::size_t i = 0; i < rank.size(); ++i) out.mesh.vertices[std::size_t(rank[i])] = forest.vertices()[i];
  out.vertex_of_node_vertex = rank;
  const auto& nodes = forest.simplices();
  // Leaves bucketed by their smallest new vertex index (a counting sort: stable, linear).
  std::vector<Index> first(rank.size() + 1, 0);
  double finest = 1.0;
  for (Index s = 0; s < Index(nodes.size()); ++s) {
    if (!forest.is_leaf(s)) continue;
    Index lowest = rank[std::size_t(nodes[s].v[0])];
    for (Index v : nodes[s].v) lowest = std::min(lowest, rank[std::size_t(v)]);
    ++first[std::size_t(lowest) + 1];
    finest = std::min(finest, forest.size(s));
  }
  for (std::size_t i = 1; i < first.size(); ++i) first[i] += first[i - 1];
  out.simplex_of_node.assign(nodes.size(), -1);
  out.mesh.simplices.resize(std::size_t(forest.leaf_count()));
  for (Index s = 0; s < Index(nodes.size()); ++s) {
    if (!forest.is_leaf(s)) continue;
    std::array<Index, D + 1> v{};
    for (int k = 0; k <= D; ++k) v[k] = rank[std::size_t(nodes[s].v[k])];
    const Index at = first[std::size_t(*std::min_element(v.begin(), v.end()))]++;
    out.simplex_of_node[s] = at;
    out.mesh.simplices[std::size_t(at)] = v;
    if (signed_measure(out.mesh, at) < 0.0) std::swap(out.mesh.simplices[std::size_t(at)][D - 1], out.mesh.simplices[std::size_t(at)][D]);
  }
  out.stats.finest_size = finest;
  out.stats.uniform_vertices = Index(std::pow(std::round(1.0 / finest) + 1.0, D));
  return out;
}

template AdaptiveMesh<2> leaf_mesh<2>(KuhnBisectionForest<2>);
template AdaptiveMesh<3> leaf_mesh<3>(KuhnBisectionForest<3>);
template AdaptiveMesh<2> build_adaptive_mesh<2>(const NearestPointIndex<2>&,
                                                const AdaptiveMeshOptions&, const Progress&);
template AdaptiveMesh<3> build_adaptive_mesh<3>(const NearestPointIndex<3>&,
                                                const AdaptiveMeshOptions&, const Progress&);

}  // namespace lsr
