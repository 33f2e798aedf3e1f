// SPDX-License-Identifier: BSD-3-Clause
/// @file rim_normals.cpp
#include "fit/rim_normals.h"

#include "sampling/local_sampling.h"
#include "thread_count.h"

#include <algorithm>

#include <omp.h>

namespace lsr {

template <int D>
Points<D> rim_normals(const NearestPointIndex<D>& data, const Points<D>& queries, int threads) {
  const int k = std::min<int>(kRimNormalNeighbours<D>, int(data.points().size()));
  Points<D> normals(queries.size(), Vec<D>::Zero());
  if (k < HeightField<D>::kTerms) return normals;
  LargeVector<Index> nearest;
  data.query_k(queries, k, nearest, threads);
  const Points<D>& p = data.points();
  const long n = long(queries.size());
#pragma omp parallel for schedule(static) num_threads(detail::thread_count(threads))
  for (long q = 0; q < n; ++q) {
    const Index* near = &nearest[std::size_t(q) * std::size_t(k)];
    const Vec<D>& x = queries[std::size_t(q)];
    double thickness = 0.0;
    Vec<D> plane;
    pca(p, near, k, thickness, plane);
    // Over the query's own tangent frame: its slope there is g (a quadric is one in any origin).
    const HeightField<D> f = fit_height_field(p, near, k, x, plane, (p[std::size_t(near[k - 1])] - x).norm());
    Vec<D> local;
    local.template head<D - 1>() = -f.slope(Eigen::Matrix<double, D - 1, 1>::Zero());
    local[D - 1] = 1.0;
    // All zero: a degenerate fit (duplicates, colinear points), or an exact plane through the
    // query, whose normal the caller has anyway.
    if (f.coefficients != decltype(f.coefficients){}) normals[std::size_t(q)] = (tangent_frame(plane).transpose() * local).normalized();
  }
  return normals;
}

template Points<2> rim_normals<2>(const NearestPointIndex<2>&, const Points<2>&, int);
template Points<3> rim_normals<3>(const NearestPointIndex<3>&, const Points<3>&, int);

}  // namespace lsr
