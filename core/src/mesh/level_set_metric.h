// SPDX-License-Identifier: BSD-3-Clause
/// @file level_set_metric.h
/// @brief The Riemannian metric of a mesh adapted to a level set (paper section 6.2; issue 46,
/// item 1): small sizes across the level sets, larger along them where they are flat. A metric
/// M prescribes the edge length 1 in its norm, sqrt(e^T M e) = 1: its eigenvectors are the
/// directions, 1 / sqrt(eigenvalue) the sizes along them (docs/how-it-works.md, Anisotropic
/// meshes, derives the sizes). Not yet used to build meshes: adapting one to it is item 2.
///
/// Across (along n = grad u / |grad u|): h_n = min(h_max, h_min + growth |u| / |grad u|), the
/// finest size at the level set, growing with the distance to it (|u| / |grad u| to first order).
/// Along each principal direction of the level set through the point, with principal curvature
/// kappa_i: h_i = clamp(sqrt(8 error / |kappa_i|), h_n, h_max), since the P1 interpolant of a
/// curve of curvature kappa over a length h deviates from it by kappa h^2 / 8 at most: `error`
/// bounds that deviation (the Hausdorff distance the mesh adds). Never finer than across.
#pragma once

#include "evolution/p1_operators.h"
#include "lsrecon/core/types.h"

#include <Eigen/Core>

#include <limits>
#include <vector>

namespace lsr {

template <int D>
using Metric = Eigen::Matrix<double, D, D>;

/// @brief The sizes a metric prescribes (lengths in the mesh's units).
struct MetricSizes {
  double h_min = 1.0 / 256;  ///< across the level set, on it
  double h_max = 1.0 / 8;    ///< the largest size in any direction
  double error = 1e-4;       ///< the interpolation error allowed along the level set
  double growth = 0.5;       ///< how fast the size across grows with the distance to the level set
  /// From this distance to the level set on, isotropic (the size across); in between, the sizes
  /// along shrink linearly towards it.
  double anisotropic_reach = std::numeric_limits<double>::infinity();
};

/// @brief The metric at a point where the field has value u, gradient g and Hessian hessian.
/// Where g vanishes (no level set direction): isotropic h_max.
template <int D>
Metric<D> level_set_metric(double u, const Vec<D>& g, const Metric<D>& hessian, const MetricSizes& sizes);

/// @brief The metric at every vertex, from the nodal values u: gradient G u and Hessian
/// G (G u), symmetrised (the recovered derivatives of the scheme, eq. 11).
template <int D>
std::vector<Metric<D>> level_set_metrics(const P1Operators<D>& ops, const Eigen::VectorXd& u, const MetricSizes& sizes);

/// @brief The sizes a metric prescribes (ascending) and their directions (columns, same order).
template <int D>
void metric_sizes(const Metric<D>& m, Vec<D>& sizes, Metric<D>& directions);

}  // namespace lsr
