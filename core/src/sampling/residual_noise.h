// SPDX-License-Identifier: BSD-3-Clause
/// @file residual_noise.h
/// @brief The noise of each point as a quadric fit sees it: the spread of its neighbours about a
/// quadric height field, which curvature does not raise. LocalSampling::noise (the thickness of
/// the PCA neighbourhood) counts the bend of a curved or creased part as noise, and the fits
/// would widen on clean curved data as if it were noisy (quadric_implicit.h).
#pragma once

#include "geometry/nearest_point_index.h"

#include <vector>

namespace lsr {

/// @brief Per point: the residual deviation of a least-squares quadric height field (in the
/// tangent frame of its normal) through its k nearest neighbours that face the same way,
/// unbiased for its degrees of freedom, median-filtered over the same neighbours, then scaled
/// by sqrt((K - D) / K), K = LocalSampling::kNeighbours (the degrees of freedom that K points'
/// PCA keeps), so that the fits' constants, set on PCA's reading, keep their meaning on noisy
/// data.
/// @param normals #N unit normals, consistently oriented (neighbours facing the other way, the
///        other side of a thin part, are left out)
/// @param k neighbours per fit, the point itself included
/// @param threads 0 for all cores
template <int D>
std::vector<double> residual_noise(const NearestPointIndex<D>& data, const Points<D>& normals, int k, int threads = 0);

/// @brief The same from the k nearest of each point, as NearestPointIndex::query_k gives them
/// (#N x k, the point itself first), when the caller has them already.
template <int D>
std::vector<double> residual_noise(const Points<D>& points, const Points<D>& normals, const LargeVector<Index>& nearest,
                                   int k, int threads = 0);

}  // namespace lsr
