// SPDX-License-Identifier: BSD-3-Clause
/// @file point_simplex_distance.h
/// @brief Exact distances from a point to a segment (2D) and to a triangle (3D).
#pragma once

#include "lsrecon/core/types.h"

namespace lsr {

/// @brief Distance from p to the segment [a, b].
/// @param corner if not null, set to 0 or 1 when the closest point is a or b, else to -1
double segment_distance(const Vec<2>& p, const Vec<2>& a, const Vec<2>& b, int* corner = nullptr);

/// @brief Distance from p to the triangle abc (closest point by Voronoi regions, Ericson,
/// Real-Time Collision Detection 5.1.5).
/// @param corner if not null, set to 0, 1 or 2 when the closest point is a, b or c, else to -1
double triangle_distance(const Vec<3>& p, const Vec<3>& a, const Vec<3>& b, const Vec<3>& c,
                         int* corner = nullptr);

}  // namespace lsr
