// SPDX-License-Identifier: BSD-3-Clause
/// @file renormalization.cpp
/// @brief Closest-facet propagation along mesh edges, in Jacobi rounds: each round reads the
/// previous one's closest facets only, so the result does not depend on the thread count.
#include "evolution/renormalization.h"

#include "geometry/point_simplex_distance.h"
#include "lsrecon/core/large_array_allocator.h"
#include "thread_count.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include <omp.h>

namespace lsr {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Distance from p to facet f; `corner` (if given) becomes the local index of the facet vertex
// that is the closest point, or -1.
template <int D>
double facet_distance(const LevelSetMesh<D>& front, Index f, const Vec<D>& p, int* corner = nullptr) {
  const auto& v = front.facets[f];
  if constexpr (D == 2) {
    return segment_distance(p, front.vertices[v[0]], front.vertices[v[1]], corner);
  } else {
    return triangle_distance(p, front.vertices[v[0]], front.vertices[v[1]], front.vertices[v[2]], corner);
  }
}

// A ball around each facet (centroid, farthest corner): |p - centre| - radius bounds the
// distance from below, so most offers that cannot win skip the exact distance. The radius is
// padded so that rounding never lets the bound pass the computed distance.
template <int D>
struct FacetBalls {
  LargeVector<Vec<D>> centre;
  LargeVector<double> radius;
  FacetBalls(const LevelSetMesh<D>& front, int threads) : centre(front.facets.size()), radius(front.facets.size()) {
    const long nf = long(front.facets.size());
#pragma omp parallel for schedule(static) num_threads(threads)
    for (long f = 0; f < nf; ++f) {
      Vec<D> c = Vec<D>::Zero();
      for (Index v : front.facets[f]) c += front.vertices[v];
      c /= double(D);
      double r = 0.0;
      for (Index v : front.facets[f]) r = std::max(r, (front.vertices[v] - c).norm());
      centre[f] = c;
      radius[f] = r * (1.0 + 1e-9) + 1e-12 * c.norm();
    }
  }
  // True when facet f is certainly farther from p than `best`.
  bool farther(Index f, const Vec<D>& p, double best) const {
    const double lower = (p - centre[f]).norm() - radius[f];
    return lower > best * (1.0 + 1e-12);
  }
};

// The nearest facet so far of every vertex; ties go to the lower facet index.
struct Closest {
  LargeVector<double> distance;
  LargeVector<Index> facet;
};

// The distinct ends of the mesh edges under facet f's vertices: all lie in one simplex, so at
// most D + 1; unused entries -1.
template <int D>
std::array<Index, D + 1> facet_ends(const LevelSetMesh<D>& front, Index f) {
  std::array<Index, D + 1> ends;
  ends.fill(-1);
  int count = 0;
  for (Index k : front.facets[f]) {
    for (Index v : {front.sources[k].a, front.sources[k].b}) {
      if (count <= D && std::find(ends.begin(), ends.begin() + count, v) == ends.begin() + count) ends[count++] = v;
    }
  }
  return ends;
}

// Lowers *at to value if smaller, from any thread.
template <typename T>
void atomic_min(T* at, T value) {
  T seen = __atomic_load_n(at, __ATOMIC_RELAXED);
  while (value < seen && !__atomic_compare_exchange_n(at, &seen, value, true, __ATOMIC_RELAXED, __ATOMIC_RELAXED)) {
  }
}

// A non-negative double's bits order as the double does.
std::uint64_t bits_of(double d) {
  std::uint64_t b;
  std::memcpy(&b, &d, sizeof b);
  return b;
}

// The vertices of the crossed simplices: the ends of the mesh edges under every facet
// measured against that facet, whatever the band (they carry the zero set). Each takes its
// nearest facet, the lowest index among equals: the smallest distance, then the smallest
// facet at that distance, both as atomic minima, so the result does not depend on the
// threads. Returns the seeded vertices in index order.
template <int D>
std::vector<Index> seed(const SimplexMesh<D>& mesh, const LevelSetMesh<D>& front, Closest& c, int threads) {
  const long nf = long(front.facets.size());
  const long nv = long(mesh.vertices.size());
  LargeVector<std::array<double, D + 1>> d(front.facets.size());
  LargeVector<std::uint64_t> nearest(mesh.vertices.size(), bits_of(kInfinity));
  LargeVector<Index> facet(mesh.vertices.size(), std::numeric_limits<Index>::max());
#pragma omp parallel num_threads(threads)
  {
#pragma omp for schedule(static)
    for (long f = 0; f < nf; ++f) {
      const auto ends = facet_ends(front, Index(f));
      for (int i = 0; i <= D && ends[i] >= 0; ++i) {
        d[f][i] = facet_distance(front, Index(f), mesh.vertices[ends[i]]);
        atomic_min(&nearest[ends[i]], bits_of(d[f][i]));
      }
    }
    // Recomputed rather than stored: the renormalisation is the solver's memory peak.
#pragma omp for schedule(static)
    for (long f = 0; f < nf; ++f) {
      const auto ends = facet_ends(front, Index(f));
      for (int i = 0; i <= D && ends[i] >= 0; ++i) {
        if (bits_of(d[f][i]) == nearest[ends[i]]) atomic_min(&facet[ends[i]], Index(f));
      }
    }
#pragma omp for schedule(static)
    for (long v = 0; v < nv; ++v) {
      if (facet[v] == std::numeric_limits<Index>::max()) continue;
      std::memcpy(&c.distance[v], &nearest[v], sizeof(double));
      c.facet[v] = facet[v];
    }
  }
  std::vector<Index> seeded;
  for (long v = 0; v < nv; ++v) {
    if (c.facet[v] >= 0) seeded.push_back(Index(v));
  }
  return seeded;
}

// Vertex w's best offer among the closest facets of its neighbours that changed in the last
// round (each facet measured once).
template <int D>
std::pair<double, Index> best_offer(const SimplexMesh<D>& mesh, const VertexNeighbours& g, const LevelSetMesh<D>& front,
                                    const FacetBalls<D>& balls, const Closest& c, const LargeVector<char>& changed,
                                    Index w) {
  std::array<Index, 48> tried;  // only the first n_tried are read
  int n_tried = 0;
  double best = c.distance[w];
  Index best_facet = c.facet[w];
  for (Index k = g.offsets[w]; k < g.offsets[w + 1]; ++k) {
    if (!changed[g.neighbours[k]]) continue;
    const Index f = c.facet[g.neighbours[k]];
    if (f < 0 || f == best_facet || std::find(tried.begin(), tried.begin() + n_tried, f) != tried.begin() + n_tried) continue;
    if (n_tried < int(tried.size())) tried[n_tried++] = f;
    if (balls.farther(f, mesh.vertices[w], best)) continue;
    const double d = facet_distance(front, f, mesh.vertices[w]);
    if (d < best || (d == best && f < best_facet)) {
      best = d;
      best_facet = f;
    }
  }
  return {best, best_facet};
}

// The front's adjacency: the facets through each front vertex (CSR) and, per facet, its D
// neighbours across its sides (a side of a triangle is an edge, of a segment a vertex), -1
// where the front is open (never, for a front extracted from a mesh).
template <int D>
struct FrontAdjacency {
  LargeVector<Index> offsets, around;
  LargeVector<std::array<Index, D>> next;
};

template <int D>
FrontAdjacency<D> front_adjacency(const LevelSetMesh<D>& front, int threads) {
  FrontAdjacency<D> adjacency;
  auto& offsets = adjacency.offsets;
  auto& around = adjacency.around;
  offsets.assign(front.vertices.size() + 1, 0);
  for (const auto& f : front.facets) {
    for (Index v : f) ++offsets[v + 1];
  }
  for (std::size_t v = 0; v < front.vertices.size(); ++v) offsets[v + 1] += offsets[v];
  around.resize(offsets.back());
  LargeVector<Index> fill(offsets.begin(), offsets.end() - 1);
  for (Index f = 0; f < Index(front.facets.size()); ++f) {
    for (Index v : front.facets[f]) around[fill[v]++] = f;
  }
  const long nf = long(front.facets.size());
  auto& next = adjacency.next;
  next.resize(front.facets.size());
#pragma omp parallel for schedule(static) num_threads(threads)
  for (long f = 0; f < nf; ++f) {
    const auto& v = front.facets[f];
    for (int k = 0; k < D; ++k) {
      // The side opposite vertex k: vertex k itself for a segment, the other two for a triangle.
      const Index a = D == 2 ? v[k] : v[(k + 1) % D];
      const Index b = D == 2 ? v[k] : v[(k + 2) % D];
      next[f][k] = -1;
      for (Index e = offsets[a]; e < offsets[a + 1]; ++e) {
        const Index g = around[e];
        const auto& w = front.facets[g];
        if (g != Index(f) && std::find(w.begin(), w.end(), b) != w.end()) next[f][k] = g;
      }
    }
  }
  return adjacency;
}

// Where the facets' Voronoi regions narrow below an edge (inside a curved front), the closest
// facet of a vertex may be no neighbour's closest, only next to one: walk over the front from
// the propagated facet across its sides while that gets closer and, where the nearest point
// is a corner of the facet, to the facets around that corner (a side walk can stop there
// while a facet through the corner is closer).
template <int D>
void descend(const SimplexMesh<D>& mesh, const LevelSetMesh<D>& front, const FrontAdjacency<D>& adjacency,
             const FacetBalls<D>& balls, Closest& c, int threads) {
  const long n = long(mesh.vertices.size());
#pragma omp parallel for schedule(dynamic, 1024) num_threads(threads)
  for (long w = 0; w < n; ++w) {
    Index f = c.facet[w];
    if (f < 0) continue;
    const Vec<D>& p = mesh.vertices[w];
    int corner = -1;
    double best = facet_distance(front, f, p, &corner);
    auto offer = [&](Index g) {
      if (balls.farther(g, p, best)) return;
      int g_corner = -1;
      const double d = facet_distance(front, g, p, &g_corner);
      if (d < best) {
        best = d;
        f = g;
        corner = g_corner;
      }
    };
    for (Index previous = -1; previous != f;) {
      previous = f;
      for (Index g : adjacency.next[previous]) {
        if (g >= 0) offer(g);
      }
      if (previous == f && corner >= 0) {
        const Index v = front.facets[f][corner];
        for (Index k = adjacency.offsets[v]; k < adjacency.offsets[v + 1]; ++k) {
          if (adjacency.around[k] != f) offer(adjacency.around[k]);
        }
      }
    }
    c.distance[w] = best;
    c.facet[w] = f;
  }
}

// Jacobi rounds from the seeded vertices until no closest facet changes within the band. The
// candidates of a round (neighbours of the vertices changed in the last one) are marked in
// parallel and listed in index order, which keeps the memory walks local.
template <int D>
void propagate(const SimplexMesh<D>& mesh, const VertexNeighbours& g, const LevelSetMesh<D>& front,
               const FacetBalls<D>& balls, double band, std::vector<Index> changed, Closest& c, int threads) {
  const long nv = long(mesh.vertices.size());
  LargeVector<char> listed(mesh.vertices.size(), 0), is_changed(mesh.vertices.size(), 0);
  LargeVector<Index> candidates;
  LargeVector<std::pair<double, Index>> offer;
  while (!changed.empty()) {
    const long nc = long(changed.size());
#pragma omp parallel for schedule(static) num_threads(threads)
    for (long i = 0; i < nc; ++i) {
      const Index v = changed[i];
      is_changed[v] = 1;
      for (Index k = g.offsets[v]; k < g.offsets[v + 1]; ++k) {
#pragma omp atomic write
        listed[g.neighbours[k]] = 1;
      }
    }
    candidates.clear();
    for (long w = 0; w < nv; ++w) {
      if (listed[w]) candidates.push_back(Index(w));
    }
    offer.resize(candidates.size());
    const long n = long(candidates.size());
#pragma omp parallel for schedule(dynamic, 1024) num_threads(threads)
    for (long i = 0; i < n; ++i) {
      offer[i] = best_offer(mesh, g, front, balls, c, is_changed, candidates[i]);
      listed[candidates[i]] = 0;
    }
    for (Index v : changed) is_changed[v] = 0;
    changed.clear();
    for (std::size_t i = 0; i < candidates.size(); ++i) {
      const Index w = candidates[i];
      const auto [d, f] = offer[i];
      if (f == c.facet[w]) continue;
      c.distance[w] = d;
      c.facet[w] = f;
      // Beyond the band the facet is kept for the descent, not passed on: on stretched
      // simplices a vertex within the band may have no neighbour nearer the front than it is.
      if (d < band) changed.push_back(w);
    }
  }
}

}  // namespace

