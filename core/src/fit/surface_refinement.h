// SPDX-License-Identifier: BSD-3-Clause
/// @file surface_refinement.h
/// @brief Surfaces sampled as finely as the data, whatever the mesh: the 3D counterpart of
/// curve_refinement.h. On an anisotropic mesh the extracted triangles span up to the long sizes
/// along flat data, and their planes would cut the fit by up to the metric's error. Long edges
/// are bisected, conformingly (each triangle by the pattern of its split edges), and the new
/// vertices projected onto the fit, until no edge is longer than twice `length`.
#pragma once

#include "fit/quadric_implicit.h"
#include "lsrecon/core/level_set_extraction.h"

#include <functional>

namespace lsr::detail {

/// @brief Bisects every edge longer than twice the smaller `length` of its ends, pass after
/// pass, projecting the midpoints onto `fit` (their sources are those of the edge's first end,
/// their normals the fit's) unless that moves them by more than a quarter of the edge. The
/// surface stays closed and consistently oriented.
/// `reference` (other positions of the surface's vertices, #vertices) gets the same midpoints of
/// its own edges, unprojected: a subdivision, as embedded as the reference surface.
void refine_long_edges(LevelSetMesh<3>& surface, Points<3>& normals, const QuadricImplicit<3>& fit,
                       const std::function<double(std::size_t vertex)>& length, Points<3>& reference, int threads);

}  // namespace lsr::detail
