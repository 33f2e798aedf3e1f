// SPDX-License-Identifier: BSD-3-Clause
/// @file simplex_geometry.cpp
#include "lsrecon/core/simplex_geometry.h"

#include "lsrecon/core/errors.h"

#include <Eigen/LU>

#include <string>

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

}  // namespace

template <int D>
double signed_measure(const SimplexMesh<D>& mesh, Index s) {
  return edge_matrix(mesh, s).determinant() / factorial(D);
}

template <int D>
SimplexGeometry<D> compute_simplex_geometry(const SimplexMesh<D>& mesh) {
  const Index ns = Index(mesh.simplices.size());
  const Index nv = Index(mesh.vertices.size());
  SimplexGeometry<D> g;
  g.measure.resize(ns);
  g.gradients.resize(ns);
  for (Index s = 0; s < ns; ++s) {
    const Eigen::Matrix<double, D, D> J = edge_matrix(mesh, s);
    const double det = J.determinant();
    if (!(std::abs(det) > 0.0)) {
      throw InvalidInput("simplex " + std::to_string(s) + " is degenerate",
                         "the mesh must not contain flat simplices");
    }
    g.measure[s] = std::abs(det) / factorial(D);
    // lambda_k(x) = e_k . J^-1 (x - x0) for k >= 1, so grad lambda_k is row k-1 of J^-1.
    const Eigen::Matrix<double, D, D> Jinv = J.inverse();
    Vec<D> sum = Vec<D>::Zero();
    for (int k = 1; k <= D; ++k) {
      g.gradients[s][k] = Jinv.row(k - 1).transpose();
      sum += g.gradients[s][k];
    }
    g.gradients[s][0] = -sum;
  }

  g.ball_offsets.assign(nv + 1, 0);
  for (const auto& simplex : mesh.simplices) {
    for (Index v : simplex) ++g.ball_offsets[v + 1];
  }
  for (Index v = 0; v < nv; ++v) g.ball_offsets[v + 1] += g.ball_offsets[v];
  g.ball_simplices.resize(g.ball_offsets[nv]);
  std::vector<Index> fill(g.ball_offsets.begin(), g.ball_offsets.end() - 1);
  g.ball_measure.assign(nv, 0.0);
  for (Index s = 0; s < ns; ++s) {
    for (Index v : mesh.simplices[s]) {
      g.ball_simplices[fill[v]++] = s;
      g.ball_measure[v] += g.measure[s];
    }
  }
  return g;
}

template double signed_measure<2>(const SimplexMesh<2>&, Index);
template double signed_measure<3>(const SimplexMesh<3>&, Index);
template SimplexGeometry<2> compute_simplex_geometry<2>(const SimplexMesh<2>&);
template SimplexGeometry<3> compute_simplex_geometry<3>(const SimplexMesh<3>&);

}  // namespace lsr
