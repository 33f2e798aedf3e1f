// SPDX-License-Identifier: BSD-3-Clause
/// @file data_mesh.h
/// @brief The mesh of the box the front evolves on: fine near the data, at each point's local
/// scale within the resolution limits, coarse away from it.
#pragma once

#include "lsrecon/core/level_set_reconstruction.h"
#include "lsrecon/core/progress.h"
#include "mesh/adaptive_refinement.h"
#include "sampling/local_sampling.h"

#include <vector>

namespace lsr::detail {

/// @brief The adaptive mesh sized by `point_scale` (local_mesh_sizes: clamped to the resolution
/// limits, or the size asked for), at most `max_vertices`. A mesh coarser than the sampling
/// resolves no finer than its own size: each point's scale is raised to the mesh size near it,
/// so that tolerances, pins and fits follow the coarser of the two. `h_min` is the finest size.
template <int D>
AdaptiveMesh<D> data_mesh(const NearestPointIndex<D>& data, std::vector<double>& point_scale, const ReconstructionOptions& o,
                          Index max_vertices, const Progress& progress, double& h_min);

/// @brief The mesh adapted to the data's metric (data_metric.h): the sizes of data_mesh across
/// the data, longer along it where it is flat (metric_adaptation.h). Raises point_scale and
/// sets h_min as data_mesh does.
template <int D>
SimplexMesh<D> anisotropic_data_mesh(const NearestPointIndex<D>& data, const LocalSampling<D>& sampling, std::vector<double>& point_scale,
                                     const ReconstructionOptions& o, Index max_vertices, const Progress& progress, double& h_min);

}  // namespace lsr::detail
