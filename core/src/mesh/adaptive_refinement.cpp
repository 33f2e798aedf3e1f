// SPDX-License-Identifier: BSD-3-Clause
/// @file adaptive_refinement.cpp
/// @brief Pass-by-pass graded refinement: each pass tests the simplices created by the last
/// one and bisects those larger than the sizing function allows.
#include "mesh/adaptive_refinement.h"

#include "mesh/refinement_budget.h"
#include "thread_count.h"

#include "sampling/z_order.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cmath>
#include <exception>
#include <limits>
#include <new>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include <omp.h>

namespace lsr {
namespace {

using namespace detail;

// New forest nodes per marked leaf (its bisection and the closure's; calibrated). The lower end: pages faulted in beyond what the pass fills would
// stay resident.
constexpr double kNodesPerMark = 2.2;

// Bisects the marked leaves, serially (the closure's order decides the forest), while a second
// thread faults in the pages the pass will fill: the forest's next nodes and, where their
// storage has room, their witnesses (docs/calibration.md).
template <int D>
void refine_marked(KuhnBisectionForest<D>& forest, const std::vector<Index>& marked, const LargeVector<Index>& witness,
                   int threads) {
  auto refine_all = [&] {
    for (Index s : marked) {
      if (forest.is_leaf(s)) forest.refine(s);
    }
  };
  if (threads == 1 || omp_get_max_threads() < 2) return refine_all();
  const std::size_t now = forest.simplices().size();
  const std::size_t next = now + std::size_t(kNodesPerMark * double(marked.size()));
  const StorageRange nodes = storage_range(forest.simplices(), now, next);
  const StorageRange witnesses = storage_range(witness, witness.size(), next);
  std::exception_ptr failure;
  // The calling thread bisects: the vertex-to-leaf lists it allocates stay in its malloc arena
  // (bisecting on whichever thread took a section spreads them over two, and raises the peak).
#pragma omp parallel num_threads(2)
  if (omp_get_thread_num() == 0) {
    try {
      refine_all();
    } catch (...) {  // an exception must not leave an OpenMP region
      failure = std::current_exception();
    }
  } else {
    populate(nodes);
    populate(witnesses);
  }
  if (failure) std::rethrow_exception(failure);
}

template <int D>
Vec<D> centroid_of(const KuhnBisectionForest<D>& forest, Index s) {
  Vec<D> c = Vec<D>::Zero();
  for (Index v : forest.simplices()[s].v) c += forest.vertices()[v];
  return c / double(D + 1);
}

template <int D>
double radius_about(const KuhnBisectionForest<D>& forest, Index s, const Vec<D>& centre) {
  double r = 0.0;
  for (Index v : forest.simplices()[s].v) r = std::max(r, (forest.vertices()[v] - centre).norm());
  return r;
}

template <int D>
struct Candidates {
  LargeVector<Index> nodes;
  LargeVector<Vec<D>> centroids;
  LargeVector<double> radii;
  LargeVector<double> sizes;
  // Cleared first: a resize past the capacity then copies nothing over.
  void resize(std::size_t n) {
    nodes.clear(), centroids.clear(), radii.clear(), sizes.clear();
    nodes.resize(n), centroids.resize(n), radii.resize(n), sizes.resize(n);
  }
};

// The leaves created since `first` that a further bisection could concern: no simplex of size
// h_min or less is ever bisected (every local size is at least h_min), so those need no
// distance query. Listed in node order into `c`, whose storage is reused from pass to pass;
// each thread lists a contiguous range of nodes after counting it (sizes are per level: the
// count reads no vertex).
template <int D>
void leaves_from(const KuhnBisectionForest<D>& forest, Index first, double h_min, int threads, Candidates<D>& c) {
  const long n = std::max(0L, long(forest.simplices().size()) - long(first));
  auto listed = [&](long i) { return forest.is_leaf(first + Index(i)) && forest.size(first + Index(i)) > h_min; };
  std::vector<std::size_t> start;
#pragma omp parallel num_threads(thread_count(threads))
  {
    const int t = omp_get_thread_num();
    const int nt = omp_get_num_threads();
#pragma omp single
    start.assign(std::size_t(nt) + 1, 0);  // implicit barrier
    const long lo = n * t / nt;
    const long hi = n * (t + 1) / nt;
    std::size_t count = 0;
    for (long i = lo; i < hi; ++i) count += listed(i);
    start[std::size_t(t) + 1] = count;
#pragma omp barrier
#pragma omp single
    {
      for (int k = 0; k < nt; ++k) start[std::size_t(k) + 1] += start[std::size_t(k)];
      c.resize(start.back());
    }  // implicit barrier
    std::size_t at = start[std::size_t(t)];
    for (long i = lo; i < hi; ++i) {
      if (!listed(i)) continue;
      const Index s = first + Index(i);
      c.nodes[at] = s;
      c.sizes[at] = forest.size(s);
      c.centroids[at] = centroid_of(forest, s);
      c.radii[at] = radius_about(forest, s, c.centroids[at]);
      ++at;
    }
  }
}

// Whether the simplex's vertices' bounding box meets the region.
template <int D>
bool meets_region(const KuhnBisectionForest<D>& forest, Index s, const AdaptiveMeshOptions& o) {
  for (int a = 0; a < D; ++a) {
    double lo = 2.0, hi = -1.0;
    for (Index v : forest.simplices()[s].v) lo = std::min(lo, forest.vertices()[v][a]), hi = std::max(hi, forest.vertices()[v][a]);
    if (hi < o.region_lo[std::size_t(a)] || lo > o.region_hi[std::size_t(a)]) return false;
  }
  return true;
}

// What a candidate's search is known to return before it runs.
enum class Certain : char { no, marked, unmarked };

// Per forest node: the data point nearest its centroid (>= 0), a point inherited from its parent
// (encoded by inherited()), not searched, or searched and no point found within its bound.
constexpr Index kNoWitness = -1;
constexpr Index kEmptyBall = -2;
constexpr Index inherited(Index point) { return -3 - point; }
constexpr Index witness_point(Index w) { return w >= 0 ? w : w <= -3 ? -3 - w : -1; }

// For a data point w and any point q within one cell of it, an upper bound on q's local size:
// the largest local size over the 3^D grid cells around w's cell. It lets the last passes,
// whose sizes lie among the local sizes, certify marks without a search.
template <int D>
class NearbyLargestSize {
 public:
  NearbyLargestSize(const Points<D>& points, const std::vector<double>& local, double floor, double cell, int threads)
      : cell_(std::max(cell, std::ldexp(1.0, -18))), around_(points.size(), floor) {
    if (local.empty()) return;
    std::unordered_map<std::uint64_t, double> largest;
    largest.reserve(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
      double& m = largest[key(cell_of(points[i]))];
      m = std::max(m, local[i]);
    }
    const long n = long(points.size());
#pragma omp parallel num_threads(thread_count(threads))
    {
      std::uint64_t last = ~std::uint64_t(0);
      double last_value = 0.0;
#pragma omp for schedule(static)
      for (long i = 0; i < n; ++i) {
        const std::array<std::int64_t, D> c = cell_of(points[std::size_t(i)]);
        if (key(c) != last) {  // Z-ordered points share cells in runs
          last = key(c);
          last_value = floor;
          for (int k = 0; k < ipow3(); ++k) {
            std::array<std::int64_t, D> d = c;
            for (int a = 0, m = k; a < D; ++a, m /= 3) d[a] += m % 3 - 1;
            const auto it = largest.find(key(d));
            if (it != largest.end()) last_value = std::max(last_value, it->second);
          }
        }
        around_[std::size_t(i)] = last_value;
      }
    }
  }
  double cell() const { return cell_; }
  double at(Index w) const { return around_[std::size_t(w)]; }

