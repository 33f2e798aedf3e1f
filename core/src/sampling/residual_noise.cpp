// SPDX-License-Identifier: BSD-3-Clause
/// @file residual_noise.cpp
#include "sampling/residual_noise.h"

#include "sampling/local_sampling.h"
#include "thread_count.h"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>

#include <omp.h>

namespace lsr {
namespace {

// Deviation of the same-facing neighbours about their quadric; -1 when too few are left to
// tell noise from the fit's freedom.
template <int D>
double quadric_residual(const Points<D>& p, const Points<D>& normals, const Index* near, int k, std::size_t i) {
  constexpr int kTerms = HeightField<D>::kTerms;
  const Eigen::Matrix<double, D, D> frame = tangent_frame(normals[i]);
  const double radius = (p[near[k - 1]] - p[i]).norm();
  if (!(radius > 0.0)) return 0.0;  // all duplicates
  Eigen::Matrix<double, kTerms, kTerms> ata = Eigen::Matrix<double, kTerms, kTerms>::Zero();
  Eigen::Matrix<double, kTerms, 1> ath = Eigen::Matrix<double, kTerms, 1>::Zero();
  int used = 0;
  for (int j = 0; j < k; ++j) {
    if (normals[near[j]].dot(normals[i]) <= 0.0) continue;
    const Vec<D> y = frame * (p[near[j]] - p[i]) / radius;  // well conditioned in units of the radius
    const Eigen::Matrix<double, kTerms, 1> row = HeightField<D>::monomials(y.template head<D - 1>());
    ata += row * row.transpose();
    ath += row * y[D - 1];
    ++used;
  }
  if (used < kTerms + 3) return -1.0;
  const Eigen::Matrix<double, kTerms, 1> c = ata.ldlt().solve(ath);
  if (!c.allFinite()) return -1.0;
  double squares = 0.0;
  for (int j = 0; j < k; ++j) {
    if (normals[near[j]].dot(normals[i]) <= 0.0) continue;
    const Vec<D> y = frame * (p[near[j]] - p[i]) / radius;
    squares += std::pow(y[D - 1] - HeightField<D>::monomials(y.template head<D - 1>()).dot(c), 2);
  }
  return radius * std::sqrt(squares / (used - kTerms));
}

}  // namespace

template <int D>
std::vector<double> residual_noise(const NearestPointIndex<D>& data, const Points<D>& normals, int k, int threads) {
  k = std::min<int>(k, int(data.points().size()));
  LargeVector<Index> nearest;
  if (k > 0) data.query_k(data.points(), k, nearest, threads);
  return residual_noise(data.points(), normals, nearest, k, threads);
}

template <int D>
std::vector<double> residual_noise(const Points<D>& p, const Points<D>& normals, const LargeVector<Index>& nearest,
                                   int k, int threads) {
  const long n = long(p.size());
  std::vector<double> noise(p.size(), 0.0);
  if (k < HeightField<D>::kTerms + 3) return noise;
  const int t = detail::thread_count(threads);
  std::vector<double> raw(p.size());
#pragma omp parallel for schedule(static) num_threads(t)
  for (long i = 0; i < n; ++i) raw[std::size_t(i)] = quadric_residual<D>(p, normals, &nearest[std::size_t(i) * k], k, std::size_t(i));
  constexpr double kSamples = LocalSampling<D>::kNeighbours;
  const double pca_scale = std::sqrt((kSamples - D) / kSamples);
#pragma omp parallel for schedule(static) num_threads(t)
  for (long i = 0; i < n; ++i) {
    double values[64];
    int m = 0;
    for (int j = 0; j < k && m < 64; ++j) {
      const double r = raw[nearest[std::size_t(i) * k + std::size_t(j)]];
      if (r >= 0.0) values[m++] = r;
    }
    if (m == 0) continue;
    std::nth_element(values, values + m / 2, values + m);
    noise[std::size_t(i)] = pca_scale * values[m / 2];
  }
  return noise;
}

template std::vector<double> residual_noise<2>(const NearestPointIndex<2>&, const Points<2>&, int, int);
template std::vector<double> residual_noise<3>(const NearestPointIndex<3>&, const Points<3>&, int, int);
template std::vector<double> residual_noise<2>(const Points<2>&, const Points<2>&, const LargeVector<Index>&, int, int);
template std::vector<double> residual_noise<3>(const Points<3>&, const Points<3>&, const LargeVector<Index>&, int, int);

}  // namespace lsr
