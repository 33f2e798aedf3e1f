// SPDX-License-Identifier: BSD-3-Clause
/// @file exact_self_intersections.h
/// @brief An independent exact checker of embedding for the tests: CGAL's
/// Polygon_mesh_processing::self_intersections on triangle surfaces, CGAL's exact kernel on
/// curves. Nothing of lsrecon's own predicates is used.
#pragma once

#include "lsrecon/core/types.h"

#include <array>
#include <cstddef>
#include <vector>

namespace lsr::testing {

/// @brief The pairs of triangles that intersect other than in shared vertices and edges, as
/// CGAL counts them (exact predicates); SIZE_MAX when CGAL cannot build the surface (not a
/// manifold oriented triangle mesh).
std::size_t cgal_self_intersections(const Points<3>& vertices, const std::vector<std::array<Index, 3>>& triangles);

/// @brief The pairs of segments of closed curves that meet other than in a shared end,
/// computed with CGAL's exact constructions.
std::size_t cgal_self_intersections(const Points<2>& vertices, const std::vector<std::array<Index, 2>>& segments);

}  // namespace lsr::testing
