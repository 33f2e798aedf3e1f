// SPDX-License-Identifier: BSD-3-Clause
/// @file mesh_resolution_sample.h
/// @brief The points the stages after the sampling see (mesh_resolution_data.h): the data
/// thinned to the density the mesh resolves.
///
/// Where the data are denser than the mesh's finest size (a 3M-point scan under a mesh of
/// resolution 256), the scale of a point is raised to that size (data_mesh.h), but a fit
/// through its k nearest spans a fraction of a mesh cell. Two views registered a cell apart
/// then read as two sheets, each followed by its own fits, and the blend puts a film of outside
/// between them: specks of solid beside the surface. Thinned to one point per scale, a fit's k
/// neighbours span k scales as on any cloud sampled at that scale, both sheets enter it, and
/// its noise (residual_noise.h) reads their spread as thickness: the surface goes between them.
///
/// The share kept is the density of a sampling at the raised scale l over the point's own. The
/// spacing s tells that density, (s / l)^(D-1), except on scan lines, whose spacing is raised
/// to the gap between the lines (local_sampling.h) while the points lie 3-10 times closer along
/// them: there the spacing's share kept 72% of a 1M-point line scan of a sphere where its
/// density asks for a third. On scan lines the spacing's sample is thinned further by its own
/// density, read from the distance r_k to the k-th nearest in it (the point and k - 1
/// others): 6 others (LocalSampling::kSpacingRank) within l against k - 1 within r_k, a share
/// of (6 / (k - 1)) (r_k / l)^2 (in 2D (2 / (k - 1)) (r_k / l)), at most all of it. On i.i.d.
/// samples pi rho r_k^2 is Gamma(k - 1)-distributed (rho: the sample's density), so there that
/// share's mean is 1 and the two together keep the spacing's (s / l)^2.
#pragma once

#include "geometry/nearest_point_index.h"
#include "sampling/cloud_halo.h"

#include <vector>

namespace lsr {

/// @brief The indices kept, in increasing order: every point whose scale is its sampling
/// scale, and of the points whose scale was raised (scale > sampling_scale) the share above. Chosen by a hash of the index (deterministic; a random choice does not alias
/// with scan lines as a regular one would). All points where no scale was raised.
/// @param scan_lines the cloud was read as scan lines (LocalSampling::scan_lines): measure
/// the density
/// @param threads 0 for all cores
/// @param halo data holds a worker's run and its halo (cloud_halo.h): the run's points are
/// chosen, with their global indices; null: data holds every point
template <int D>
std::vector<Index> mesh_resolution_sample(const NearestPointIndex<D>& data, const std::vector<double>& sampling_scale,
                                          const std::vector<double>& scale, bool scan_lines, int threads = 0,
                                          const CloudHalo* halo = nullptr);

}  // namespace lsr
