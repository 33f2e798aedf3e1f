// SPDX-License-Identifier: BSD-3-Clause
/// @file rim_normals.cpp
#include "fit/rim_normals.h"

#include "sampling/local_sampling.h"

#include <Eigen/Eigenvalues>

#include <algorithm>

#include <omp.h>

namespace lsr {

template <int D>
Points<D> rim_normals(const NearestPointIndex<D>& data, const Points<D>& queries, int threads) {
  constexpr int kTerms = HeightField<D>::kTerms;
  const int k = std::min<int>(kRimNormalNeighbours<D>, int(data.points().size()));
  Points<D> normals(queries.size(), Vec<D>::Zero());
  if (k < kTerms) return normals;
  LargeVector<Index> nearest;
  data.query_k(queries, k, nearest, threads);
  const Points<D>& p = data.points();
  const long n = long(queries.size());
#pragma omp parallel for schedule(static) num_threads(threads > 0 ? threads : omp_get_max_threads())
  for (long q = 0; q < n; ++q) {
    const Index* near = &nearest[std::size_t(q) * std::size_t(k)];
    Vec<D> centre = Vec<D>::Zero();
    for (int j = 0; j < k; ++j) centre += p[std::size_t(near[j])];
    centre /= double(k);
    Eigen::Matrix<double, D, D> scatter = Eigen::Matrix<double, D, D>::Zero();
    double radius = 0.0;
    for (int j = 0; j < k; ++j) {
      const Vec<D> y = p[std::size_t(near[j])] - centre;
      scatter += y * y.transpose();
      radius = std::max(radius, y.norm());
    }
    if (!(radius > 0.0)) continue;
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, D, D>> pca(scatter);
    const Eigen::Matrix<double, D, D> frame = tangent_frame<D>(pca.eigenvectors().col(0));
    // Normal equations in units of the neighbourhood's radius (well conditioned).
    Eigen::Matrix<double, kTerms, kTerms> ata = Eigen::Matrix<double, kTerms, kTerms>::Zero();
    Eigen::Matrix<double, kTerms, 1> ath = Eigen::Matrix<double, kTerms, 1>::Zero();
    for (int j = 0; j < k; ++j) {
      const Vec<D> y = frame * (p[std::size_t(near[j])] - centre) / radius;
      const Eigen::Matrix<double, kTerms, 1> row = HeightField<D>::monomials(y.template head<D - 1>());
      ata += row * row.transpose();
      ath += row * y[D - 1];
    }
    const Eigen::Matrix<double, kTerms, 1> c = ata.ldlt().solve(ath);
    if (!c.allFinite()) continue;
    HeightField<D> f;
    for (int t = 0; t < kTerms; ++t) f.coefficients[std::size_t(t)] = c[t];
    const Vec<D> foot = frame * (queries[std::size_t(q)] - centre) / radius;
    Vec<D> local;
    local.template head<D - 1>() = -f.slope(foot.template head<D - 1>());  // slopes are unitless
    local[D - 1] = 1.0;
    normals[std::size_t(q)] = (frame.transpose() * local).normalized();
  }
  return normals;
}

template Points<2> rim_normals<2>(const NearestPointIndex<2>&, const Points<2>&, int);
template Points<3> rim_normals<3>(const NearestPointIndex<3>&, const Points<3>&, int);

}  // namespace lsr
