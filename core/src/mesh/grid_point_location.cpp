// SPDX-License-Identifier: BSD-3-Clause
/// @file grid_point_location.cpp
/// @brief Point location in any simplicial mesh through a uniform grid of buckets: as many
/// buckets as simplices, each simplex listed in the buckets its bounding box meets, and a
/// point tested against the simplices of its bucket.
#include "mesh/point_location.h"

#include "thread_count.h"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <limits>

#include <omp.h>

namespace lsr {

namespace {

// The simplices listed by the cells of a uniform grid over the mesh's bounding box that their
// own bounding boxes overlap (CSR), about one simplex per cell.
template <int D>
struct SimplexGrid {
  Vec<D> lo, hi, cell;
  int n = 1;  ///< cells per side
  std::vector<Index> offsets, entries;
  int bucket(double x, int k) const { return std::clamp(int(std::floor((x - lo[k]) / cell[k])), 0, n - 1); }
};

template <int D>
SimplexGrid<D> bucket_simplices(const SimplexMesh<D>& mesh) {
  SimplexGrid<D> g;
  g.lo = mesh.vertices[0];
  g.hi = g.lo;
  for (const auto& v : mesh.vertices) {
    g.lo = g.lo.cwiseMin(v);
    g.hi = g.hi.cwiseMax(v);
  }
  const std::size_t ns = mesh.simplices.size();
  const int n = g.n = std::max(1, int(std::ceil(std::pow(double(ns), 1.0 / D))));
  g.cell = (g.hi - g.lo) / n;
  // Filled in two passes (count, then place).
  std::vector<Index>& offsets = g.offsets;
  offsets.assign(std::size_t(std::pow(n, D)) + 1, 0);
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<Index> fill(offsets.begin(), offsets.end() - 1);
    for (std::size_t s = 0; s < ns; ++s) {
      std::array<int, D> a{}, b{};
      for (int k = 0; k < D; ++k) {
        double smin = mesh.vertices[std::size_t(mesh.simplices[s][0])][k], smax = smin;
        for (int j = 1; j <= D; ++j) {
          smin = std::min(smin, mesh.vertices[std::size_t(mesh.simplices[s][std::size_t(j)])][k]);
          smax = std::max(smax, mesh.vertices[std::size_t(mesh.simplices[s][std::size_t(j)])][k]);
        }
        a[std::size_t(k)] = g.bucket(smin, k);
        b[std::size_t(k)] = g.bucket(smax, k);
      }
      std::array<int, D> i = a;
      for (;;) {
        std::size_t id = 0;
        for (int k = D - 1; k >= 0; --k) id = id * std::size_t(n) + std::size_t(i[std::size_t(k)]);
        if (pass == 0) {
          ++offsets[id + 1];
        } else {
          g.entries[std::size_t(fill[id]++)] = Index(s);
        }
        int k = 0;
        for (; k < D && i[std::size_t(k)] == b[std::size_t(k)]; ++k) i[std::size_t(k)] = a[std::size_t(k)];
        if (k == D) break;
        ++i[std::size_t(k)];
      }
    }
    if (pass == 0) {
      for (std::size_t k = 1; k < offsets.size(); ++k) offsets[k] += offsets[k - 1];
      g.entries.resize(std::size_t(offsets.back()));
    }
  }
  return g;
}

// The simplex of p's cell that holds p deepest (largest least barycentric coordinate); none
// outside the grid.
template <int D>
Location<D> locate_in_grid(const SimplexMesh<D>& mesh, const SimplexGrid<D>& g, const Vec<D>& p) {
  Location<D> at;
  if (!p.allFinite()) return at;
  std::size_t id = 0;
  bool inside = true;
  for (int k = D - 1; k >= 0; --k) {
    const double tol = 1e-12 * (g.hi[k] - g.lo[k]);
    inside = inside && p[k] >= g.lo[k] - tol && p[k] <= g.hi[k] + tol;
    id = id * std::size_t(g.n) + std::size_t(g.bucket(p[k], k));
  }
  if (!inside) return at;
  double deepest = -std::numeric_limits<double>::infinity();
  for (Index e = g.offsets[id]; e < g.offsets[id + 1]; ++e) {
    const auto& s = mesh.simplices[std::size_t(g.entries[std::size_t(e)])];
    const Vec<D> x0 = mesh.vertices[std::size_t(s[0])];
    Eigen::Matrix<double, D, D> edges;
    for (int j = 0; j < D; ++j) edges.col(j) = mesh.vertices[std::size_t(s[std::size_t(j + 1)])] - x0;
    const Vec<D> w = edges.partialPivLu().solve(Vec<D>(p - x0));
    const double w0 = 1.0 - w.sum();
    const double least = std::min(w0, w.minCoeff());
    if (least <= deepest) continue;
    deepest = least;
    at.simplex = g.entries[std::size_t(e)];
    at.vertices = s;
    at.weights[0] = w0;
    for (int j = 0; j < D; ++j) at.weights[std::size_t(j + 1)] = w[j];
    if (least >= 0.0) break;  // inside: no other simplex holds it deeper but a neighbour at a tie
  }
  if (deepest < -1e-9) at = Location<D>();  // in a gap of the buckets' lists: cannot be, kept safe
  return at;
}

}  // namespace

template <int D>
std::vector<Location<D>> locate_all(const SimplexMesh<D>& mesh, const Points<D>& points, int threads) {
  std::vector<Location<D>> out(points.size());
  if (mesh.simplices.empty()) return out;
  const SimplexGrid<D> grid = bucket_simplices(mesh);
  const long np = long(points.size());
#pragma omp parallel for schedule(static) num_threads(detail::thread_count(threads))
  for (long q = 0; q < np; ++q) out[std::size_t(q)] = locate_in_grid(mesh, grid, points[std::size_t(q)]);
  return out;
}

template std::vector<Location<2>> locate_all<2>(const SimplexMesh<2>&, const Points<2>&, int);
template std::vector<Location<3>> locate_all<3>(const SimplexMesh<3>&, const Points<3>&, int);

}  // namespace lsr
