// SPDX-License-Identifier: BSD-3-Clause
/// @file fitted_surface.h
/// @brief The fitted surface: the blended local quadrics replace u near the front, within what
/// the front decided.
#pragma once

#include "fit/fitted_field.h"
#include "fit/quadric_implicit.h"
#include "geometry/nearest_point_index.h"
#include "lsrecon/core/level_set_reconstruction.h"
#include "lsrecon/core/simplex_geometry.h"

#include <Eigen/Core>

#include <vector>

namespace lsr::detail {

// The fitted surface: F replaces u on the band of vertices within band_factor local spacings of
// the front (u is a signed distance there after renormalisation), u keeps the sign beyond, so
// the front's topology decides everything the fit does not reach. Output vertices are then
// projected onto F itself, which removes the P1 interpolation error of the extraction.
// Returns the surface's vertices as extracted: a level set, embedded (embedded_moves.h).
template <int D>
Points<D> attach_fit(ReconstructionResult<D>& r, const FrontToFit<D>& front, const QuadricImplicit<D>& fit, bool volume);

/// @brief The surface extracted from the fitted field, onto F: each vertex projected by its
/// `share` (empty: in full), normals F's; the unsupported parts (farther than kUnsupported
/// `vertex_scale` from the data) faired and given their facets' normals.
template <int D>
void project_onto_fit(ReconstructionResult<D>& r, const QuadricImplicit<D>& fit, const std::vector<double>& share,
                      const std::vector<double>& vertex_scale, const NearestPointIndex<D>& data, int threads);

/// @brief On an anisotropic mesh: the output's facets refined onto the fit as finely as an
/// isotropic mesh would give them (curve_refinement.h, surface_refinement.h), to a share of the
/// vertex scale (growing with the distance to the data) interpolated at each output vertex.
/// Not with a volume mesh, whose boundary is the surface as extracted. `embedded` (the
/// surface's vertices before the moves) is refined alongside, unprojected.
template <int D>
void refine_onto_fit(ReconstructionResult<D>& r, const QuadricImplicit<D>& fit, const Eigen::VectorXd& scale, const Eigen::VectorXd& distance,
                     Points<D>& embedded, int threads);

/// @brief The blended local quadrics through the data (unit box) with their oriented normals;
/// the fits widen with the noise a quadric sees (residual_noise.h), not with the bend that
/// PCA's thickness also counts. Where the cloud is denser than the mesh, `data` is already the
/// sample at the mesh's size (mesh_resolution_data.h), which the fits need as much as the mesh.
template <int D>
QuadricImplicit<D> fit_quadrics(const NearestPointIndex<D>& data, const Points<D>& normals, const std::vector<double>& point_scale,
                                int threads, const Progress& progress = Progress());

}  // namespace lsr::detail
