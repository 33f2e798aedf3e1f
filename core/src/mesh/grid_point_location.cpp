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

template <int D>
std::vector<Location<D>> locate_all(const SimplexMesh<D>& mesh, const Points<D>& points, int threads) {
  std::vector<Location<D>> out(points.size());
  if (mesh.simplices.empty()) return out;
  Vec<D> lo = mesh.vertices[0], hi = lo;
  for (const auto& v : mesh.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  const std::size_t ns = mesh.simplices.size();
  const int n = std::max(1, int(std::ceil(std::pow(double(ns), 1.0 / D))));
  const Vec<D> cell = (hi - lo) / n;
  const auto bucket_of = [&](const Vec<D>& x, int k) {
    return std::clamp(int(std::floor((x[k] - lo[k]) / cell[k])), 0, n - 1);
  };
  // CSR lists of the buckets, filled in two passes (count, then place).
  std::vector<Index> offsets(std::size_t(std::pow(n, D)) + 1, 0), entries;
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
        a[std::size_t(k)] = bucket_of(Vec<D>::Constant(smin), k);
        b[std::size_t(k)] = bucket_of(Vec<D>::Constant(smax), k);
      }
      std::array<int, D> i = a;
      for (;;) {
        std::size_t id = 0;
        for (int k = D - 1; k >= 0; --k) id = id * std::size_t(n) + std::size_t(i[std::size_t(k)]);
        if (pass == 0) {
          ++offsets[id + 1];
        } else {
          entries[std::size_t(fill[id]++)] = Index(s);
        }
        int k = 0;
        for (; k < D && i[std::size_t(k)] == b[std::size_t(k)]; ++k) i[std::size_t(k)] = a[std::size_t(k)];
        if (k == D) break;
        ++i[std::size_t(k)];
      }
    }
    if (pass == 0) {
      for (std::size_t k = 1; k < offsets.size(); ++k) offsets[k] += offsets[k - 1];
      entries.resize(std::size_t(offsets.back()));
    }
  }
  const long np = long(points.size());
#pragma omp parallel for schedule(static) num_threads(detail::thread_count(threads))
  for (long q = 0; q < np; ++q) {
    const Vec<D>& p = points[std::size_t(q)];
    if (!p.allFinite()) continue;
    std::size_t id = 0;
    bool inside = true;
    for (int k = D - 1; k >= 0; --k) {
      const double tol = 1e-12 * (hi[k] - lo[k]);
      inside = inside && p[k] >= lo[k] - tol && p[k] <= hi[k] + tol;
      id = id * std::size_t(n) + std::size_t(bucket_of(p, k));
    }
    if (!inside) continue;
    Location<D>& at = out[std::size_t(q)];
    double deepest = -std::numeric_limits<double>::infinity();
    for (Index e = offsets[id]; e < offsets[id + 1]; ++e) {
      const auto& s = mesh.simplices[std::size_t(entries[std::size_t(e)])];
      const Vec<D> x0 = mesh.vertices[std::size_t(s[0])];
      Eigen::Matrix<double, D, D> edges;
      for (int j = 0; j < D; ++j) edges.col(j) = mesh.vertices[std::size_t(s[std::size_t(j + 1)])] - x0;
      const Vec<D> w = edges.partialPivLu().solve(Vec<D>(p - x0));
      const double w0 = 1.0 - w.sum();
      const double least = std::min(w0, w.minCoeff());
      if (least <= deepest) continue;
      deepest = least;
      at.simplex = entries[std::size_t(e)];
      at.vertices = s;
      at.weights[0] = w0;
      for (int j = 0; j < D; ++j) at.weights[std::size_t(j + 1)] = w[j];
      if (least >= 0.0) break;  // inside: no other simplex holds it deeper but a neighbour at a tie
    }
    if (deepest < -1e-9) at = Location<D>();  // in a gap of the buckets' lists: cannot be, kept safe
  }
  return out;
}

template std::vector<Location<2>> locate_all<2>(const SimplexMesh<2>&, const Points<2>&, int);
template std::vector<Location<3>> locate_all<3>(const SimplexMesh<3>&, const Points<3>&, int);

}  // namespace lsr
