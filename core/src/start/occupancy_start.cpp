// SPDX-License-Identifier: BSD-3-Clause
/// @file occupancy_start.cpp
#include "start/occupancy_start.h"

#include "start/normal_propagation.h"
#include "start/winding_number.h"

#include <omp.h>

namespace lsr::detail {

template <int D>
Points<D> outward_normals(const Points<D>& points, const Points<D>& normals, const std::vector<double>& areas,
                          const LargeVector<Index>& knn, int k) {
  const PropagatedSenses tree = propagate_senses<D>(points, normals, knn, k);
  const auto parts = std::size_t(tree.parts);
  std::vector<Vec<D>> centroid(parts, Vec<D>::Zero());
  std::vector<double> count(parts, 0.0), flux(parts, 0.0);
  for (std::size_t p = 0; p < points.size(); ++p) {
    centroid[std::size_t(tree.part[p])] += points[p];
    count[std::size_t(tree.part[p])] += 1.0;
  }
  for (std::size_t q = 0; q < parts; ++q) centroid[q] /= count[q];
  for (std::size_t p = 0; p < points.size(); ++p) {
    const auto q = std::size_t(tree.part[p]);
    flux[q] += areas[p] * tree.sense[p] * normals[p].dot(points[p] - centroid[q]);
  }
  Points<D> out(normals.size());
  for (std::size_t p = 0; p < normals.size(); ++p) {
    out[p] = (flux[std::size_t(tree.part[p])] >= 0.0 ? 1.0 : -1.0) * tree.sense[p] * normals[p];
  }
  return out;
}

template <int D>
Eigen::VectorXd occupancy_start(const Points<D>& vertices, const Points<D>& points, const Points<D>& normals,
                                const std::vector<double>& spacing, const LargeVector<Index>& knn, int k, int threads) {
  std::vector<double> area(points.size());
  for (std::size_t p = 0; p < points.size(); ++p) area[p] = sample_measure<D>(spacing[p]);
  const WindingNumber<D> w(points, outward_normals(points, normals, area, knn, k), area, spacing);
  Eigen::VectorXd u(Eigen::Index(vertices.size()));
#pragma omp parallel for schedule(dynamic, 1024) num_threads(threads > 0 ? threads : omp_get_max_threads())
  for (std::ptrdiff_t v = 0; v < std::ptrdiff_t(vertices.size()); ++v) u[v] = 0.5 - w.at(vertices[std::size_t(v)]);
  return u;
}

template Points<2> outward_normals<2>(const Points<2>&, const Points<2>&, const std::vector<double>&, const LargeVector<Index>&, int);
template Points<3> outward_normals<3>(const Points<3>&, const Points<3>&, const std::vector<double>&, const LargeVector<Index>&, int);
template Eigen::VectorXd occupancy_start<2>(const Points<2>&, const Points<2>&, const Points<2>&, const std::vector<double>&, const LargeVector<Index>&, int, int);
template Eigen::VectorXd occupancy_start<3>(const Points<3>&, const Points<3>&, const Points<3>&, const std::vector<double>&, const LargeVector<Index>&, int, int);

}  // namespace lsr::detail
