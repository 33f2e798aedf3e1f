// SPDX-License-Identifier: BSD-3-Clause
/// @file data_mesh.cpp
#include "mesh/data_mesh.h"

#include "mesh/data_metric.h"
#include "mesh/metric_adaptation.h"
#include "sampling/data_preparation.h"

#include <algorithm>

namespace lsr::detail {

namespace {

// The Kuhn mesh's options: each point's size, and its scale raised to it.
template <int D>
AdaptiveMeshOptions mesh_options(std::vector<double>& point_scale, const ReconstructionOptions& o, Index max_vertices, double& h_min) {
  AdaptiveMeshOptions mo;
  mo.point_size = local_mesh_sizes<D>(point_scale, o.mesh.h_min, o.mesh.max_resolution);
  for (std::size_t i = 0; i < point_scale.size(); ++i) point_scale[i] = std::max(point_scale[i], mo.point_size[i]);
  mo.h_min = *std::min_element(mo.point_size.begin(), mo.point_size.end());
  mo.h_max = std::max(o.mesh.h_max, mo.h_min);
  mo.grading = o.mesh.grading;
  mo.max_vertices = max_vertices;
  mo.threads = o.limits.threads;
  h_min = mo.h_min;
  return mo;
}

// The anisotropic mesh starts from the Kuhn mesh this much coarser than the data's sizes and
// splits down to them across: starting at the data's sizes, it collapses nine vertices in ten
// (the factor is calibrated: docs/calibration.md).
template <int D>
constexpr double kAnisotropicStartCoarsening = D == 2 ? 8.0 : 4.0;

}  // namespace

template <int D>
AdaptiveMesh<D> data_mesh(const NearestPointIndex<D>& data, std::vector<double>& point_scale, const ReconstructionOptions& o,
                          Index max_vertices, const Progress& progress, double& h_min) {
  return build_adaptive_mesh(data, mesh_options<D>(point_scale, o, max_vertices, h_min), progress);
}

template <int D>
SimplexMesh<D> anisotropic_data_mesh(const NearestPointIndex<D>& data, const LocalSampling<D>& sampling, std::vector<double>& point_scale,
                                     const ReconstructionOptions& o, Index max_vertices, const Progress& progress, double& h_min) {
  AdaptiveMeshOptions mo = mesh_options<D>(point_scale, o, max_vertices, h_min);
  const std::vector<double> size = mo.point_size;
  for (double& x : mo.point_size) x = std::min(kAnisotropicStartCoarsening<D> * x, mo.h_max);
  mo.h_min = std::min(kAnisotropicStartCoarsening<D> * mo.h_min, mo.h_max);
  const SimplexMesh<D> start = build_adaptive_mesh(data, mo, progress).mesh;
  progress.update("mesh", -1.0);
  return adapt_to_metric(start, data_metric<D>(data, sampling, size, o.mesh.anisotropic_error, o.mesh.h_max));
}

template SimplexMesh<2> anisotropic_data_mesh<2>(const NearestPointIndex<2>&, const LocalSampling<2>&, std::vector<double>&,
                                                 const ReconstructionOptions&, Index, const Progress&, double&);
template SimplexMesh<3> anisotropic_data_mesh<3>(const NearestPointIndex<3>&, const LocalSampling<3>&, std::vector<double>&,
                                                 const ReconstructionOptions&, Index, const Progress&, double&);
template AdaptiveMesh<2> data_mesh<2>(const NearestPointIndex<2>&, std::vector<double>&, const ReconstructionOptions&, Index,
                                      const Progress&, double&);
template AdaptiveMesh<3> data_mesh<3>(const NearestPointIndex<3>&, std::vector<double>&, const ReconstructionOptions&, Index,
                                      const Progress&, double&);

}  // namespace lsr::detail
