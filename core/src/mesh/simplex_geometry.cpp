// SPDX-License-Identifier: BSD-3-Clause
/// @file simplex_geometry.cpp
#include "lsrecon/core/simplex_geometry.h"

#include "lsrecon/core/errors.h"
#include "thread_count.h"

#include <Eigen/LU>

#include <algorithm>
#include <string>

#include <omp.h>

namespace lsr {
namespace {

template <int D>
Eigen::Matrix<double, D, D> edge_matrix(const SimplexMesh<D>& mesh, Index s) {
  const auto& v = mesh.simplices[s];
  Eigen::Matrix<double, D, D> J;
  for (int k = 0; k < D; ++k) J.col(k) = mesh.vertices[v[k + 1]] - mesh.vertices[v[0]];
  return J;
}

constexpr double factorial(int d) { return d <= 1 ? 1.0 : d * factorial(d - 1); }

// CSR of the simplices around each vertex, in increasing simplex order.
template <int D>
void list_balls(const SimplexMesh<D>& mesh, LargeVector<Index>& offsets, LargeVector<Index>& around) {
  const std::size_t nv = mesh.vertices.size();
  offsets.assign(nv + 1, 0);
  for (const auto& simplex : mesh.simplices) {
    for (Index v : simplex) ++offsets[std::size_t(v) + 1];
  }
  for (std::size_t v = 0; v < nv; ++v) offsets[v + 1] += offsets[v];
  around.resize(std::size_t(offsets[nv]));
  std::vector<Index> fill(offsets.begin(), offsets.end() - 1);
  for (Index s = 0; s < Index(mesh.simplices.size()); ++s) {
    for (Index v : mesh.simplices[std::size_t(s)]) around[std::size_t(fill[std::size_t(v)]++)] = s;
  }
}

// The distinct other vertices of the simplices around each vertex, sorted: per vertex, in
// parallel (a per-thread stamp marks the ones already listed). Twice: once to count the rows,
// once to fill them.
template <int D>
VertexNeighbours neighbours_from_balls(const SimplexMesh<D>& mesh, const LargeVector<Index>& ball_start,
                                       const LargeVector<Index>& around, int threads) {
  const std::size_t nv = mesh.vertices.size();
  VertexNeighbours g;
  g.offsets.assign(nv + 1, 0);
  const long n = long(nv);
  for (int pass = 0; pass < 2; ++pass) {
    if (pass == 1) {
      for (std::size_t v = 0; v < nv; ++v) g.offsets[v + 1] += g.offsets[v];
      g.neighbours.resize(std::size_t(g.offsets[nv]));
    }
#pragma omp parallel num_threads(detail::thread_count(threads))
    {
      std::vector<Index> stamp(nv, -1), row;
#pragma omp for schedule(static)
      for (long v = 0; v < n; ++v) {
        row.clear();
        for (Index k = ball_start[std::size_t(v)]; k < ball_start[std::size_t(v) + 1]; ++k) {
          for (Index w : mesh.simplices[std::size_t(around[std::size_t(k)])]) {
            if (w == Index(v) || stamp[std::size_t(w)] == Index(v)) continue;
            stamp[std::size_t(w)] = Index(v);
            row.push_back(w);
          }
        }
        if (pass == 0) {
          g.offsets[std::size_t(v) + 1] = Index(row.size());
        } else {
          std::sort(row.begin(), row.end());
          std::copy(row.begin(), row.end(), g.neighbours.begin() + g.offsets[std::size_t(v)]);
        }
      }
    }
  }
  return g;
}

}  // namespace

template <int D>
double signed_measure(const SimplexMesh<D>& mesh, Index s) {
  return edge_matrix(mesh, s).determinant() / factorial(D);
}

// lambda_k(x) = e_k . J^-1 (x - x0) for k >= 1, so grad lambda_k is row k-1 of J^-1.
template <int D>
std::array<Vec<D>, D + 1> gradients_from(const Eigen::Matrix<double, D, D>& J) {
  const Eigen::Matrix<double, D, D> Jinv = J.inverse();
  std::array<Vec<D>, D + 1> grad;
  Vec<D> sum = Vec<D>::Zero();
  for (int k = 1; k <= D; ++k) {
    grad[k] = Jinv.row(k - 1).transpose();
    sum += grad[k];
  }
  grad[0] = -sum;
  return grad;
}

template <int D>
std::array<Vec<D>, D + 1> barycentric_gradients(const SimplexMesh<D>& mesh, Index s) {
  return gradients_from<D>(edge_matrix(mesh, s));
}

template <int D>
SimplexGeometry<D> compute_simplex_geometry(const SimplexMesh<D>& mesh, bool with_gradients) {
  const Index ns = Index(mesh.simplices.size());
  const Index nv = Index(mesh.vertices.size());
  SimplexGeometry<D> g;
  g.measure.resize(ns);
  if (with_gradients) g.gradients.resize(ns);
  Index degenerate = -1;
#pragma omp parallel for schedule(static)
  for (Index s = 0; s < ns; ++s) {
    const Eigen::Matrix<double, D, D> J = edge_matrix(mesh, s);
    const double det = J.determinant();
    if (!(std::abs(det) > 0.0)) {
#pragma omp critical
      degenerate = degenerate < 0 ? s : std::min(degenerate, s);
      continue;
    }
    g.measure[s] = std::abs(det) / factorial(D);
    if (with_gradients) g.gradients[s] = gradients_from<D>(J);
  }
  if (degenerate >= 0) {
    throw InvalidInput("simplex " + std::to_string(degenerate) + " is degenerate",
                       "the mesh must not contain flat simplices");
  }

  list_balls(mesh, g.ball_offsets, g.ball_simplices);
  // Gathered per vertex in increasing simplex order: the sums of a serial scatter, bit for bit.
  g.ball_measure.assign(nv, 0.0);
#pragma omp parallel for schedule(static)
  for (Index v = 0; v < nv; ++v) {
    for (Index k = g.ball_offsets[v]; k < g.ball_offsets[v + 1]; ++k) g.ball_measure[v] += g.measure[g.ball_simplices[k]];
  }
  return g;
}

template <int D>
VertexNeighbours vertex_neighbours(const SimplexMesh<D>& mesh, int threads) {
  LargeVector<Index> ball_start, around;
  list_balls(mesh, ball_start, around);
  return neighbours_from_balls(mesh, ball_start, around, threads);
}

template <int D>
VertexNeighbours vertex_neighbours(const SimplexMesh<D>& mesh, const SimplexGeometry<D>& geometry, int threads) {
  return neighbours_from_balls(mesh, geometry.ball_offsets, geometry.ball_simplices, threads);
}

template VertexNeighbours vertex_neighbours<2>(const SimplexMesh<2>&, int);
template VertexNeighbours vertex_neighbours<2>(const SimplexMesh<2>&, const SimplexGeometry<2>&, int);
template VertexNeighbours vertex_neighbours<3>(const SimplexMesh<3>&, const SimplexGeometry<3>&, int);
template VertexNeighbours vertex_neighbours<3>(const SimplexMesh<3>&, int);
template double signed_measure<2>(const SimplexMesh<2>&, Index);
template double signed_measure<3>(const SimplexMesh<3>&, Index);
template SimplexGeometry<2> compute_simplex_geometry<2>(const SimplexMesh<2>&, bool);
template SimplexGeometry<3> compute_simplex_geometry<3>(const SimplexMesh<3>&, bool);
template std::array<Vec<2>, 3> barycentric_gradients<2>(const SimplexMesh<2>&, Index);
template std::array<Vec<3>, 4> barycentric_gradients<3>(const SimplexMesh<3>&, Index);

}  // namespace lsr
