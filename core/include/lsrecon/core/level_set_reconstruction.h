// SPDX-License-Identifier: BSD-3-Clause
/// @file level_set_reconstruction.h
/// @brief The whole pipeline of the paper (figure 2) as one call: unoriented points in, closed
/// curves (2D) or a closed oriented surface with normals (3D) out, in the input's coordinates.
///
/// The front evolves by du/dt = |grad u| (beta kappa(u) + alpha d(x)). The paper's curvature
/// weight beta = 1 bridges concavities: they stall beta |kappa| / alpha outside the data
/// (docs/design.md section 9). Every length here follows the local sampling of the data (see
/// ReconstructionOptions); the front finds the topology, and a fit through the data places the
/// surface. docs/how-it-works.md explains each stage and where it departs from the paper.
#pragma once

#include "lsrecon/core/progress.h"
#include "lsrecon/core/reconstruction_options.h"
#include "lsrecon/core/reconstruction_result.h"
#include "lsrecon/core/types.h"

#include <functional>
#include <type_traits>

namespace lsr {

/// @brief Reconstructs from points (#N, any scale).
/// @throw InvalidInput for too few or degenerate points and options out of range (the message
/// says what to change); MeshTooLarge when the mesh would exceed LimitOptions::max_vertices. Cancellation
/// and non-convergence are statuses, not exceptions.
template <int D>
ReconstructionResult<D> reconstruct(const Points<D>& points, const ReconstructionOptions& options = {},
                                    const ProgressCallback& progress = {});

/// @brief reconstruct() on the rows of a matrix, as libigl takes points (an Eigen::MatrixX3d, a
/// Map or an Eigen::Ref of one): #N x 3 gives a surface, #N x 2 closed curves. The column count
/// must be known at compile time: pass a dynamic-width Eigen::MatrixXd as V.leftCols<3>().
template <class Derived, int C = Derived::ColsAtCompileTime, std::enable_if_t<C == 2 || C == 3, int> = 0>
ReconstructionResult<C> reconstruct(const Eigen::MatrixBase<Derived>& points, const ReconstructionOptions& options = {},
                                    const ProgressCallback& progress = {}) {
  Points<C> rows(std::size_t(points.rows()));
  for (Eigen::Index i = 0; i < points.rows(); ++i) rows[std::size_t(i)] = points.row(i).transpose();
  return reconstruct<C>(rows, options, progress);
}

/// @brief A signed distance (or any function negative inside, positive outside, with a regular
/// zero set) in the input's coordinates.
template <int D>
using SignedDistance = std::function<double(const Vec<D>&)>;

/// @brief reconstruct() starting from the zero set of initial (input coordinates) instead of
/// a circle / sphere; options.start is ignored. Either options.evolution.two_sided (a start that
/// crosses the data, e.g. a previous or rough surface of the object), or alpha given: > 0 when
/// that zero set encloses the data, < 0 when it lies inside the shape.
/// initial is evaluated at every mesh vertex, from several threads at once.
/// @throw InvalidInput as reconstruct(), or if alpha is 0 without two_sided, or initial has no
/// zero set in the box.
template <int D>
ReconstructionResult<D> reconstruct_from(const Points<D>& points, const SignedDistance<D>& initial,
                                         const ReconstructionOptions& options,
                                         const ProgressCallback& progress = {});

}  // namespace lsr
