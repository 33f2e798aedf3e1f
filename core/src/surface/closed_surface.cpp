// SPDX-License-Identifier: BSD-3-Clause
/// @file closed_surface.cpp
#include "surface/closed_surface.h"

#include "lsrecon/core/level_set_volume_mesh.h"
#include "surface/unsupported_parts.h"

namespace lsr::detail {

template <int D>
LevelSetMesh<D> extract_closed_surface(const SimplexMesh<D>& mesh, const Points<D>& points, std::vector<double>& values,
                                       int threads) {
  cap_at_walls<D>(mesh, values);
  LevelSetMesh<D> surface = extract_zero_level_set(mesh, values, kOutputEdgeMargin, threads);
  while (drop_unsupported_parts(mesh, surface, points, values, threads) > 0) {
    surface = extract_zero_level_set(mesh, values, kOutputEdgeMargin, threads);
  }
  return surface;
}

template <int D>
void attach_volume(ReconstructionResult<D>& r, const SimplexMesh<D>& mesh, const std::vector<double>& values,
                   bool wanted) {
  if (!wanted) return;
  r.volume = split_along_level_set(mesh, values, r.surface);
  // Where the split had to pull a vertex back, the surface follows: it is the inside's boundary.
  for (std::size_t i = 0; i < r.surface.vertices.size(); ++i) {
    r.surface.vertices[i] = r.volume.vertices[std::size_t(r.volume.interface_offset) + i];
  }
}

template <int D>
void attach_front(ReconstructionResult<D>& r, const SimplexMesh<D>& mesh, const P1Operators<D>& ops,
                  const Eigen::VectorXd& u, double level, const Points<D>& points, bool volume, int threads) {
  std::vector<double> values(u.data(), u.data() + u.size());
  for (double& v : values) v -= level;
  r.surface = extract_closed_surface(mesh, points, values, threads);
  attach_volume(r, mesh, values, volume);
  const Eigen::VectorXd g = ops.gradient_times(u);
  r.normals.resize(r.surface.vertices.size());
  for (std::size_t i = 0; i < r.surface.vertices.size(); ++i) {
    const EdgePoint& e = r.surface.sources[i];
    const Vec<D> n = (1.0 - e.t) * g.template segment<D>(D * e.a) + e.t * g.template segment<D>(D * e.b);
    r.normals[i] = n.norm() > 0.0 ? Vec<D>(n.normalized()) : Vec<D>::Zero();
  }
}

template <int D>
Points<D> oriented_normals(const LocalSampling<D>& s, const std::vector<Location<D>>& at, const Eigen::VectorXd& gradient) {
  Points<D> n = s.normals;
  for (std::size_t i = 0; i < n.size(); ++i) {
    Vec<D> g = Vec<D>::Zero();
    for (int k = 0; k <= D; ++k) g += at[i].weights[k] * gradient.template segment<D>(D * at[i].vertices[k]);
    if (n[i].dot(g) < 0.0) n[i] = -n[i];
  }
  return n;
}

template LevelSetMesh<2> extract_closed_surface<2>(const SimplexMesh<2>& mesh, const Points<2>& points, std::vector<double>& values,
                                       int threads);
template LevelSetMesh<3> extract_closed_surface<3>(const SimplexMesh<3>& mesh, const Points<3>& points, std::vector<double>& values,
                                       int threads);
template void attach_volume<2>(ReconstructionResult<2>& r, const SimplexMesh<2>& mesh, const std::vector<double>& values,
                   bool wanted);
template void attach_volume<3>(ReconstructionResult<3>& r, const SimplexMesh<3>& mesh, const std::vector<double>& values,
                   bool wanted);
template void attach_front<2>(ReconstructionResult<2>& r, const SimplexMesh<2>& mesh, const P1Operators<2>& ops,
                  const Eigen::VectorXd& u, double level, const Points<2>& points, bool volume, int threads);
template void attach_front<3>(ReconstructionResult<3>& r, const SimplexMesh<3>& mesh, const P1Operators<3>& ops,
                  const Eigen::VectorXd& u, double level, const Points<3>& points, bool volume, int threads);
template Points<2> oriented_normals<2>(const LocalSampling<2>& s, const std::vector<Location<2>>& at, const Eigen::VectorXd& gradient);
template Points<3> oriented_normals<3>(const LocalSampling<3>& s, const std::vector<Location<3>>& at, const Eigen::VectorXd& gradient);

}  // namespace lsr::detail
