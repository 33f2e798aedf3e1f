// SPDX-License-Identifier: BSD-3-Clause
/// @file open_side_closure.h
/// @brief Closes the sides a scanner never saw (an underside on a table, the back of a single
/// view): the wall flood of the tagged start entered there and wraps the scanned sheet from
/// both sides, which the front would follow into a perforated double shell.
///
/// A data point is two-sided when the flood's edge lies along both directions of its normal.
/// When they are many, every point is oriented (towards the side the flood reached; where it
/// reached both, the one it reached by the shorter path from the walls: the seen side faces the
/// open space, the other lies in a pocket entered round the sheet's rim), and the pocket is
/// where the oriented points' winding number exceeds 1/2 (winding_number.h): under an open
/// sheet, up to the disc spanning its rim. On a single view, where no path tells a side, the
/// senses are propagated along the sheet (normal_propagation.h) and the pocket is where w
/// exceeds its value at the far pole of a ball seen from one side (0.146): the unseen half of
/// the body, across the view's gaps. The pocket is taken from the flood; there and in the
/// band behind two-sided points whose paths tell their side (all of them on a single view,
/// where none do) the front is held by curvature alone. A pocket inside data
/// closed up to holes (median winding number near 1) is left to the tangent discs, which span
/// holes along the surface's curvature where the membrane is flat. Derivation and
/// measurements: docs/how-it-works.md (Open sides).
#pragma once

#include "geometry/nearest_point_index.h"
#include "lsrecon/core/simplex_geometry.h"
#include "lsrecon/core/types.h"

#include <Eigen/Core>

#include <functional>
#include <vector>

namespace lsr::detail {

/// @brief What close_open_sides found.
struct OpenSides {
  Index two_sided_points = 0;  ///< data points the flood reached from both sides (0 when nothing was closed)
  Index seen_points = 0;       ///< data points the flood reached at all (0 when nothing was closed)
  std::vector<char> held;      ///< #V: the pocket taken back from the flood and the band behind sided points:
                               ///< no attraction (empty when nothing was closed)
  std::vector<char> kept;      ///< #V: held, or over the membrane: the front is kept, not fitted
};

/// @brief The points' sides a flood the tangent discs stop reached (one_sided_points), computed
/// on demand; empty: none.
using DiscSides = std::function<std::vector<signed char>()>;

/// @brief Below this share of two-sided points among the points the flood reached the data are
/// closed (thin parts and sampling gaps make a few): nothing is taken back.
constexpr double kOpenSideShare = 0.05;

/// @brief Takes the pockets behind open sheets back from `reached` (3D), a flood that keeps
/// gap_factor local scales from the data.
/// @param normals the points' unoriented normals, `point_scale` their local scales
/// @param vertex_scale #V the nearest point's scale, `dist` #V the distance to the data
/// @param disc_sides when `reached` ignores the tangent discs: one_sided_points of the flood
/// the discs stop, asked for only past the gate; if the pocket is then the inside of data
/// closed up to holes (its median winding number at least 0.95), nothing is taken back (the
/// discs span the holes)
template <int D>
OpenSides close_open_sides(const SimplexMesh<D>& mesh, const VertexNeighbours& neighbours, const NearestPointIndex<D>& data,
                           const Points<D>& normals, const std::vector<double>& point_scale, const Eigen::VectorXd& vertex_scale,
                           const std::vector<double>& dist, const std::vector<Index>& nearest, double gap_factor,
                           std::vector<char>& reached, const DiscSides& disc_sides, int threads);

/// @brief Per point, +1 / -1 when `reached` comes near it along its normal / against it only,
/// 0 when on both sides or neither (3D).
template <int D>
std::vector<signed char> one_sided_points(const SimplexMesh<D>& mesh, const NearestPointIndex<D>& data, const Points<D>& normals,
                                          const std::vector<double>& point_scale, const Eigen::VectorXd& vertex_scale,
                                          const std::vector<double>& dist, double gap_factor, const std::vector<char>& reached,
                                          int threads);

}  // namespace lsr::detail
