// SPDX-License-Identifier: BSD-3-Clause
/// @file occupancy_start.h
/// @brief u0 from the occupancy of oriented data: inside where the data, oriented outwards,
/// wind more than half round a vertex (winding_number.h).
#pragma once

#include "lsrecon/core/types.h"

#include <Eigen/Core>

#include <vector>

namespace lsr::detail {

/// @brief The unoriented unit `normals` of `points`, each standing for `areas`, oriented
/// outwards consistently: senses relative to each other propagate along the k-nearest graph
/// `knn` (propagate_senses), and each of its parts takes the overall sense in which the flux of
/// x - c through it, c its centroid, is positive. By the divergence theorem that flux is D times
/// the enclosed volume for a closed surface, whatever c; for an open sheet it is the cone's over
/// c, positive on the convex side.
template <int D>
Points<D> outward_normals(const Points<D>& points, const Points<D>& normals, const std::vector<double>& areas,
                          const LargeVector<Index>& knn, int k);

/// @brief 1/2 - w at each vertex, w the generalised winding number of `points` with their
/// outward_normals, each sample standing for the patch its `spacing` gives (sample_measure) and
/// smoothed over that radius. Negative inside; the zero level set passes
/// through the samples and, across a gap in them, where the data subtend half the directions
/// (the disc spanning a hole's rim). Far from the data it is 1/2 outside and -1/2 inside, so
/// a sheet the front left across a gap of the data (a membrane over a torus's hole) is gone.
template <int D>
Eigen::VectorXd occupancy_start(const Points<D>& vertices, const Points<D>& points, const Points<D>& normals,
                                const std::vector<double>& spacing, const LargeVector<Index>& knn, int k, int threads);

}  // namespace lsr::detail
