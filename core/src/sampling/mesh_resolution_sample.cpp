// SPDX-License-Identifier: BSD-3-Clause
/// @file mesh_resolution_sample.cpp
#include "sampling/mesh_resolution_sample.h"

#include "sampling/local_sampling.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace lsr {
namespace {

// The density's neighbours: as many as a clean fit reads (QuadricImplicit::kFitNeighbours), so
// that on scan lines they reach the next lines.
template <int D>
constexpr int kDensityNeighbours = D == 2 ? 10 : 30;
// Points measured per query: bounds the neighbour lists (2.4 GB for 10M points at once).
constexpr std::size_t kBlock = std::size_t(1) << 16;

// A uniform number in [0, 1) from the index (splitmix64's finaliser).
double uniform(std::uint64_t i) {
  std::uint64_t z = i + 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  z ^= z >> 31;
  return double(z >> 11) * 0x1.0p-53;
}

}  // namespace

template <int D>
std::vector<Index> mesh_resolution_sample(const NearestPointIndex<D>& data, const std::vector<double>& sampling_scale,
                                          const std::vector<double>& scale, bool scan_lines, int threads) {
  const Points<D>& p = data.points();
  std::vector<double> share(p.size(), 1.0);
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (scale[i] > sampling_scale[i]) share[i] = std::pow(sampling_scale[i] / scale[i], D - 1);
  }
  std::vector<Index> kept;
  kept.reserve(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (share[i] >= 1.0 || uniform(i) < share[i]) kept.push_back(Index(i));
  }
  if (!scan_lines || kept.size() == p.size()) return kept;
  // The spacing's sample is a superset: its density is the data's times that share, so its
  // own r_k measures what is left to thin (at 10M points a tenth of the queries).
  Points<D> kept_points(kept.size());
  for (std::size_t j = 0; j < kept.size(); ++j) kept_points[j] = p[std::size_t(kept[j])];
  const NearestPointIndex<D> sample(std::move(kept_points));
  const Points<D>& q = sample.points();
  const int k = std::min<int>(kDensityNeighbours<D>, int(q.size()));
  // The k nearest are the point and k - 1 others.
  const double rank_share = double(LocalSampling<D>::kSpacingRank) / double(std::max(1, k - 1));
  std::vector<Index> thinned;
  for (std::size_t begin = 0; begin < q.size(); begin += kBlock) {
    const std::size_t end = std::min(q.size(), begin + kBlock);
    const Points<D> queries(q.begin() + long(begin), q.begin() + long(end));
    LargeVector<Index> nearest;
    sample.query_k(queries, k, nearest, threads);
    for (std::size_t j = begin; j < end; ++j) {
      const std::size_t i = std::size_t(kept[j]);
      if (!(scale[i] > sampling_scale[i])) {
        thinned.push_back(kept[j]);
        continue;
      }
      const double r = (q[std::size_t(nearest[(j - begin) * std::size_t(k) + std::size_t(k - 1)])] - q[j]).norm();
      const double measured = share[i] * std::min(1.0, rank_share * std::pow(r / scale[i], D - 1));
      if (measured >= 1.0 || uniform(i) < measured) thinned.push_back(kept[j]);
    }
  }
  return thinned;
}

template std::vector<Index> mesh_resolution_sample<2>(const NearestPointIndex<2>&, const std::vector<double>&,
                                                      const std::vector<double>&, bool, int);
template std::vector<Index> mesh_resolution_sample<3>(const NearestPointIndex<3>&, const std::vector<double>&,
                                                      const std::vector<double>&, bool, int);

}  // namespace lsr
