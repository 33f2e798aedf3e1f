// SPDX-License-Identifier: BSD-3-Clause
/// @file mesh_resolution_sample.cpp
#include "fit/mesh_resolution_sample.h"

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
// Points measured per query: bounds the neighbour lists (10M points, 2.4 GB at once).
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
  const int k = std::min<int>(kDensityNeighbours<D>, int(p.size()));
  std::vector<double> share(p.size(), 1.0);
  std::vector<std::size_t> measured;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!(scale[i] > sampling_scale[i])) continue;
    if (scan_lines) {
      measured.push_back(i);
    } else {
      share[i] = std::pow(sampling_scale[i] / scale[i], D - 1);
    }
  }
  // The k nearest are the point and k - 1 others.
  const double rank_share = double(LocalSampling<D>::kSpacingRank) / double(std::max(1, k - 1));
  for (std::size_t begin = 0; begin < measured.size(); begin += kBlock) {
    const std::size_t end = std::min(measured.size(), begin + kBlock);
    Points<D> queries;
    for (std::size_t j = begin; j < end; ++j) queries.push_back(p[measured[j]]);
    LargeVector<Index> nearest;
    data.query_k(queries, k, nearest, threads);
    for (std::size_t j = begin; j < end; ++j) {
      const std::size_t i = measured[j];
      const double r = (p[std::size_t(nearest[(j - begin) * std::size_t(k) + std::size_t(k - 1)])] - p[i]).norm();
      share[i] = rank_share * std::pow(r / scale[i], D - 1);
    }
  }
  std::vector<Index> kept;
  kept.reserve(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (share[i] >= 1.0 || uniform(i) < share[i]) kept.push_back(Index(i));
  }
  return kept;
}

template std::vector<Index> mesh_resolution_sample<2>(const NearestPointIndex<2>&, const std::vector<double>&,
                                                      const std::vector<double>&, bool, int);
template std::vector<Index> mesh_resolution_sample<3>(const NearestPointIndex<3>&, const std::vector<double>&,
                                                      const std::vector<double>&, bool, int);

}  // namespace lsr
