// SPDX-License-Identifier: BSD-3-Clause
#include "geometry/facet_mesh_distance.h"

#include "geometry/point_simplex_distance.h"
#include "lsrecon/core/errors.h"
#include "thread_count.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace lsr {
namespace {

template <int D>
const std::vector<std::array<Index, D>>& checked(const Points<D>& vertices, const std::vector<std::array<Index, D>>& facets) {
  if (facets.empty()) throw InvalidInput("the mesh has no facet", "pass a closed curve or surface");
  for (const auto& t : facets) {
    for (Index v : t) {
      if (v < 0 || std::size_t(v) >= vertices.size()) {
        throw InvalidInput("a facet refers to vertex " + std::to_string(v) + " of " + std::to_string(vertices.size()),
                           "check the mesh file");
      }
    }
  }
  return facets;
}

template <int D>
Points<D> centroids(const Points<D>& x, const std::vector<std::array<Index, D>>& facets) {
  Points<D> c;
  c.reserve(facets.size());
  for (const auto& t : facets) {
    Vec<D> sum = Vec<D>::Zero();
    for (Index v : t) sum += x[v];
    c.push_back(sum / double(D));
  }
  return c;
}

// Which side of the directed edge a -> b the point q lies on, in the (y, z) plane, with q
// moved by (e, e^2) for an infinitesimal e when it lies on the edge's line: a shared edge,
// seen in opposite directions by its two triangles, then has q on exactly one side.
bool left_of(const Vec<3>& a, const Vec<3>& b, const Vec<3>& q) {
  const double dy = b.y() - a.y(), dz = b.z() - a.z();
  const double e = dy * (q.z() - a.z()) - dz * (q.y() - a.y());
  if (e != 0.0) return e > 0.0;
  if (dz != 0.0) return -dz > 0.0;  // d e / d q_y
  return dy > 0.0;                  // d e / d q_z
}

// Where the ray q + s e_x crosses the facet, or a negative s when it misses it.
double crossing(const std::array<Vec<2>, 2>& p, const Vec<2>& q) {
  // q moved up by an infinitesimal: an end at q's height counts as below.
  const bool above0 = p[0].y() > q.y(), above1 = p[1].y() > q.y();
  if (above0 == above1) return -1.0;
  const double x = p[0].x() + (q.y() - p[0].y()) * (p[1].x() - p[0].x()) / (p[1].y() - p[0].y());
  return x - q.x();
}

double crossing(const std::array<Vec<3>, 3>& p, const Vec<3>& q) {
  const bool s0 = left_of(p[0], p[1], q), s1 = left_of(p[1], p[2], q), s2 = left_of(p[2], p[0], q);
  if (s0 != s1 || s1 != s2) return -1.0;  // the (perturbed) ray misses this shadow
  const Vec<3> n = (p[1] - p[0]).cross(p[2] - p[0]);
  if (n.x() == 0.0) return -1.0;  // seen edge-on
  return n.dot(p[0] - q) / n.x();
}

}  // namespace

template <int D>
FacetMeshDistance<D>::FacetMeshDistance(Points<D> vertices, std::vector<Facet> facets)
    : vertices_(std::move(vertices)), facets_(std::move(facets)),
      vertex_index_(vertices_), centroid_index_(centroids<D>(vertices_, checked<D>(vertices_, facets_))) {
  const std::size_t nf = facets_.size();
  std::vector<double> reach(nf, 0.0);
  for (std::size_t f = 0; f < nf; ++f) {
    for (Index v : facets_[f]) reach[f] = std::max(reach[f], (vertices_[v] - centroid_index_.points()[f]).norm());
  }
  std::vector<double> sorted = reach;
  std::nth_element(sorted.begin(), sorted.begin() + std::ptrdiff_t(nf / 2), sorted.end());
  const double large = 4.0 * sorted[nf / 2];
  for (std::size_t f = 0; f < nf; ++f) {
    if (reach[f] > large) {
      large_facets_.push_back(Index(f));
    } else {
      small_reach_ = std::max(small_reach_, reach[f]);
    }
  }
  // The crossing grid over the shadows' bounding box, about 4 shadows per cell.
  lo_ = hi_ = vertices_[facets_[0][0]];
  for (const auto& t : facets_) {
    for (Index v : t) {
      lo_ = lo_.cwiseMin(vertices_[v]);
      hi_ = hi_.cwiseMax(vertices_[v]);
    }
  }
  cells_ = std::clamp(int(D == 3 ? std::sqrt(double(nf) / 4.0) : double(nf) / 4.0), 1, D == 3 ? 1024 : 1 << 20);
  auto range = [&](const Facet& t, int axis, int& first, int& last) {
    double a = vertices_[t[0]][axis], b = a;
    for (Index v : t) {
      a = std::min(a, vertices_[v][axis]);
      b = std::max(b, vertices_[v][axis]);
    }
    const double span = std::max(hi_[axis] - lo_[axis], 1e-300);
    first = std::clamp(int((a - lo_[axis]) / span * cells_), 0, cells_ - 1);
    last = std::clamp(int((b - lo_[axis]) / span * cells_), 0, cells_ - 1);
  };
  const std::size_t ncells = D == 3 ? std::size_t(cells_) * cells_ : std::size_t(cells_);
  cell_offsets_.assign(ncells + 1, 0);
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<Index> fill(cell_offsets_.begin(), cell_offsets_.end() - 1);
    for (std::size_t f = 0; f < nf; ++f) {
      int y0, y1, z0 = 0, z1 = 0;
      range(facets_[f], 1, y0, y1);
      if constexpr (D == 3) range(facets_[f], 2, z0, z1);
      for (int y = y0; y <= y1; ++y) {
        for (int z = z0; z <= z1; ++z) {
          const std::size_t cell = D == 3 ? std::size_t(y) * cells_ + z : std::size_t(y);
          if (pass == 0) {
            ++cell_offsets_[cell + 1];
          } else {
            cell_facets_[std::size_t(fill[cell]++)] = Index(f);
          }
        }
      }
    }
    if (pass == 0) {
      for (std::size_t c = 1; c < cell_offsets_.size(); ++c) cell_offsets_[c] += cell_offsets_[c - 1];
      cell_facets_.resize(std::size_t(cell_offsets_.back()));
    }
  }
}

