// SPDX-License-Identifier: BSD-3-Clause
/// @file occupancy_start.cpp
#include "start/occupancy_start.h"

#include "sampling/local_sampling.h"
#include "start/normal_propagation.h"
#include "start/winding_number.h"
#include "thread_count.h"

#include <algorithm>
#include <cmath>

namespace lsr::detail {

template <int D>
Points<D> outward_normals(const Points<D>& points, const Points<D>& normals, const std::vector<double>& areas,
                          const LargeVector<Index>& knn, int k, const std::vector<double>& noise, const std::vector<double>& radii) {
  const PropagatedSenses tree = propagate_senses<D>(points, normals, knn, k, noise);
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
  if (parts < 2 || radii.empty()) return out;
  // Nested parts alternate: a part inside an odd number of others bounds a cavity and faces
  // inwards (even-odd rule). With every part turned outwards, w just outside a part's samples
  // (2 radii out, past its own jump) counts the parts around it; its median over the part's
  // samples, rounded, is the part's depth.
  const WindingNumber<D> w(points, out, areas, radii);
  std::vector<std::vector<double>> around(parts);
  for (std::size_t p = 0; p < points.size(); ++p) around[std::size_t(tree.part[p])].push_back(w.at(points[p] + 2.0 * radii[p] * out[p]));
  std::vector<char> cavity(parts);
  for (std::size_t q = 0; q < parts; ++q) {
    auto middle = around[q].begin() + std::ptrdiff_t(around[q].size() / 2);
    std::nth_element(around[q].begin(), middle, around[q].end());
    cavity[q] = std::lround(*middle) % 2 != 0;
  }
  for (std::size_t p = 0; p < points.size(); ++p) {
    if (cavity[std::size_t(tree.part[p])]) out[p] = -out[p];
  }
  return out;
}

namespace {
// A bound on the work, not a threshold: a region flipped by the spanning tree wears down by
// about a probe distance per pass (two spacings): 32 passes undo a region 64 spacings across.
constexpr int kConsistencyPasses = 32;
}  // namespace

template <int D>
void make_consistent(const Points<D>& points, Points<D>& outward, const std::vector<double>& areas,
                     const std::vector<double>& radii, const LargeVector<Index>& knn, int k, int threads) {
  const std::size_t n = points.size();
  std::vector<char> flip(n), tested(n, 1);
  bool all_tested = true;
  for (int pass = 0; pass < kConsistencyPasses; ++pass) {
    const WindingNumber<D> w(points, outward, areas, radii);
    std::size_t flips = 0;
#pragma omp parallel for schedule(dynamic, 256) reduction(+ : flips) num_threads(thread_count(threads))
    for (std::ptrdiff_t i = 0; i < std::ptrdiff_t(n); ++i) {
      const auto p = std::size_t(i);
      flip[p] = 0;
      if (!tested[p]) continue;
      const Vec<D> probe = 2.0 * radii[p] * outward[p];
      flip[p] = w.at(points[p] + probe) > w.at(points[p] - probe);
      flips += std::size_t(flip[p]);
    }
    if (flips == 0 && all_tested) return;
    std::fill(tested.begin(), tested.end(), char(flips == 0));
    all_tested = flips == 0;
    for (std::size_t p = 0; p < n; ++p) {
      if (!flip[p]) continue;
      outward[p] = -outward[p];
      for (int j = 0; j < k; ++j) tested[std::size_t(knn[p * std::size_t(k) + std::size_t(j)])] = 1;
    }
    // The graph made symmetric: p is tested again when a point among whose k nearest it is flipped.
    for (std::size_t p = 0; p < n && !all_tested; ++p) {
      for (int j = 0; j < k && !tested[p]; ++j) tested[p] = flip[std::size_t(knn[p * std::size_t(k) + std::size_t(j)])];
    }
  }
}

template <int D>
Eigen::VectorXd occupancy_start(const Points<D>& vertices, const NearestPointIndex<D>& data, const Points<D>& normals,
                                const std::vector<double>& noise, const std::vector<double>& scale, int threads) {
  const Points<D>& points = data.points();
  constexpr int k = LocalSampling<D>::kNeighbours, rank = LocalSampling<D>::kSpacingRank;
  LargeVector<Index> knn;
  data.query_k(points, k, knn, threads);
  // Each sample's area from the density of the sample summed (k - 1 others within the farthest
  // of its k nearest), not from the cloud's spacing: where the mesh reads a thinned sample
  // (mesh_resolution_sample.h) the spacing is the dense cloud's, and its areas would add up to
  // a fraction of the surface (w about 1/2 inside a body). Its radius: the spacing of that
  // density, or the point's scale where larger (noise: w smooth across the band the data fill).
  std::vector<double> area(points.size()), radius(points.size());
  for (std::size_t p = 0; p < points.size(); ++p) {
    const double reach = (points[std::size_t(knn[p * std::size_t(k) + std::size_t(k - 1)])] - points[p]).norm();
    area[p] = sample_measure<D>(reach, k - 1);
    radius[p] = std::max(reach * std::pow(double(rank) / (k - 1), 1.0 / (D - 1)), scale[p]);
  }
  Points<D> outward = outward_normals(points, normals, area, knn, k, noise, radius);
  make_consistent(points, outward, area, radius, knn, k, threads);
  const WindingNumber<D> w(points, outward, area, radius);
  Eigen::VectorXd u(Eigen::Index(vertices.size()));
#pragma omp parallel for schedule(dynamic, 1024) num_threads(thread_count(threads))
  for (std::ptrdiff_t v = 0; v < std::ptrdiff_t(vertices.size()); ++v) u[v] = 0.5 - w.at(vertices[std::size_t(v)]);
  return u;
}

template Points<2> outward_normals<2>(const Points<2>&, const Points<2>&, const std::vector<double>&, const LargeVector<Index>&, int,
                                      const std::vector<double>&, const std::vector<double>&);
template Points<3> outward_normals<3>(const Points<3>&, const Points<3>&, const std::vector<double>&, const LargeVector<Index>&, int,
                                      const std::vector<double>&, const std::vector<double>&);
template void make_consistent<2>(const Points<2>&, Points<2>&, const std::vector<double>&, const std::vector<double>&,
                                 const LargeVector<Index>&, int, int);
template void make_consistent<3>(const Points<3>&, Points<3>&, const std::vector<double>&, const std::vector<double>&,
                                 const LargeVector<Index>&, int, int);
template Eigen::VectorXd occupancy_start<2>(const Points<2>&, const NearestPointIndex<2>&, const Points<2>&, const std::vector<double>&,
                                            const std::vector<double>&, int);
template Eigen::VectorXd occupancy_start<3>(const Points<3>&, const NearestPointIndex<3>&, const Points<3>&, const std::vector<double>&,
                                            const std::vector<double>&, int);

}  // namespace lsr::detail
