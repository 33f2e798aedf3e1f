// SPDX-License-Identifier: BSD-3-Clause
/// @file vertex_fields.h
/// @brief What each mesh vertex takes from its nearest data point: the distance d(x), the
/// local scale and noise, the direction away from it.
#pragma once

#include "geometry/nearest_point_index.h"
#include "lsrecon/core/types.h"
#include "mesh/adaptive_refinement.h"
#include "sampling/local_sampling.h"

#include <Eigen/Core>

#include <vector>

namespace lsr::detail {

template <int D>
struct VertexFields {
  std::vector<double> dist;    ///< #V: distance to the nearest data point
  std::vector<Index> nearest;  ///< #V: that point
  Eigen::VectorXd distance;    ///< dist as a vector
  Eigen::VectorXd scale;       ///< #V: the nearest point's local scale
  Eigen::VectorXd noise;       ///< #V: the nearest point's noise
};

template <int D>
VertexFields<D> vertex_fields(const NearestPointIndex<D>& data, const SimplexMesh<D>& mesh, const LocalSampling<D>& sampling,
                              const std::vector<double>& point_scale, int threads);

/// @brief #V unit directions from each vertex's nearest data point to it (zero on the data):
/// for the two-sided drive and the rest past the data.
template <int D>
Points<D> away_from_data(const NearestPointIndex<D>& data, const SimplexMesh<D>& mesh, const VertexFields<D>& fields);

/// @brief Frees the bisection forest once point location no longer needs it.
template <int D>
void release_forest(AdaptiveMesh<D>& adaptive);

}  // namespace lsr::detail
