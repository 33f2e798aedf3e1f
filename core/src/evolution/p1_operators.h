// SPDX-License-Identifier: BSD-3-Clause
/// @file p1_operators.h
/// @brief Nodal derivatives by L2 projection on a fixed simplicial mesh (paper section 5.3):
/// the gradient G (eq. 10-11), the divergence of a nodal vector field, and the curvature
/// operator M = Div A^-1 G (eq. 12-14) in its symmetric form Lambda M = -G^T W G (appendix C).
#pragma once

#include "lsrecon/core/large_array_allocator.h"
#include "lsrecon/core/simplex_geometry.h"

#include <Eigen/SparseCore>

#include <vector>

namespace lsr {

/// 32-bit indices: G of a 20M-vertex mesh has ~1e9 entries, and the index traffic of every
/// product drops by a third.
using SparseRowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor, Index>;

/// @brief The operators of one fixed mesh, assembled once.
///
/// Nodal vector fields are stored as one vector of D * #V entries, component k of vertex i at
/// D * i + k. G is assembled (in parallel, straight into its storage): products with it ran
/// 4.6x faster than matrix-free gathers over the simplices (docs/calibration.md), whose
/// per-simplex reads are scattered. Its D rows of a vertex share one column pattern (the vertex
/// and its neighbours), so G is stored by blocks: one column index and D side-by-side values per
/// entry. G^T is not stored (it doubled the operators' memory, a third of the peak): G^T y is
/// scattered from G's rows, read in storage order like G u. Gathered per column instead, through
/// an index of transposed entries, it read scattered values and took 5x the time of G u on a
/// Z-ordered mesh.
template <int D>
struct P1Operators {
  /// G, (D #V) x #V: (G u)_i = sum_{K in B_i} |K| sum_{j in K} u_j grad w_{K,j} / |B_i|
  /// (eq. 11). Row block i holds the entries offsets[i] .. offsets[i + 1] - 1; entry e is in
  /// column columns[e] (i and its neighbours, sorted) with G(D i + k, columns[e]) at
  /// values[D e + k].
  std::vector<Index> offsets;
  LargeVector<Index> columns;
  LargeVector<double> values;
  /// #V x (D #V): (Div q)_i = sum_{K in B_i} |K| sum_{j in K} <q_j, grad w_{K,j}> / |B_i|, the
  /// projection eq. (12)-(14) apply to the components of a nodal field. Empty unless assembled
  /// with_divergence (only the paper-form reference and curvature() need it).
  SparseRowMatrix divergence;
  Eigen::VectorXd ball_measure;  ///< #V: |B_i| (the diagonal of Lambda)
  std::vector<char> on_boundary; ///< #V: 1 for vertices on the walls of the box [0,1]^D

  /// @brief G u, D #V entries, in parallel (each entry summed in a fixed order: deterministic).
  Eigen::VectorXd gradient_times(const Eigen::VectorXd& u) const;
  /// @brief G u into out, whose storage is reused when it has the size already.
  void gradient_times(const Eigen::VectorXd& u, Eigen::VectorXd& out) const;
  /// @brief G^T y for y of D #V entries, in parallel and in a fixed order (deterministic).
  Eigen::VectorXd gradient_transpose_times(const Eigen::VectorXd& y) const;
  /// @brief sum_k w_{D i + k} G(D i + k, j)^2 over i for every j: diag(G^T W G).
  Eigen::VectorXd weighted_column_squares(const Eigen::VectorXd& w) const;
  /// @brief G as a sparse matrix, for the paper-form reference and the tests.
  SparseRowMatrix gradient_matrix() const;
  /// @brief |(G u)_i| per vertex.
  Eigen::VectorXd gradient_norms(const Eigen::VectorXd& u) const;
  /// @brief |(G u)_i| per vertex into out, without storing G u.
  void gradient_norms(const Eigen::VectorXd& u, Eigen::VectorXd& out) const;
  /// @brief The paper's curvature kappa_i = (Div A^-1 G u)_i with a_j = max(|(G u)_j|, eps_a)
  /// (eq. 14), on every vertex. Accurate on vertices away from the box walls.
  /// @throw std::logic_error if the divergence was not assembled.
  Eigen::VectorXd curvature(const Eigen::VectorXd& u, double eps_a) const;
};

/// @brief Assembles the operators of a mesh (the divergence only when asked: it doubles the
/// assembly time).
/// @param neighbours the mesh's vertex_neighbours(), or nullptr to compute them here
/// @param threads threads for the assembly, 0 for all cores
template <int D>
P1Operators<D> assemble_p1_operators(const SimplexMesh<D>& mesh, const SimplexGeometry<D>& geometry,
                                     bool with_divergence = false, const VertexNeighbours* neighbours = nullptr,
                                     int threads = 0);

/// @brief The symmetric form of the curvature operator at a frozen gradient:
/// apply(v) = G^T W G v with W = diag(|B_j| / a_j) per component, so that
/// Lambda M v = -apply(v) on rows of vertices away from the box walls.
///
/// It keeps G v between products, and a time loop keeps one operator for all its steps
/// (freeze() per step): vectors allocated afresh at each product were page-faulted in again
/// each time (glibc returns large freed blocks to the system), at 3x the arithmetic's cost.
/// Hence apply() is not reentrant.
template <int D>
class SymmetricCurvatureOperator {
 public:
  /// @brief An operator to be frozen before use.
  explicit SymmetricCurvatureOperator(const P1Operators<D>& ops) : ops_(ops) {}
  /// @param a #V: the frozen |grad u^n|, already bounded below by eps_a.
  /// @param scale #V factors on W (a per-vertex curvature weight), or nullptr for none.
  SymmetricCurvatureOperator(const P1Operators<D>& ops, const Eigen::VectorXd& a,
                             const Eigen::VectorXd* scale = nullptr);
  /// @brief Freezes W at a new gradient norm a (same arguments as the constructor).
  void freeze(const Eigen::VectorXd& a, const Eigen::VectorXd* scale = nullptr);
  /// @brief G^T W G v.
  Eigen::VectorXd apply(const Eigen::VectorXd& v) const;
  /// @brief G^T W G v into out (reused when it has the size already).
  void apply(const Eigen::VectorXd& v, Eigen::VectorXd& out) const;
  /// @brief diag(G^T W G), for Jacobi preconditioning.
  Eigen::VectorXd diagonal() const;
  /// @brief diag(G^T W G) into out.
  void diagonal(Eigen::VectorXd& out) const;
  /// @brief Frees W and the product's buffer; freeze() again before the next use.
  void release();

 private:
  const P1Operators<D>& ops_;
  Eigen::VectorXd weights_;           ///< #V: |B_j| / a_j, the same for the D components
  mutable Eigen::VectorXd gradient_;  ///< D #V: G v of the last product
};

}  // namespace lsr
