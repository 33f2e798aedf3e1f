// SPDX-License-Identifier: BSD-3-Clause
/// @file p1_operators.cpp
#include "evolution/p1_operators.h"

#include "thread_count.h"

#include <algorithm>
#include <cstdint>
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
// their vertices j: its columns are i and its neighbours. Written straight into its storage, one
// vertex per task: no triplet list and no serial pass.
template <int D>
void assemble_gradient(const SimplexMesh<D>& mesh, const SimplexGeometry<D>& g, const VertexNeighbours& n,
                       int threads, P1Operators<D>& ops) {
  const Index nv = Index(mesh.vertices.size());
  ops.offsets.resize(std::size_t(nv) + 1);
  ops.offsets[0] = 0;
  for (Index i = 0; i < nv; ++i) ops.offsets[i + 1] = ops.offsets[i] + n.offsets[i + 1] - n.offsets[i] + 1;
  ops.columns.resize(std::size_t(ops.offsets[nv]));
  ops.values.assign(D * ops.columns.size(), 0.0);
#pragma omp parallel for schedule(dynamic, 4096) num_threads(threads)
  for (Index i = 0; i < nv; ++i) {
    // Columns: the sorted neighbours with i merged in.
    const Index* first = n.neighbours.data() + n.offsets[i];
    const Index* last = n.neighbours.data() + n.offsets[i + 1];
    Index* cols = ops.columns.data() + ops.offsets[i];
    const Index* split = std::lower_bound(first, last, i);
    std::copy(first, split, cols);
    cols[split - first] = i;
    std::copy(split, last, cols + (split - first) + 1);
    const Index size = ops.offsets[i + 1] - ops.offsets[i];
    double* values = ops.values.data() + D * std::size_t(ops.offsets[i]);
    for (Index b = g.ball_offsets[i]; b < g.ball_offsets[i + 1]; ++b) {
      const Index s = g.ball_simplices[b];
      const double w = g.measure[s] / g.ball_measure[i];
      const std::array<Vec<D>, D + 1> grad = gradients_of(mesh, g, s);
      for (int j = 0; j <= D; ++j) {
        const Index at = Index(std::lower_bound(cols, cols + size, mesh.simplices[s][j]) - cols);
        for (int k = 0; k < D; ++k) values[D * at + k] += w * grad[j][k];
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

// (G u)_i, summed in storage order.
template <int D>
Vec<D> row_block_times(const P1Operators<D>& ops, Index i, const Eigen::VectorXd& u) {
  Vec<D> sum = Vec<D>::Zero();
  for (Index e = ops.offsets[i]; e < ops.offsets[i + 1]; ++e) {
    sum += u[ops.columns[e]] * Eigen::Map<const Vec<D>>(ops.values.data() + D * std::size_t(e));
  }
  return sum;
}

// out[j] = sum over the entries (i, j) of G's block pattern of f(i, G(D i .. D i + D - 1, j)),
// for every j: G^T-like products scattered from G's rows, read in storage order. Each thread
// owns the columns of its range of rows; the terms its rows give to other ranges' columns are
// set aside first and added in row order, so every out[j] sums its terms in increasing i, as
// one thread would: the same result on any number of threads.
template <int D, class F>
void scatter_columns(const P1Operators<D>& ops, F f, Eigen::VectorXd& out) {
  struct Term {
    Index column;
    double value;
  };
  const Index nv = Index(ops.offsets.size()) - 1;
  out.resize(nv);
  std::vector<std::vector<Term>> crossing;
#pragma omp parallel
  {
    const int t = omp_get_thread_num(), threads = omp_get_num_threads();
#pragma omp single
    crossing.resize(std::size_t(threads));
    const Index lo = Index(std::int64_t(nv) * t / threads), hi = Index(std::int64_t(nv) * (t + 1) / threads);
    auto mine = [&](Index j) { return j >= lo && j < hi; };
    for (Index i = lo; i < hi; ++i) {
      const Index first = ops.offsets[i], last = ops.offsets[i + 1];
      if (mine(ops.columns[first]) && mine(ops.columns[last - 1])) continue;  // sorted columns
      for (Index e = first; e < last; ++e) {
        if (!mine(ops.columns[e])) crossing[std::size_t(t)].push_back({ops.columns[e], f(i, &ops.values[D * std::size_t(e)])});
      }
    }
#pragma omp barrier
    auto add_crossing = [&](int from) {
      for (const Term& term : crossing[std::size_t(from)]) {
        if (mine(term.column)) out[term.column] += term.value;
      }
    };
    for (Index j = lo; j < hi; ++j) out[j] = 0.0;
    for (int from = 0; from < t; ++from) add_crossing(from);
    for (Index i = lo; i < hi; ++i) {
      for (Index e = ops.offsets[i]; e < ops.offsets[i + 1]; ++e) {
        if (mine(ops.columns[e])) out[ops.columns[e]] += f(i, &ops.values[D * std::size_t(e)]);
      }
    }
    for (int from = t + 1; from < threads; ++from) add_crossing(from);
  }
}

template <int D, class F>
Eigen::VectorXd scatter_columns(const P1Operators<D>& ops, F f) {
  Eigen::VectorXd out;
  scatter_columns<D>(ops, f, out);
  return out;
}

}  // namespace

template <int D>
P1Operators<D> assemble_p1_operators(const SimplexMesh<D>& mesh, const SimplexGeometry<D>& g, bool with_divergence,
                                     const VertexNeighbours* neighbours, int threads) {
  threads = detail::thread_count(threads);
  P1Operators<D> ops;
  // Filled in place: a copy of each would touch another 0.6 GB per million vertices.
  assemble_gradient(mesh, g, neighbours ? *neighbours : vertex_neighbours(mesh, threads), threads, ops);
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
Eigen::VectorXd P1Operators<D>::gradient_times(const Eigen::VectorXd& u) const {
  Eigen::VectorXd out;
  gradient_times(u, out);
  return out;
}

template <int D>
void P1Operators<D>::gradient_times(const Eigen::VectorXd& u, Eigen::VectorXd& out) const {
  const Index nv = Index(offsets.size()) - 1;
  out.resize(D * nv);
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < nv; ++i) out.template segment<D>(D * i) = row_block_times(*this, i, u);
}

template <int D>
Eigen::VectorXd P1Operators<D>::gradient_transpose_times(const Eigen::VectorXd& y) const {
  return scatter_columns<D>(*this, [&y](Index i, const double* g) {
    double s = 0.0;
    for (int k = 0; k < D; ++k) s += g[k] * y[D * i + k];
    return s;
  });
}

template <int D>
Eigen::VectorXd P1Operators<D>::weighted_column_squares(const Eigen::VectorXd& w) const {
  return scatter_columns<D>(*this, [&w](Index i, const double* g) {
    double s = 0.0;
    for (int k = 0; k < D; ++k) s += w[D * i + k] * g[k] * g[k];
    return s;
  });
}

template <int D>
SparseRowMatrix P1Operators<D>::gradient_matrix() const {
  const Index nv = Index(offsets.size()) - 1;
  std::vector<Eigen::Triplet<double, Index>> entries;
  entries.reserve(values.size());
  for (Index i = 0; i < nv; ++i) {
    for (Index e = offsets[i]; e < offsets[i + 1]; ++e) {
      for (int k = 0; k < D; ++k) entries.emplace_back(D * i + k, columns[e], values[D * std::size_t(e) + k]);
    }
  }
  SparseRowMatrix g(D * nv, nv);
  g.setFromTriplets(entries.begin(), entries.end());
  return g;
}

template <int D>
Eigen::VectorXd P1Operators<D>::gradient_norms(const Eigen::VectorXd& u) const {
  Eigen::VectorXd out;
  gradient_norms(u, out);
  return out;
}

template <int D>
void P1Operators<D>::gradient_norms(const Eigen::VectorXd& u, Eigen::VectorXd& out) const {
  const Index nv = Index(offsets.size()) - 1;
  out.resize(nv);
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < nv; ++i) out[i] = row_block_times(*this, i, u).norm();
}

template <int D>
Eigen::VectorXd P1Operators<D>::curvature(const Eigen::VectorXd& u, double eps_a) const {
  if (divergence.rows() == 0) throw std::logic_error("curvature() needs operators assembled with_divergence");
  Eigen::VectorXd q = gradient_times(u);
  const Eigen::VectorXd a = norms_per_vertex<D>(q).cwiseMax(eps_a);
  for (Eigen::Index i = 0; i < a.size(); ++i) q.template segment<D>(D * i) /= a[i];
  return divergence * q;
}

template <int D>
SymmetricCurvatureOperator<D>::SymmetricCurvatureOperator(const P1Operators<D>& ops,
                                                          const Eigen::VectorXd& a,
                                                          const Eigen::VectorXd* scale)
    : ops_(ops) {
  freeze(a, scale);
}

template <int D>
void SymmetricCurvatureOperator<D>::freeze(const Eigen::VectorXd& a, const Eigen::VectorXd* scale) {
  weights_.resize(a.size());
  for (Eigen::Index j = 0; j < a.size(); ++j) weights_[j] = ops_.ball_measure[j] / a[j] * (scale ? (*scale)[j] : 1.0);
}

template <int D>
Eigen::VectorXd SymmetricCurvatureOperator<D>::apply(const Eigen::VectorXd& v) const {
  Eigen::VectorXd out;
  apply(v, out);
  return out;
}

// G^T (W G v): W is applied inside the scatter, which reads G v's entries of row i once.
template <int D>
void SymmetricCurvatureOperator<D>::apply(const Eigen::VectorXd& v, Eigen::VectorXd& out) const {
  ops_.gradient_times(v, gradient_);
  const Eigen::VectorXd& w = weights_;
  const Eigen::VectorXd& gv = gradient_;
  scatter_columns<D>(ops_, [&w, &gv](Index i, const double* g) {
    double s = 0.0;
    for (int k = 0; k < D; ++k) s += g[k] * (w[i] * gv[D * i + k]);
    return s;
  }, out);
}

template <int D>
Eigen::VectorXd SymmetricCurvatureOperator<D>::diagonal() const {
  Eigen::VectorXd out;
  diagonal(out);
  return out;
}

template <int D>
void SymmetricCurvatureOperator<D>::diagonal(Eigen::VectorXd& out) const {
  const Eigen::VectorXd& w = weights_;
  scatter_columns<D>(ops_, [&w](Index i, const double* g) {
    double s = 0.0;
    for (int k = 0; k < D; ++k) s += w[i] * g[k] * g[k];
    return s;
  }, out);
}

template <int D>
void SymmetricCurvatureOperator<D>::release() {
  weights_.resize(0);
  gradient_.resize(0);
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
