// SPDX-License-Identifier: BSD-3-Clause
#include "mesh/metric_gradation.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <utility>

namespace lsr {

template <int D>
Metric<D> metric_intersection(const Metric<D>& a, const Metric<D>& b) {
  // Generalised eigenvectors of (b, a): a-orthonormal, they diagonalise both.
  const Eigen::GeneralizedSelfAdjointEigenSolver<Metric<D>> e(b, a);
  const Metric<D> p = e.eigenvectors();  // p^T a p = I, p^T b p = diag(eigenvalues)
  Vec<D> lambda;
  for (int i = 0; i < D; ++i) lambda[i] = std::max(1.0, e.eigenvalues()[i]);
  const Metric<D> inverse = p.inverse();
  Metric<D> m = inverse.transpose() * lambda.asDiagonal() * inverse;
  return 0.5 * (m + m.transpose());
}

template <int D>
int limit_gradation(const SimplexMesh<D>& mesh, std::vector<Metric<D>>& metrics, double beta, int max_sweeps) {
  std::vector<std::pair<Index, Index>> edges;
  for (const auto& s : mesh.simplices) {
    for (int i = 0; i <= D; ++i) {
      for (int j = i + 1; j <= D; ++j) edges.emplace_back(std::min(s[i], s[j]), std::max(s[i], s[j]));
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  const double log_beta = std::log(beta);
  // What p allows at q; true if q's metric grew.
  const auto propagate = [&](Index p, Index q) {
    const Vec<D> e = mesh.vertices[std::size_t(q)] - mesh.vertices[std::size_t(p)];
    const double length = std::sqrt(e.dot(metrics[std::size_t(p)] * e));
    const Metric<D> allowed = metrics[std::size_t(p)] / std::pow(1.0 + length * log_beta, 2);
    const Metric<D> m = metric_intersection<D>(metrics[std::size_t(q)], allowed);
    const bool changed = (m - metrics[std::size_t(q)]).norm() > 1e-9 * metrics[std::size_t(q)].norm();
    if (changed) metrics[std::size_t(q)] = m;
    return changed;
  };
  int sweep = 0;
  for (bool changed = true; changed && sweep < max_sweeps; ++sweep) {
    changed = false;
    for (const auto& [p, q] : edges) {
      changed = propagate(p, q) || changed;
      changed = propagate(q, p) || changed;
    }
  }
  return sweep;
}

template Metric<2> metric_intersection<2>(const Metric<2>&, const Metric<2>&);
template Metric<3> metric_intersection<3>(const Metric<3>&, const Metric<3>&);
template int limit_gradation<2>(const SimplexMesh<2>&, std::vector<Metric<2>>&, double, int);
template int limit_gradation<3>(const SimplexMesh<3>&, std::vector<Metric<3>>&, double, int);

}  // namespace lsr
