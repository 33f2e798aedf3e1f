// SPDX-License-Identifier: BSD-3-Clause
/// @file facet_intersection.h
/// @brief Whether two facets of a mesh (triangles in 3D, segments in 2D) meet anywhere but in
/// the vertices and edge they share, decided exactly (exact_predicates.h): CGAL's meaning of a
/// self-intersection (Polygon_mesh_processing::self_intersections).
///
/// Facets sharing an edge intersect when they fold onto each other (coplanar, on one side of
/// the edge); facets sharing a vertex when anything but that vertex is common; others when
/// they meet at all. A degenerate facet (collinear corners) meets whatever touches it.
#pragma once

#include "lsrecon/core/types.h"

#include <array>

namespace lsr::detail {

/// @brief true when triangles f and g of `x` intersect other than in the vertices they share
/// (by index).
bool facets_intersect(const Points<3>& x, const std::array<Index, 3>& f, const std::array<Index, 3>& g);

/// @brief true when segments f and g of `x` intersect other than in the vertex they share.
bool facets_intersect(const Points<2>& x, const std::array<Index, 2>& f, const std::array<Index, 2>& g);

}  // namespace lsr::detail
