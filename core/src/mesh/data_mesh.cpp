// SPDX-License-Identifier: BSD-3-Clause
/// @file data_mesh.cpp
#include "mesh/data_mesh.h"

#include "mesh/data_metric.h"
#include "mesh/metric_adaptation.h"
#include "sampling/data_preparation.h"

#include <algorithm>

namespace lsr::detail {

template <int D>
AdaptiveMesh<D> data_mesh(const NearestPointIndex<D>& data, std::vector<double>& point_scale, const ReconstructionOptions& o,
                          Index max_vertices, const Progress& progress, double& h_min) {
  AdaptiveMeshOptions mo;
  mo.point_size = local_mesh_sizes<D>(point_scale, o.mesh.h_min, o.mesh.max_resolution);
  for (std::size_t i = 0; i < point_scale.size(); ++i) point_scale[i] = std::max(point_scale[i], mo.point_size[i]);
  mo.h_min = *std::min_element(mo.point_size.begin(), mo.point_size.end());
  mo.h_max = std::max(o.mesh.h_max, mo.h_min);
  mo.grading = o.mesh.grading;
  mo.max_vertices = max_vertices;
  mo.threads = o.limits.threads;
  h_min = mo.h_min;
  return build_adaptive_mesh(data, mo, progress);
}

SimplexMesh<2> anisotropic_data_mesh(const SimplexMesh<2>& isotropic, const NearestPointIndex<2>& data, const LocalSampling<2>& sampling,
                                     const std::vector<double>& point_scale, const ReconstructionOptions& o, const Progress& progress) {
  progress.update("mesh", -1.0);
  const std::vector<double> size = local_mesh_sizes<2>(point_scale, o.mesh.h_min, o.mesh.max_resolution);
  return adapt_to_metric(isotropic, data_metric<2>(data, sampling, size, o.mesh.anisotropic_error, o.mesh.h_max));
}

template AdaptiveMesh<2> data_mesh<2>(const NearestPointIndex<2>&, std::vector<double>&, const ReconstructionOptions&, Index,
                                      const Progress&, double&);
template AdaptiveMesh<3> data_mesh<3>(const NearestPointIndex<3>&, std::vector<double>&, const ReconstructionOptions&, Index,
                                      const Progress&, double&);

}  // namespace lsr::detail
