// SPDX-License-Identifier: BSD-3-Clause
/// @file occupancy_start.h
/// @brief u0 from the occupancy of oriented data: inside where the data, oriented outwards,
/// wind more than half round a vertex (winding_number.h).
#pragma once

#include "geometry/nearest_point_index.h"
#include "lsrecon/core/types.h"

#include <Eigen/Core>

#include <vector>

namespace lsr::detail {

/// @brief The unoriented unit `normals` of `points`, each standing for `areas`, oriented
/// outwards consistently: senses relative to each other propagate along the k-nearest graph
/// `knn` (propagate_senses), and each of its parts takes the overall sense in which the flux of
/// x - c through it, c its centroid, is positive. By the divergence theorem that flux is D times
/// the enclosed volume for a closed surface, whatever c; for an open sheet it is the cone's over
/// c, positive on the convex side. `noise`: each point's deviation (propagate_senses), or empty.
/// Given the samples' `radii` (WindingNumber), a part inside an odd number of others then
/// faces inwards: it bounds a cavity (the inner sphere of a hollow ball).
template <int D>
Points<D> outward_normals(const Points<D>& points, const Points<D>& normals, const std::vector<double>& areas,
                          const LargeVector<Index>& knn, int k, const std::vector<double>& noise = {},
                          const std::vector<double>& radii = {});

/// @brief `outward` (unit normals oriented outwards, as outward_normals gives them) made
/// consistent with the winding number w they generate, samples weighing `areas` and smoothed
/// over `radii`: each pass flips the normals along which w is larger at p + 2 r_p n_p than at
/// p - 2 r_p n_p (beyond the smoothing, where a sheet's own jump of w is complete), until no
/// flip or kConsistencyPasses. Where a wrong turn of the spanning tree flipped a region, the
/// passes wear it down from its border inwards. A flip changes w near it: after a pass only the
/// flipped points and their neighbours in `knn` (k per point) are tested again, and when none
/// flips, every point once more (a flip's far field may tip a point elsewhere).
template <int D>
void make_consistent(const Points<D>& points, Points<D>& outward, const std::vector<double>& areas,
                     const std::vector<double>& radii, const LargeVector<Index>& knn, int k, int threads);

/// @brief 1/2 - w at each vertex, w the generalised winding number of the `data` points with
/// their `normals` turned outward_normals and make_consistent along the graph of the neighbourhoods the normals
/// were fitted on (LocalSampling::kNeighbours), each sample standing for the patch its
/// neighbourhood's density gives (sample_measure of the k nearest) and smoothed over the spacing
/// of that density or its `scale` (local_scales: 1.5 sigma where the noise is larger), the larger. Negative inside; the zero
/// level set passes through the samples and, across a gap in them, where the data subtend half the directions
/// (the disc spanning a hole's rim). Far from the data it is 1/2 outside and -1/2 inside, so
/// a sheet the front left across a gap of the data (a membrane over a torus's hole) is gone.
template <int D>
Eigen::VectorXd occupancy_start(const Points<D>& vertices, const NearestPointIndex<D>& data, const Points<D>& normals,
                                const std::vector<double>& noise, const std::vector<double>& scale, int threads);

}  // namespace lsr::detail
