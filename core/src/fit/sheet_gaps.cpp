// SPDX-License-Identifier: BSD-3-Clause
/// @file sheet_gaps.cpp
#include "fit/sheet_gaps.h"

#include "thread_count.h"

#include <algorithm>

#include <omp.h>

namespace lsr {

template <int D>
std::vector<char> between_facing_sheets(const NearestPointIndex<D>& data, const Points<D>& normals,
                                        const Points<D>& queries, const std::vector<double>& distance,
                                        const std::vector<double>& beyond, int threads) {
  constexpr double kReach = 1.5, kOpposite = -0.5, kFacing = 0.8;
  // The few points nearest to q hold those within 1.5 times its distance: on random samples of
  // two sheets about a dozen.
  constexpr int kNear = 16;
  const int k = std::min<int>(kNear, int(data.points().size()));
  std::vector<char> between(queries.size(), 0);
  // Only the queries beyond their noise band are asked (most are not).
  std::vector<std::size_t> asked;
  Points<D> far;
  for (std::size_t q = 0; q < queries.size(); ++q) {
    if (!(distance[q] > beyond[q])) continue;
    asked.push_back(q);
    far.push_back(queries[q]);
  }
  if (asked.empty() || k < 2) return between;
  LargeVector<Index> nearest;
  data.query_k(far, k, nearest, threads);
  const Points<D>& p = data.points();
#pragma omp parallel for schedule(static) num_threads(detail::thread_count(threads))
  for (std::ptrdiff_t slot = 0; slot < std::ptrdiff_t(asked.size()); ++slot) {
    const std::size_t q = asked[std::size_t(slot)];
    // The unit directions q -> p of the near points that q faces.
    Vec<D> towards[kNear];
    int facing = 0;
    for (int j = 0; j < k; ++j) {
      const Index i = nearest[std::size_t(slot) * k + j];
      const Vec<D> d = p[i] - queries[q];
      const double length = d.norm();
      if (length > kReach * distance[q]) continue;
      if (-d.dot(normals[i]) > kFacing * length) towards[facing++] = d / length;
    }
    for (int a = 0; a < facing && !between[q]; ++a) {
      for (int b = a + 1; b < facing; ++b) {
        if (towards[a].dot(towards[b]) < kOpposite) {
          between[q] = 1;
          break;
        }
      }
    }
  }
  return between;
}

template std::vector<char> between_facing_sheets<2>(const NearestPointIndex<2>&, const Points<2>&, const Points<2>&,
                                                    const std::vector<double>&, const std::vector<double>&, int);
template std::vector<char> between_facing_sheets<3>(const NearestPointIndex<3>&, const Points<3>&, const Points<3>&,
                                                    const std::vector<double>&, const std::vector<double>&, int);

}  // namespace lsr
