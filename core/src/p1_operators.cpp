// SPDX-License-Identifier: BSD-3-Clause
/// @file p1_operators.cpp
#include "lsrecon/core/p1_operators.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace lsr {
namespace {

// Row block i of G gathers |K| grad w_{K,j} / |B_i| over the simplices K of the ball of i and
// their vertices j, at (D i + k, j). Filled row by row in order: no triplet list, whose size
// (#ball entries x (D+1) x D) dominated the peak memory (1.4 GB at 209k vertices, measured).
template <int D>
SparseRowMatrix assemble_gradient(const SimplexMesh<D>& mesh, const SimplexGeometry<D>& g) {
  const Index nv = Index(mesh.vertices.size());
  SparseRowMatrix gradient(static_cast<std::ptrdiff_t>(D) * nv, nv);
  gradient.reserve(std::ptrdiff_t(g.ball_simplices.size()) * D * 3);  // ~ 1-ring size per row
  std::vector<std::pair<Index, Vec<D>>> row;
  for (Index i = 0; i < nv; ++i) {
    row.clear();
    for (Index b = g.ball_offsets[i]; b < g.ball_offsets[i + 1]; ++b) {
      const Index s = g.ball_simplices[b];
      const double w = g.measure[s] / g.ball_measure[i];
      for (int j = 0; j <= D; ++j) row.emplace_back(mesh.simplices[s][j], w * g.gradients[s][j]);
    }
    std::sort(row.begin(), row.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (int k = 0; k < D; ++k) {
      gradient.startVec(std::ptrdiff_t(D) * i + k);
      for (std::size_t e = 0; e < row.size();) {
        double sum = 0.0;
        const Index col = row[e].first;
        for (; e < row.size() && row[e].first == col; ++e) sum += row[e].second[k];
        gradient.insertBack(std::ptrdiff_t(D) * i + k, col) = sum;
      }
    }
  }
  gradient.finalize();
  return gradient;
}

// Div has the pattern of G with the roles of the vector component and the row swapped:
// (i, D j + k). Only the reference path and the tests need it.
template <int D>
SparseRowMatrix assemble_divergence(const SimplexMesh<D>& mesh, const SimplexGeometry<D>& g) {
  const Index nv = Index(mesh.vertices.size());
  std::vector<Eigen::Triplet<double, std::ptrdiff_t>> div;
  div.reserve(std::size_t(g.ball_simplices.size()) * (D + 1) * D);
  for (Index i = 0; i < nv; ++i) {
    for (Index b = g.ball_offsets[i]; b < g.ball_offsets[i + 1]; ++b) {
      const Index s = g.ball_simplices[b];
      const double w = g.measure[s] / g.ball_measure[i];
      for (int j = 0; j <= D; ++j) {
        for (int k = 0; k < D; ++k) {
          div.emplace_back(i, std::ptrdiff_t(D) * mesh.simplices[s][j] + k, w * g.gradients[s][j][k]);
        }
      }
    }
  }
  SparseRowMatrix divergence(nv, std::ptrdiff_t(D) * nv);
  divergence.setFromTriplets(div.begin(), div.end());
  return divergence;
}

template <int D>
Eigen::VectorXd norms_per_vertex(const Eigen::VectorXd& field) {
  const Eigen::Index n = field.size() / D;
  Eigen::VectorXd out(n);
  for (Eigen::Index i = 0; i < n; ++i) out[i] = field.template segment<D>(D * i).norm();
  return out;
}

}  // namespace

template <int D>
P1Operators<D> assemble_p1_operators(const SimplexMesh<D>& mesh, const SimplexGeometry<D>& g,
                                     bool with_divergence) {
  P1Operators<D> ops;
  ops.gradient = assemble_gradient(mesh, g);
  if (with_divergence) ops.divergence = assemble_divergence(mesh, g);
  ops.gradient_transpose = ops.gradient.transpose();
  ops.ball_measure = Eigen::Map<const Eigen::VectorXd>(g.ball_measure.data(), Eigen::Index(g.ball_measure.size()));
  ops.on_boundary.resize(mesh.vertices.size());
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Vec<D>& x = mesh.vertices[i];
    ops.on_boundary[i] = (x.minCoeff() <= 0.0 || x.maxCoeff() >= 1.0) ? 1 : 0;
  }
  return ops;
}

template <int D>
Eigen::VectorXd P1Operators<D>::gradient_norms(const Eigen::VectorXd& u) const {
  return norms_per_vertex<D>(gradient * u);
}

template <int D>
Eigen::VectorXd P1Operators<D>::curvature(const Eigen::VectorXd& u, double eps_a) const {
  if (divergence.rows() == 0) throw std::logic_error("curvature() needs operators assembled with_divergence");
  Eigen::VectorXd q = gradient * u;
  const Eigen::VectorXd a = norms_per_vertex<D>(q).cwiseMax(eps_a);
  for (Eigen::Index i = 0; i < a.size(); ++i) q.template segment<D>(D * i) /= a[i];
  return divergence * q;
}

template <int D>
SymmetricCurvatureOperator<D>::SymmetricCurvatureOperator(const P1Operators<D>& ops,
                                                          const Eigen::VectorXd& a,
                                                          const Eigen::VectorXd* scale)
    : ops_(ops), weights_(D * a.size()) {
  for (Eigen::Index j = 0; j < a.size(); ++j) {
    weights_.template segment<D>(D * j).setConstant(ops.ball_measure[j] / a[j] * (scale ? (*scale)[j] : 1.0));
  }
}

template <int D>
Eigen::VectorXd SymmetricCurvatureOperator<D>::apply(const Eigen::VectorXd& v) const {
  const Eigen::VectorXd wg = weights_.cwiseProduct(ops_.gradient * v);
  return ops_.gradient_transpose * wg;
}

template <int D>
Eigen::VectorXd SymmetricCurvatureOperator<D>::diagonal() const {
  // diag_i = sum over column i of G of W * G^2: row i of G^T holds that column.
  const auto& gt = ops_.gradient_transpose;
  Eigen::VectorXd diag = Eigen::VectorXd::Zero(gt.rows());
  for (Eigen::Index i = 0; i < gt.outerSize(); ++i) {
    for (SparseRowMatrix::InnerIterator it(gt, i); it; ++it) {
      diag[i] += weights_[it.col()] * it.value() * it.value();
    }
  }
  return diag;
}

template struct P1Operators<2>;
template struct P1Operators<3>;
template P1Operators<2> assemble_p1_operators<2>(const SimplexMesh<2>&, const SimplexGeometry<2>&, bool);
template P1Operators<3> assemble_p1_operators<3>(const SimplexMesh<3>&, const SimplexGeometry<3>&, bool);
template class SymmetricCurvatureOperator<2>;
template class SymmetricCurvatureOperator<3>;

}  // namespace lsr
