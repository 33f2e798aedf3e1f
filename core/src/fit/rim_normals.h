// SPDX-License-Identifier: BSD-3-Clause
/// @file rim_normals.h
/// @brief Normals where the seen surface ends, from the data alone.
#pragma once

#include "geometry/nearest_point_index.h"

namespace lsr {

/// @brief Points fitted per rim normal (rim_normals).
template <int D>
constexpr int kRimNormalNeighbours = D == 2 ? 20 : 100;

/// @brief The unit normal at each query of the quadric height field fitted (least squares) to
/// its kRimNormalNeighbours nearest data points, over the tangent plane of their PCA, evaluated
/// at the query's foot; the sign is arbitrary.
template <int D>
Points<D> rim_normals(const NearestPointIndex<D>& data, const Points<D>& queries, int threads = 0);

}  // namespace lsr
