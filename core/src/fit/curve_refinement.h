// SPDX-License-Identifier: BSD-3-Clause
/// @file curve_refinement.h
/// @brief Closed curves sampled as finely as the data, whatever the mesh: on an anisotropic mesh
/// the extracted curve's vertices lie up to the long size apart along flat data, and its chords
/// would cut the curve by up to the metric's error. Long segments are split and their new
/// points projected onto the fit, which is smooth at every scale.
#pragma once

#include "fit/quadric_implicit.h"
#include "lsrecon/core/level_set_extraction.h"

#include <functional>

namespace lsr::detail {

/// @brief Splits each segment longer than twice `length` at its first vertex into equal parts no
/// longer than that, projects the new points onto `fit` and appends them (their sources are
/// those of the segment's first vertex, their normals the fit's). An extraction from an
/// isotropic mesh has no segment that long (at most sqrt(2) sizes), and is left as it is.
/// `reference` (other positions of the curve's vertices, #vertices) gets the same new points on
/// its own segments, unprojected: a subdivision, as embedded as the reference curve.
void refine_long_segments(LevelSetMesh<2>& curve, Points<2>& normals, const QuadricImplicit<2>& fit,
                          const std::function<double(std::size_t vertex)>& length, Points<2>& reference, int threads);

}  // namespace lsr::detail
