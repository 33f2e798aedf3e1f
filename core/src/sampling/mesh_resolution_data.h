// SPDX-License-Identifier: BSD-3-Clause
/// @file mesh_resolution_data.h
/// @brief The data the stages after the sampling read: where the cloud is denser than the mesh
/// resolves, the sample of mesh_resolution_sample.h with its sampling, so that the mesh, the
/// front, the stopping test and the fits cost what the mesh's cap allows, not what the cloud
/// holds (10M points: 51 s after the sampling against 21 s, docs/how-it-works.md).
#pragma once

#include "geometry/nearest_point_index.h"
#include "sampling/cloud_halo.h"
#include "sampling/local_sampling.h"

#include <vector>

namespace lsr::detail {

/// @brief What keep_mesh_resolution left out: what each kept point stands for, and what gives
/// every point its normal at the end. All empty when every point was kept.
template <int D>
struct LeftOut {
  std::vector<Index> kept;         ///< the points kept, increasing indices into the full data
  std::vector<Index> nearest;      ///< every point's nearest kept point (an index into the kept data)
  std::vector<Index> represented;  ///< #kept: the points of the cloud nearest to each, itself included
  Points<D> normals;               ///< every point's PCA normal (LocalSampling::normals)
};

/// @brief Thins data, sampling and point_scale in place to mesh_resolution_sample's points,
/// the sample at the mesh size of each point (mesh_size: local_mesh_sizes of point_scale), the
/// rim points (LocalSampling::rim), and in 2D the points farther than their size from those:
/// on a curve every point lies within its size of a kept point. Nothing changes where no size
/// exceeds its point's scale.
/// @param threads 0 for all cores
/// @param halo data holds a worker's run and its halo (cloud_halo.h): its run is thinned, to
/// the bit as one process thins it, sampling and point_scale to the run's kept points; data is
/// left as it is, and LeftOut has kept (indices into data) and represented only. Null: data
/// holds every point.
template <int D>
LeftOut<D> keep_mesh_resolution(NearestPointIndex<D>& data, LocalSampling<D>& sampling, std::vector<double>& point_scale,
                                const std::vector<double>& mesh_size, int threads, const CloudHalo* halo = nullptr);

/// @brief Every point's outward normal: a kept point's is `oriented` (#kept, in the kept data's
/// order), a point left out turns its PCA normal to agree with that of its nearest kept point,
/// at most about one mesh size away on the same sheet. Without a point left out, `oriented`.
template <int D>
Points<D> every_point_normals(const LeftOut<D>& out, Points<D> oriented);

}  // namespace lsr::detail
