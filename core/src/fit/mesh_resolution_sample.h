// SPDX-License-Identifier: BSD-3-Clause
/// @file mesh_resolution_sample.h
/// @brief The points the fits see: the data thinned to the density the mesh resolves.
///
/// Where the data are denser than the mesh's finest size (a 3M-point scan under a mesh of
/// resolution 256), the scale of a point is raised to that size (data_mesh.h), but a fit
/// through its k nearest spans a fraction of a mesh cell. Two views registered a cell apart
/// then read as two sheets, each followed by its own fits, and the blend puts a film of outside
/// between them: specks of solid beside the surface (measured on the 3M torus line scan, where
/// every fit widened to 480 points removed them). Thinned to one point per scale, a fit's k
/// neighbours span k scales as on any cloud sampled at that scale, both sheets enter it, and
/// its noise (residual_noise.h) reads their spread as thickness: the surface goes between them.
#pragma once

#include "lsrecon/core/types.h"

#include <vector>

namespace lsr {

/// @brief The indices kept, in increasing order: every point whose scale is its sampling
/// scale, and of the points whose scale was raised (scale > sampling_scale) a share
/// (sampling_scale / scale)^(D-1), the density of a sampling at the raised scale. Chosen by a
/// hash of the index (deterministic; a random choice does not alias with scan lines as a
/// regular one would). All points where no scale was raised.
template <int D>
std::vector<Index> mesh_resolution_sample(const std::vector<double>& sampling_scale, const std::vector<double>& scale);

}  // namespace lsr
