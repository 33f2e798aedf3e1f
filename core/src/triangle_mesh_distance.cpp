// SPDX-License-Identifier: BSD-3-Clause
#include "lsrecon/core/triangle_mesh_distance.h"

#include "lsrecon/core/errors.h"
#include "lsrecon/core/point_simplex_distance.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace lsr {
namespace {

using Triangles = std::vector<std::array<Index, 3>>;

const Triangles& checked(const Points<3>& vertices, const Triangles& triangles) {
  if (triangles.empty()) throw InvalidInput("the mesh has no triangle", "pass a closed triangle mesh");
  for (const auto& t : triangles) {
    for (Index v : t) {
      if (v < 0 || std::size_t(v) >= vertices.size()) {
        throw InvalidInput("a triangle refers to vertex " + std::to_string(v) + " of " + std::to_string(vertices.size()),
                           "check the mesh file");
      }
    }
  }
  return triangles;
}

Points<3> centroids(const Points<3>& x, const Triangles& triangles) {
  Points<3> c;
  c.reserve(triangles.size());
  for (const auto& t : triangles) c.push_back((x[t[0]] + x[t[1]] + x[t[2]]) / 3.0);
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

}  // namespace

TriangleMeshDistance::TriangleMeshDistance(Points<3> vertices, Triangles triangles)
    : vertices_(std::move(vertices)), triangles_(std::move(triangles)),
      vertex_index_(vertices_), centroid_index_(centroids(vertices_, checked(vertices_, triangles_))) {
  const std::size_t nf = triangles_.size();
  std::vector<double> reach(nf, 0.0);
  for (std::size_t f = 0; f < nf; ++f) {
    const Vec<3> c = centroid_index_.points()[f];
    for (Index v : triangles_[f]) reach[f] = std::max(reach[f], (vertices_[v] - c).norm());
  }
  std::vector<double> sorted = reach;
  std::nth_element(sorted.begin(), sorted.begin() + std::ptrdiff_t(nf / 2), sorted.end());
  const double large = 4.0 * sorted[nf / 2];
  for (std::size_t f = 0; f < nf; ++f) {
    if (reach[f] > large) {
      large_triangles_.push_back(Index(f));
    } else {
      small_reach_ = std::max(small_reach_, reach[f]);
    }
  }
  // The crossing grid over the (y, z) bounding box, about 4 shadows per cell.
  lo_ = hi_ = vertices_[triangles_[0][0]];
  for (const auto& t : triangles_) {
    for (Index v : t) {
      lo_ = lo_.cwiseMin(vertices_[v]);
      hi_ = hi_.cwiseMax(vertices_[v]);
    }
  }
  cells_ = std::clamp(int(std::sqrt(double(nf) / 4.0)), 1, 1024);
  auto cell_range = [&](const std::array<Index, 3>& t, int axis, int& first, int& last) {
    double a = vertices_[t[0]][axis], b = a;
    for (Index v : t) {
      a = std::min(a, vertices_[v][axis]);
      b = std::max(b, vertices_[v][axis]);
    }
    const double span = std::max(hi_[axis] - lo_[axis], 1e-300);
    first = std::clamp(int((a - lo_[axis]) / span * cells_), 0, cells_ - 1);
    last = std::clamp(int((b - lo_[axis]) / span * cells_), 0, cells_ - 1);
  };
  cell_offsets_.assign(std::size_t(cells_) * cells_ + 1, 0);
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<Index> fill(cell_offsets_.begin(), cell_offsets_.end() - 1);
    for (std::size_t f = 0; f < nf; ++f) {
      int y0, y1, z0, z1;
      cell_range(triangles_[f], 1, y0, y1);
      cell_range(triangles_[f], 2, z0, z1);
      for (int y = y0; y <= y1; ++y) {
        for (int z = z0; z <= z1; ++z) {
          const std::size_t cell = std::size_t(y) * cells_ + z;
          if (pass == 0) {
            ++cell_offsets_[cell + 1];
          } else {
            cell_triangles_[std::size_t(fill[cell]++)] = Index(f);
          }
        }
      }
    }
    if (pass == 0) {
      for (std::size_t c = 1; c < cell_offsets_.size(); ++c) cell_offsets_[c] += cell_offsets_[c - 1];
      cell_triangles_.resize(std::size_t(cell_offsets_.back()));
    }
  }
}

double TriangleMeshDistance::triangle_distance_to(const Vec<3>& q, Index f) const {
  const auto& t = triangles_[std::size_t(f)];
  return triangle_distance(q, vertices_[t[0]], vertices_[t[1]], vertices_[t[2]]);
}

double TriangleMeshDistance::distance(const Vec<3>& q) const {
  std::vector<double> nearest_vertex;
  vertex_index_.query(Points<3>{q}, nearest_vertex, nullptr, 1);
  double best = nearest_vertex[0];
  std::vector<Index> near;
  centroid_index_.within(q, best + small_reach_, near);
  for (Index f : near) best = std::min(best, triangle_distance_to(q, f));
  for (Index f : large_triangles_) best = std::min(best, triangle_distance_to(q, f));
  return best;
}

std::vector<double> TriangleMeshDistance::distances(const Points<3>& queries, int threads) const {
  std::vector<double> best;
  vertex_index_.query(queries, best, nullptr, threads);
#pragma omp parallel num_threads(threads > 0 ? threads : omp_get_max_threads())
  {
    std::vector<Index> near;
#pragma omp for schedule(dynamic, 256)
    for (std::ptrdiff_t q = 0; q < std::ptrdiff_t(queries.size()); ++q) {
      double b = best[std::size_t(q)];
      centroid_index_.within(queries[std::size_t(q)], b + small_reach_, near);
      for (Index f : near) b = std::min(b, triangle_distance_to(queries[std::size_t(q)], f));
      for (Index f : large_triangles_) b = std::min(b, triangle_distance_to(queries[std::size_t(q)], f));
      best[std::size_t(q)] = b;
    }
  }
  return best;
}

bool TriangleMeshDistance::inside(const Vec<3>& q) const {
  if (q.x() > hi_.x() || q.y() < lo_.y() || q.y() > hi_.y() || q.z() < lo_.z() || q.z() > hi_.z()) return false;
  auto cell_of = [&](int axis) {
    const double span = std::max(hi_[axis] - lo_[axis], 1e-300);
    return std::clamp(int((q[axis] - lo_[axis]) / span * cells_), 0, cells_ - 1);
  };
  const std::size_t cell = std::size_t(cell_of(1)) * cells_ + cell_of(2);
  bool odd = false;
  for (Index k = cell_offsets_[cell]; k < cell_offsets_[cell + 1]; ++k) {
    const auto& t = triangles_[std::size_t(cell_triangles_[std::size_t(k)])];
    const Vec<3>& a = vertices_[t[0]];
    const Vec<3>& b = vertices_[t[1]];
    const Vec<3>& c = vertices_[t[2]];
    const bool s0 = left_of(a, b, q), s1 = left_of(b, c, q), s2 = left_of(c, a, q);
    if (s0 != s1 || s1 != s2) continue;  // the (perturbed) ray misses this shadow
    // Where the ray meets the triangle's plane: n . (p - a) = 0 with p = q + s e_x.
    const Vec<3> n = (b - a).cross(c - a);
    if (n.x() == 0.0) continue;  // seen edge-on: no crossing
    const double s = n.dot(a - q) / n.x();
    if (s > 0.0) odd = !odd;
  }
  return odd;
}

double TriangleMeshDistance::signed_distance(const Vec<3>& q) const {
  const double d = distance(q);
  return inside(q) ? -d : d;
}

}  // namespace lsr