template <int D>
double FacetMeshDistance<D>::facet_distance(const Vec<D>& q, Index f) const {
  const auto& t = facets_[std::size_t(f)];
  if constexpr (D == 2) {
    return segment_distance(q, vertices_[t[0]], vertices_[t[1]]);
  } else {
    return triangle_distance(q, vertices_[t[0]], vertices_[t[1]], vertices_[t[2]]);
  }
}

template <int D>
double FacetMeshDistance<D>::nearest(const Vec<D>& q, double vertex_distance, std::vector<Index>& scratch) const {
  double best = vertex_distance;
  centroid_index_.within(q, best + small_reach_, scratch);
  for (Index f : scratch) best = std::min(best, facet_distance(q, f));
  for (Index f : large_facets_) best = std::min(best, facet_distance(q, f));
  return best;
}

template <int D>
double FacetMeshDistance<D>::distance(const Vec<D>& q) const {
  std::vector<double> nearest_vertex;
  vertex_index_.query(Points<D>{q}, nearest_vertex, nullptr, 1);
  std::vector<Index> scratch;
  return nearest(q, nearest_vertex[0], scratch);
}

template <int D>
std::vector<double> FacetMeshDistance<D>::distances(const Points<D>& queries, int threads) const {
  std::vector<double> best;
  vertex_index_.query(queries, best, nullptr, threads);
#pragma omp parallel num_threads(detail::thread_count(threads))
  {
    std::vector<Index> scratch;
#pragma omp for schedule(dynamic, 256)
    for (std::ptrdiff_t q = 0; q < std::ptrdiff_t(queries.size()); ++q) {
      best[std::size_t(q)] = nearest(queries[std::size_t(q)], best[std::size_t(q)], scratch);
    }
  }
  return best;
}

template <int D>
std::size_t FacetMeshDistance<D>::cell_of(const Vec<D>& q) const {
  auto index = [&](int axis) {
    const double span = std::max(hi_[axis] - lo_[axis], 1e-300);
    return std::size_t(std::clamp(int((q[axis] - lo_[axis]) / span * cells_), 0, cells_ - 1));
  };
  if constexpr (D == 3) {
    return index(1) * std::size_t(cells_) + index(2);
  } else {
    return index(1);
  }
}

template <int D>
bool FacetMeshDistance<D>::inside(const Vec<D>& q) const {
  if (q.x() > hi_.x()) return false;
  for (int axis = 1; axis < D; ++axis) {
    if (q[axis] < lo_[axis] || q[axis] > hi_[axis]) return false;
  }
  const std::size_t cell = cell_of(q);
  bool odd = false;
  for (Index k = cell_offsets_[cell]; k < cell_offsets_[cell + 1]; ++k) {
    const Facet& t = facets_[std::size_t(cell_facets_[std::size_t(k)])];
    std::array<Vec<D>, D> p;
    for (int i = 0; i < D; ++i) p[i] = vertices_[t[i]];
    if (crossing(p, q) > 0.0) odd = !odd;
  }
  return odd;
}

template <int D>
double FacetMeshDistance<D>::signed_distance(const Vec<D>& q) const {
  const double d = distance(q);
  return inside(q) ? -d : d;
}

template class FacetMeshDistance<2>;
template class FacetMeshDistance<3>;

}  // namespace lsr
