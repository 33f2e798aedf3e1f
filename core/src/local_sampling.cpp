// SPDX-License-Identifier: BSD-3-Clause
/// @file local_sampling.cpp
#include "lsrecon/core/local_sampling.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

#include <omp.h>

namespace lsr {
namespace {

// Distance to the rank-th neighbour counting each position once (copies of p_i or of a
// neighbour are skipped; the farthest found if fewer).
template <int D>
double kth_distinct_distance(const Points<D>& p, const Index* nearest, int k, std::size_t i, int rank) {
  int found = 0;
  double last = 0.0;
  const Vec<D>* previous = &p[i];
  for (int j = 0; j < k; ++j) {
    const Vec<D>& q = p[nearest[j]];
    if (q == p[i] || q == *previous) continue;  // sorted by distance: copies are adjacent
    previous = &q;
    last = (q - p[i]).norm();
    if (++found == rank) break;
  }
  return last;
}

template <int D>
void pca(const Points<D>& p, const Index* nearest, int k, double& thickness, Vec<D>& normal) {
  Vec<D> mean = Vec<D>::Zero();
  for (int j = 0; j < k; ++j) mean += p[nearest[j]];
  mean /= double(k);
  Eigen::Matrix<double, D, D> cov = Eigen::Matrix<double, D, D>::Zero();
  for (int j = 0; j < k; ++j) {
    const Vec<D> e = p[nearest[j]] - mean;
    cov += e * e.transpose() / double(k);
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, D, D>> eig(cov);
  thickness = std::sqrt(std::max(0.0, eig.eigenvalues()[0]));
  normal = eig.eigenvectors().col(0);
}

// Median of raw over each point's neighbourhood.
std::vector<double> neighbourhood_median(const std::vector<double>& raw, const std::vector<Index>& nearest, int k,
                                         int threads) {
  std::vector<double> out(raw.size());
  const long n = long(raw.size());
#pragma omp parallel for schedule(static) num_threads(threads)
  for (long i = 0; i < n; ++i) {
    double v[32];
    for (int j = 0; j < k; ++j) v[j] = raw[nearest[std::size_t(i) * k + j]];
    std::nth_element(v, v + k / 2, v + k);
    out[i] = v[k / 2];
  }
  return out;
}

}  // namespace

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

template <int D>
LocalSampling<D> estimate_local_sampling(const NearestPointIndex<D>& data, int threads) {
  constexpr int k = LocalSampling<D>::kNeighbours;
  const int t = threads > 0 ? threads : omp_get_max_threads();
  const Points<D>& p = data.points();
  LocalSampling<D> s;
  std::vector<Index> neighbours;
  data.query_k(p, k, neighbours, t);
  const long n = long(p.size());
  std::vector<double> spacing(p.size()), noise(p.size());
  s.normals.resize(p.size());
  s.gap.resize(p.size());
#pragma omp parallel for schedule(static) num_threads(t)
  for (long i = 0; i < n; ++i) {
    const Index* nearest = &neighbours[std::size_t(i) * k];
    spacing[i] = kth_distinct_distance(p, nearest, k, std::size_t(i), LocalSampling<D>::kSpacingRank);
    s.gap[i] = kth_distinct_distance(p, nearest, k, std::size_t(i), 1);
    pca(p, nearest, k, noise[i], s.normals[i]);
  }
  s.spacing = neighbourhood_median(spacing, neighbours, k, t);
  s.noise = neighbourhood_median(noise, neighbours, k, t);
  return s;
}

template LocalSampling<2> estimate_local_sampling<2>(const NearestPointIndex<2>&, int);
template LocalSampling<3> estimate_local_sampling<3>(const NearestPointIndex<3>&, int);

}  // namespace lsr
