// SPDX-License-Identifier: BSD-3-Clause
/// @file vertex_fields.cpp
#include "mesh/vertex_fields.h"

#include <utility>

namespace lsr::detail {

template <int D>
VertexFields<D> vertex_fields(const NearestPointIndex<D>& data, const SimplexMesh<D>& mesh, const LocalSampling<D>& sampling,
                              const std::vector<double>& point_scale, int threads) {
  VertexFields<D> f;
  data.query(mesh.vertices, f.dist, &f.nearest, threads);
  const std::size_t nv = mesh.vertices.size();
  f.scale.resize(Eigen::Index(nv));
  f.noise.resize(Eigen::Index(nv));
  for (std::size_t v = 0; v < nv; ++v) {
    f.scale[v] = point_scale[f.nearest[v]];
    f.noise[v] = sampling.noise[f.nearest[v]];
  }
  f.distance = Eigen::Map<const Eigen::VectorXd>(f.dist.data(), Eigen::Index(f.dist.size()));
  return f;
}

template <int D>
Points<D> away_from_data(const NearestPointIndex<D>& data, const SimplexMesh<D>& mesh, const VertexFields<D>& fields) {
  const std::size_t nv = mesh.vertices.size();
  Points<D> away(nv, Vec<D>::Zero());
  for (std::size_t v = 0; v < nv; ++v) {
    if (fields.dist[v] > 0.0) away[v] = (mesh.vertices[v] - data.points()[std::size_t(fields.nearest[v])]) / fields.dist[v];
  }
  return away;
}

template <int D>
void release_forest(AdaptiveMesh<D>& adaptive) {
  const KuhnBisectionForest<D> forest = std::move(adaptive.forest);
  const std::vector<Index> nodes = std::move(adaptive.simplex_of_node);
  const std::vector<Index> renumbered = std::move(adaptive.vertex_of_node_vertex);
}

template VertexFields<2> vertex_fields<2>(const NearestPointIndex<2>&, const SimplexMesh<2>&, const LocalSampling<2>&,
                                          const std::vector<double>&, int);
template VertexFields<3> vertex_fields<3>(const NearestPointIndex<3>&, const SimplexMesh<3>&, const LocalSampling<3>&,
                                          const std::vector<double>&, int);
template Points<2> away_from_data<2>(const NearestPointIndex<2>&, const SimplexMesh<2>&, const VertexFields<2>&);
template Points<3> away_from_data<3>(const NearestPointIndex<3>&, const SimplexMesh<3>&, const VertexFields<3>&);
template void release_forest<2>(AdaptiveMesh<2>&);
template void release_forest<3>(AdaptiveMesh<3>&);

}  // namespace lsr::detail