template <int D>
RenormalizationReport<D> renormalize(const SimplexMesh<D>& mesh, const VertexNeighbours& neighbours,
                                     Eigen::VectorXd& u, double band, int threads) {
  threads = detail::thread_count(threads);
  RenormalizationReport<D> report;
  const std::vector<double> values(u.data(), u.data() + u.size());
  report.front = extract_zero_level_set(mesh, values, 1e-9, threads);
  if (report.front.facets.empty()) return report;

  Closest c{LargeVector<double>(mesh.vertices.size(), kInfinity), LargeVector<Index>(mesh.vertices.size(), -1)};
  const FacetBalls<D> balls(report.front, threads);
  propagate(mesh, neighbours, report.front, balls, band, seed(mesh, report.front, c, threads), c, threads);
  descend(mesh, report.front, front_adjacency(report.front, threads), balls, c, threads);
  for (Eigen::Index i = 0; i < u.size(); ++i) {
    // Beyond the band (or cut off from the front, which a connected mesh never is): +-band.
    const bool within = c.facet[i] >= 0 && c.distance[i] < band;
    const double d = within ? c.distance[i] : (std::isfinite(band) ? band : std::abs(u[i]));
    u[i] = u[i] < 0.0 ? -d : d;
    report.band_vertices += within;
  }
  return report;
}

template <int D>
RenormalizationReport<D> renormalize(const SimplexMesh<D>& mesh, Eigen::VectorXd& u, double band, int threads) {
  return renormalize(mesh, vertex_neighbours(mesh, threads), u, band, threads);
}

template RenormalizationReport<2> renormalize<2>(const SimplexMesh<2>&, const VertexNeighbours&, Eigen::VectorXd&, double, int);
template RenormalizationReport<3> renormalize<3>(const SimplexMesh<3>&, const VertexNeighbours&, Eigen::VectorXd&, double, int);
template RenormalizationReport<2> renormalize<2>(const SimplexMesh<2>&, Eigen::VectorXd&, double, int);
template RenormalizationReport<3> renormalize<3>(const SimplexMesh<3>&, Eigen::VectorXd&, double, int);

}  // namespace lsr
