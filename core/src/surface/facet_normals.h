// SPDX-License-Identifier: BSD-3-Clause
/// @file facet_normals.h
/// @brief Vertex normals from a surface's facets, where the fit's do not apply: at vertices the
/// fairing moved, and where the fit's normal points against the vertex's facets. The
/// projection onto the fit gives each vertex the normal of the fits blended there, which
/// belongs to another sheet where two lie within a fit's reach or the fit extrapolates (a
/// sparse cloud seen at grazing angles): there it points into the surface.
#pragma once

#include "lsrecon/core/level_set_extraction.h"

#include <vector>

namespace lsr {

/// @brief The facet's normal times its measure (3D: twice its area), oriented as the facet.
template <int D>
Vec<D> facet_area_normal(const Points<D>& vertices, const std::array<Index, D>& facet);

/// @brief Sets the normal of each vertex `flagged` (empty: none), and of each whose normal
/// points against its facets, to the unit sum of its facets' area normals.
template <int D>
void set_facet_normals(const LevelSetMesh<D>& surface, const std::vector<char>& flagged, Points<D>& normals);

}  // namespace lsr
