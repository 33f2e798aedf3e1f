// SPDX-License-Identifier: BSD-3-Clause
/// @file p1_operators.cpp
#include "lsrecon/core/p1_operators.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include <omp.h>

namespace lsr {
namespace {

// Stored, or computed here when the geometry was computed without them (the pipeline: each
// simplex is met D + 1 times, and its gradients take less time to compute than to fetch).
template <int D>
std::array<Vec<D>, D + 1> gradients_of(const SimplexMesh<D>& mesh, const SimplexGeometry<D>& g, Index s) {
  return g.gradients.empty() ? barycentric_gradients(mesh, s) : g.gradients[std::size_t(s)];
}

// Row block i of G gathers |K| grad w_{K,j} / |B_i| over the simplices K of the ball of i and
// their vertices j, at (D i + k, j): its columns are i and its neighbours, the same for the D
// rows of the block. Written straight into compressed storage, one vertex per task: no triplet
// list (1.4 GB at 209k vertices, measured) and no serial pass.
template <int D>
void assemble_gradient(const SimplexMesh<D>& mesh, const SimplexGeometry<D>& g, const VertexNeighbours& n,
                       int threads, SparseRowMatrix& gradient) {
  const Index nv = Index(mesh.vertices.size());
  gradient.resize(D * nv, nv);
  auto row_size = [&](Index i) { return n.offsets[i + 1] - n.offsets[i] + 1; };
  auto* outer = gradient.outerIndexPtr();
  outer[0] = 0;
  for (Index i = 0; i < nv; ++i) {
    for (int k = 0; k < D; ++k) outer[D * i + k + 1] = outer[D * i + k] + row_size(i);
  }
  gradient.resizeNonZeros(outer[D * nv]);
  auto* columns = gradient.innerIndexPtr();
  double* values = gradient.valuePtr();
#pragma omp parallel for schedule(dynamic, 4096) num_threads(threads)
  for (Index i = 0; i < nv; ++i) {
    // Columns: the sorted neighbours with i merged in.
    const Index* first = n.neighbours.data() + n.offsets[i];
    const Index* last = n.neighbours.data() + n.offsets[i + 1];
    Index* cols = columns + outer[D * i];
    const Index* split = std::lower_bound(first, last, i);
    std::copy(first, split, cols);
    cols[split - first] = i;
    std::copy(split, last, cols + (split - first) + 1);
    const Index size = row_size(i);
    for (int k = 0; k < D; ++k) {
      std::copy_n(cols, size, columns + outer[D * i + k]);
      std::fill_n(values + outer[D * i + k], size, 0.0);
    }
    for (Index b = g.ball_offsets[i]; b < g.ball_offsets[i + 1]; ++b) {
      const Index s = g.ball_simplices[b];
      const double w = g.measure[s] / g.ball_measure[i];
      const std::array<Vec<D>, D + 1> grad = gradients_of(mesh, g, s);
      for (int j = 0; j <= D; ++j) {
        const Index at = Index(std::lower_bound(cols, cols + size, mesh.simplices[s][j]) - cols);
        for (int k = 0; k < D; ++k) values[outer[D * i + k] + at] += w * grad[j][k];
      }
    }
  }
}

// Div has the pattern of G with the roles of the vector component and the row swapped:
// (i, D j + k). Only the reference path and the tests need it.
template <int D>
SparseRowMatrix assemble_divergence(const SimplexMesh<D>& mesh, const SimplexGeometry<D>& g) {
  const Index nv = Index(mesh.vertices.size());
  std::vector<Eigen::Triplet<double, Index>> div;
  div.reserve(std::size_t(g.ball_simplices.size()) * (D + 1) * D);
  for (Index i = 0; i < nv; ++i) {
    for (Index b = g.ball_offsets[i]; b < g.ball_offsets[i + 1]; ++b) {
      const Index s = g.ball_simplices[b];
      const double w = g.measure[s] / g.ball_measure[i];
      const std::array<Vec<D>, D + 1> grad = gradients_of(mesh, g, s);
      for (int j = 0; j <= D; ++j) {
        for (int k = 0; k < D; ++k) {
          div.emplace_back(i, D * mesh.simplices[s][j] + k, w * grad[j][k]);
        }
      }
    }
  }
  SparseRowMatrix divergence(nv, D * nv);
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

int thread_count(int threads) { return threads > 0 ? threads : omp_get_max_threads(); }

// Where G(D i, j) sits in G's values for each entry (j, i) of the block pattern, found by
// binary search in row D i (the block pattern of G is symmetric: i is in row block j's columns
// exactly when j is in row block i's).
template <int D>
std::vector<Index> transpose_index(const SparseRowMatrix& gradient, int threads) {
  const Index nv = Index(gradient.cols());
  const auto* outer = gradient.outerIndexPtr();
  const auto* cols = gradient.innerIndexPtr();
  std::vector<Index> index(std::size_t(outer[D * nv] / D));
#pragma omp parallel for schedule(dynamic, 4096) num_threads(threads)
  for (Index j = 0; j < nv; ++j) {
    const Index first = outer[D * j], size = outer[D * j + 1] - first;
    for (Index e = 0; e < size; ++e) {
      const Index i = cols[first + e];
      const Index* row = cols + outer[D * i];
      index[std::size_t(first / D + e)] = outer[D * i] + Index(std::lower_bound(row, cols + outer[D * i + 1], j) - row);
    }
  }
  return index;
}

// sum over the entries (j, i) of f(D i + k, G(D i + k, j)), for every j.
template <int D, class F>
Eigen::VectorXd gather_columns(const SparseRowMatrix& gradient, const std::vector<Index>& index, F f) {
  const Index nv = Index(gradient.cols());
  const auto* outer = gradient.outerIndexPtr();
  const auto* cols = gradient.innerIndexPtr();
  const double* values = gradient.valuePtr();
  Eigen::VectorXd out(nv);
#pragma omp parallel for schedule(static)
  for (Index j = 0; j < nv; ++j) {
    const Index first = outer[D * j], size = outer[D * j + 1] - first;
    double sum = 0.0;
    for (Index e = 0; e < size; ++e) {
      const Index i = cols[first + e];
      const Index at = index[std::size_t(first / D + e)];
      const Index stride = outer[D * i + 1] - outer[D * i];
      for (int k = 0; k < D; ++k) sum += f(D * i + k, values[at + k * stride]);
    }
    out[j] = sum;
  }
  return out;
}

}  // namespace

template <int D>
P1Operators<D> assemble_p1_operators(const SimplexMesh<D>& mesh, const SimplexGeometry<D>& g, bool with_divergence,
                                     const VertexNeighbours* neighbours, int threads) {
  threads = thread_count(threads);
  P1Operators<D> ops;
  // Filled in place: a copy of each would touch another 0.6 GB per million vertices.
  assemble_gradient(mesh, g, neighbours ? *neighbours : vertex_neighbours(mesh, threads), threads, ops.gradient);
  ops.transpose_index = transpose_index<D>(ops.gradient, threads);
  if (with_divergence) ops.divergence = assemble_divergence(mesh, g);
  ops.ball_measure = Eigen::Map<const Eigen::VectorXd>(g.ball_measure.data(), Eigen::Index(g.ball_measure.size()));
  ops.on_boundary.resize(mesh.vertices.size());
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Vec<D>& x = mesh.vertices[i];
    ops.on_boundary[i] = (x.minCoeff() <= 0.0 || x.maxCoeff() >= 1.0) ? 1 : 0;
  }
  return ops;
}

template <int D>
Eigen::VectorXd P1Operators<D>::gradient_transpose_times(const Eigen::VectorXd& y) const {
  return gather_columns<D>(gradient, transpose_index, [&y](Index row, double g) { return g * y[row]; });
}

template <int D>
Eigen::VectorXd P1Operators<D>::weighted_column_squares(const Eigen::VectorXd& w) const {
  return gather_columns<D>(gradient, transpose_index, [&w](Index row, double g) { return w[row] * g * g; });
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
  return ops_.gradient_transpose_times(weights_.cwiseProduct(ops_.gradient * v));
}

template <int D>
Eigen::VectorXd SymmetricCurvatureOperator<D>::diagonal() const {
  return ops_.weighted_column_squares(weights_);
}

template struct P1Operators<2>;
template struct P1Operators<3>;
template P1Operators<2> assemble_p1_operators<2>(const SimplexMesh<2>&, const SimplexGeometry<2>&, bool,
                                                 const VertexNeighbours*, int);
template P1Operators<3> assemble_p1_operators<3>(const SimplexMesh<3>&, const SimplexGeometry<3>&, bool,
                                                 const VertexNeighbours*, int);
template class SymmetricCurvatureOperator<2>;
template class SymmetricCurvatureOperator<3>;

}  // namespace lsr
