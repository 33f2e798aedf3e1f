// SPDX-License-Identifier: BSD-3-Clause
/// @file sheet_gaps.h
/// @brief Which query points lie in a gap between two sheets of the data: outside both, facing
/// each other. There the front's pinned cells may hold a bridge across the gap (its width below
/// two pin radii) as deep as half the gap, and the fit, which cuts it, is to be believed.
#pragma once

#include "geometry/nearest_point_index.h"

#include <vector>

namespace lsr {

/// @brief True for each query q that lies farther than its `beyond` from the data and has two
/// data points p, p' within 1.5 times its distance to the data such that
///  * they lie on opposite sides of q: the directions q -> p and q -> p' more than 120 degrees
///    apart (the nearest points of two facing sheets lie along the gap's normal, on both sides);
///  * q lies off each one's outward side: p -> q within 37 degrees of n_p (cos > 0.8), and the
///    same for p'. Not across a hole in one sheet (the rim points across it see q along their
///    tangent planes) nor inside a thin part (its points' outward normals point away from q).
/// @param normals outward unit normals of the data points
/// @param distance each query's distance to the nearest data point
/// @param beyond per query: nearer than that to the data, q is inside a sheet's noise band,
///        where the points scattered on either side of it face it too
template <int D>
std::vector<char> between_facing_sheets(const NearestPointIndex<D>& data, const Points<D>& normals,
                                        const Points<D>& queries, const std::vector<double>& distance,
                                        const std::vector<double>& beyond, int threads = 0);

}  // namespace lsr