 private:
  static constexpr int ipow3() { return D == 2 ? 9 : 27; }
  std::array<std::int64_t, D> cell_of(const Vec<D>& p) const {
    std::array<std::int64_t, D> c{};
    // Clamping moves no two cells further apart: a bound over merged cells is still a bound.
    for (int a = 0; a < D; ++a) c[a] = std::clamp<std::int64_t>(std::int64_t(std::floor(p[a] / cell_)) + 2, 1, (1 << 21) - 2);
    return c;
  }
  static std::uint64_t key(const std::array<std::int64_t, D>& c) {
    std::uint64_t k = 0;
    for (int a = 0; a < D; ++a) k = (k << 21) ^ std::uint64_t(c[a]);
    return k;
  }
  double cell_;
  std::vector<double> around_;
};

// Any data point bounds the distance from above: a candidate whose parent's witness point is
// within its marking distance, and which is larger than every local size, is marked whatever
// its nearest point (it inherits the witness). The parent's search bounds the distance from
// below, by its nearest point's distance or, if it found none, by its own bound: a child
// whose bound lies inside that empty ball finds nothing and stays unmarked.
template <int D>
std::vector<Certain> certain_outcomes(const KuhnBisectionForest<D>& forest, const Candidates<D>& cand,
                                      const LargeVector<Index>& witness, const Points<D>& points,
                                      const AdaptiveMeshOptions& o, double largest_local,
                                      const NearbyLargestSize<D>& nearby) {
  const long n = long(cand.nodes.size());
  std::vector<Certain> certain(cand.nodes.size(), Certain::no);
#pragma omp parallel for schedule(static) num_threads(thread_count(o.threads))
  for (long i = 0; i < n; ++i) {
    const std::size_t c = std::size_t(i);
    const Index parent = forest.simplices()[cand.nodes[c]].parent;
    const Index w = parent >= 0 ? witness[std::size_t(parent)] : kNoWitness;
    if ((w == kEmptyBall || w >= 0) && cand.sizes[c] <= o.h_max) {
      const Vec<D> centre = centroid_of(forest, parent);
      const double empty = w >= 0 ? (centre - points[std::size_t(w)]).norm()
                                  : radius_about(forest, parent, centre) + forest.size(parent) / o.grading;
      const double reach = cand.radii[c] + cand.sizes[c] / o.grading;
      if (empty - (cand.centroids[c] - centre).norm() > reach * (1.0 + 1e-12)) {
        certain[c] = Certain::unmarked;
        continue;
      }
    }
    const Index point = witness_point(w);
    if (point < 0) continue;
    const double upper = (cand.centroids[c] - points[std::size_t(point)]).norm();
    const double ceiling = 2.0 * upper <= nearby.cell() ? nearby.at(point) : largest_local;
    if (cand.sizes[c] > ceiling && cand.sizes[c] > o.grading * (upper - cand.radii[c]) * (1.0 + 1e-12)) certain[c] = Certain::marked;
  }
  return certain;
}

// The centroids of the candidates whose outcome is not certain, and how far to search from
// each: its radius + size / grading (any distance for a simplex wider than h_max).
template <int D>
void uncertain_searches(const Candidates<D>& cand, const std::vector<Certain>& certain, const AdaptiveMeshOptions& o,
                        Points<D>& searched, std::vector<double>& bound) {
  searched.clear();
  bound.clear();
  for (std::size_t i = 0; i < cand.nodes.size(); ++i) {
    if (certain[i] != Certain::no) continue;
    searched.push_back(cand.centroids[i]);
    bound.push_back(cand.sizes[i] > o.h_max ? std::numeric_limits<double>::infinity() : cand.radii[i] + cand.sizes[i] / o.grading);
  }
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
  const AdaptiveMeshOptions predicted = checked_prediction(data, o);
  const int cells = background_cells(o.h_max);
  KuhnBisectionForest<D> forest(cells);
  int passes = 0;
  // One pass per bisection level from the background cells down to h_min.
  const double expected_passes = std::max(1.0, std::ceil(D * std::log2(1.0 / (cells * o.h_min))));
  Candidates<D> cand;
  leaves_from(forest, 0, o.h_min, o.threads, cand);
  std::vector<double> dist, bound;
  std::vector<Index> nearest;
  Points<D> searched;  // kept across passes: its storage is faulted in once
  LargeVector<Index> witness;  // per forest node: a data point near it, kNoWitness or kEmptyBall
  const double largest_local =
      o.point_size.empty() ? o.h_min : std::max(o.h_min, *std::max_element(o.point_size.begin(), o.point_size.end()));
  // 4 typical sizes (calibrated: docs/calibration.md).
  const NearbyLargestSize<D> nearby(data.points(), o.point_size, o.h_min, 4.0 * predicted.h_min, o.threads);
  const RefiningPoints refining(o);
  PassHistory history;
  history.vertices.push_back(double(forest.vertices().size()));
  while (!cand.nodes.empty()) {
    progress.update("mesh", std::min(1.0, passes / expected_passes));
    // A simplex is marked when a point is near (within its radius + size / grading) and its size
    // exceeds that point's local size. Children whose outcome is certain skip the search; the others
    // search for their nearest point only within that bound (exact where it matters, much
    // faster far out).
    const std::size_t nc = cand.nodes.size();
    witness.resize(forest.simplices().size(), kNoWitness);
    std::vector<Certain> certain = certain_outcomes(forest, cand, witness, data.points(), o, largest_local, nearby);
    // Outside the region nothing is marked; no child inside reads these witnesses (a child
    // meeting the region has a parent that meets it).
    for (std::size_t i = 0; i < nc && !o.region_lo.empty(); ++i) {
      if (!meets_region(forest, cand.nodes[i], o)) certain[i] = Certain::unmarked;
    }
    uncertain_searches(cand, certain, o, searched, bound);
    data.query_within(searched, bound, dist, nearest, o.threads);
    const Index first_new = Index(forest.simplices().size());
    double largest_marked = 0.0;
    std::vector<Index> marked;
    for (std::size_t i = 0, q = 0; i < nc; ++i) {
      const Index node = cand.nodes[i];
      const double size = cand.sizes[i];
      bool mark = true;
      if (certain[i] == Certain::marked) {
        witness[std::size_t(node)] = inherited(witness_point(witness[std::size_t(forest.simplices()[node].parent)]));
      } else if (certain[i] == Certain::unmarked) {
        mark = false;
        witness[std::size_t(node)] = kEmptyBall;
      } else {
        const bool near = nearest[q] >= 0;  // a point within the bound
        const double dist_lower = near ? std::max(0.0, dist[q] - cand.radii[i]) : 0.0;
        const double local = !near || o.point_size.empty() ? o.h_min : std::max(o.h_min, o.point_size[nearest[q]]);
        mark = size > o.h_max || (near && size > local && size > o.grading * dist_lower);
        witness[std::size_t(node)] = near ? nearest[q] : kEmptyBall;
        ++q;
      }
      if (mark) {
        marked.push_back(node);
        largest_marked = std::max(largest_marked, size);
      }
    }
    if (marked.empty()) break;
    refine_marked(forest, marked, witness, o.threads);
    ++passes;

    history.vertices.push_back(double(forest.vertices().size()));
    history.bisected.push_back(largest_marked);
    check_predicted_size<D>(history, predicted, refining);
    reserve_predicted(forest, first_new, history, predicted.h_min, refining);
    leaves_from(forest, first_new, o.h_min, o.threads, cand);
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
  }
  const long ns = long(out.mesh.simplices.size());
#pragma omp parallel for schedule(static)
  for (long s = 0; s < ns; ++s) {
    auto& v = out.mesh.simplices[std::size_t(s)];
    if (signed_measure(out.mesh, Index(s)) < 0.0) std::swap(v[D - 1], v[D]);
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
