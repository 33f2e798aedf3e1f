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
// Points per query: bounds the neighbour lists (2.4 GB for 10M points at once).
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
                                          const std::vector<double>& scale, bool scan_lines, int threads, const CloudHalo* halo) {
  const Points<D>& p = data.points();
  const std::size_t first = halo ? halo->first : 0, end = halo ? halo->end : p.size();
  const auto global = [&](std::size_t i) { return halo ? i - first + halo->global_first : i; };
  const TileExchange* x = halo ? halo->exchange : nullptr;
  std::vector<double> share(p.size(), 1.0);
  for (std::size_t i = first; i < end; ++i) {
    if (scale[i] > sampling_scale[i]) share[i] = std::pow(sampling_scale[i] / scale[i], D - 1);
  }
  std::vector<Index> kept;
  kept.reserve(end - first);
  for (std::size_t i = first; i < end; ++i) {
    if (share[i] >= 1.0 || uniform(global(i)) < share[i]) kept.push_back(Index(i));
  }
  const std::size_t points = halo ? halo->global_size : p.size(), sampled = sum_over_workers(x, kept.size());
  if (!scan_lines || sampled == points) return kept;
  // The spacing's sample is a superset: its density is the data's times that share, so its
  // own r_k measures what is left to thin (at 10M points a tenth of the queries). A worker's
  // sample reads the others' within its points' k-th nearest.
  Points<D> kept_points(kept.size());
  for (std::size_t j = 0; j < kept.size(); ++j) kept_points[j] = p[std::size_t(kept[j])];
  const int k = int(std::min<std::size_t>(kDensityNeighbours<D>, sampled));
  HaloCloud<D> local = with_halo<D>(kept_points, 0, sampled, x, [&] { return own_neighbourhoods(kept_points, k, 1.0, threads, Progress()); });
  const NearestPointIndex<D> sample(std::move(local.points));
  const Points<D>& q = sample.points();
  // The k nearest are the point and k - 1 others.
  const double rank_share = double(LocalSampling<D>::kSpacingRank) / double(std::max(1, k - 1));
  std::vector<Index> thinned;
  for (std::size_t begin = 0; begin < kept.size(); begin += kBlock) {
    const std::size_t end_block = std::min(kept.size(), begin + kBlock);
    const Points<D> queries(q.begin() + long(local.halo.first + begin), q.begin() + long(local.halo.first + end_block));
    LargeVector<Index> nearest;
    sample.query_k(queries, k, nearest, threads);
    for (std::size_t j = begin; j < end_block; ++j) {
      const std::size_t i = std::size_t(kept[j]);
      if (!(scale[i] > sampling_scale[i])) {
        thinned.push_back(kept[j]);
        continue;
      }
      const double r = (q[std::size_t(nearest[(j - begin) * std::size_t(k) + std::size_t(k - 1)])] - q[local.halo.first + j]).norm();
      const double measured = share[i] * std::min(1.0, rank_share * std::pow(r / scale[i], D - 1));
      if (measured >= 1.0 || uniform(global(i)) < measured) thinned.push_back(kept[j]);
    }
  }
  return thinned;
}

template std::vector<Index> mesh_resolution_sample<2>(const NearestPointIndex<2>&, const std::vector<double>&,
                                                      const std::vector<double>&, bool, int, const CloudHalo*);
template std::vector<Index> mesh_resolution_sample<3>(const NearestPointIndex<3>&, const std::vector<double>&,
                                                      const std::vector<double>&, bool, int, const CloudHalo*);

}  // namespace lsr
