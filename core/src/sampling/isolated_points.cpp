// SPDX-License-Identifier: BSD-3-Clause
/// @file isolated_points.cpp
#include "sampling/isolated_points.h"

#include "sampling/spacing_over_gaps.h"

#include <algorithm>

namespace lsr {

template <int D>
bool isolated_points_found(const NearestPointIndex<D>& data, const LargeVector<Index>& neighbours, bool raised, double factor,
                           int threads, const TileRuns& tiles, LocalSampling<D>& s) {
  constexpr int k = LocalSampling<D>::kNeighbours, wide = LocalSampling<D>::kHoleNeighbours;
  const Points<D>& p = data.points();
  const std::size_t first = tiles.first();
  std::vector<std::size_t> candidates;
  for (std::size_t i = first; i < tiles.end(); ++i) {
    if (s.gap[i] > factor * s.spacing[i]) candidates.push_back(i);
  }
  if (tiles.sum(long(candidates.size())) == 0) return false;  // the usual case: nothing to raise or exchange
  std::vector<double> spacing(candidates.size());
  for (std::size_t c = 0; c < candidates.size(); ++c) spacing[c] = s.spacing[candidates[c]];
  if (raised) {
    // The gap widths of the candidates' neighbours, each from its owner's index, where its
    // kHoleNeighbours nearest are the cloud's.
    std::vector<int> asked(p.size(), 0);
    for (const std::size_t i : candidates) {
      for (int j = 0; j < k; ++j) asked[std::size_t(neighbours[(i - first) * k + std::size_t(j)])] = 1;
    }
    if (tiles.halo) tiles.halo->add_to_owners(asked);
    Points<D> at;
    std::vector<std::size_t> which;
    for (std::size_t i = first; i < tiles.end(); ++i) {
      if (asked[i] == 0) continue;
      at.push_back(p[i]);
      which.push_back(i);
    }
    LargeVector<Index> around;
    data.query_k(at, wide, around, threads);
    std::vector<double> width(p.size(), 0.0);
    for (std::size_t q = 0; q < which.size(); ++q) {
      Vec<D> normal = s.normals[which[q]];
      double noise = 0.0;
      width[which[q]] = gap_width(p, &around[q * wide], which[q], normal, noise);
    }
    tiles.share(width);
    for (std::size_t c = 0; c < candidates.size(); ++c) {
      const double filtered = neighbourhood_median(width, &neighbours[(candidates[c] - first) * k], k);
      spacing[c] = std::max(spacing[c], filtered / LocalSampling<D>::kHoleToSpacing);
    }
  }
  long isolated = 0;
  for (std::size_t c = 0; c < candidates.size(); ++c) isolated += s.gap[candidates[c]] > factor * spacing[c];
  if (tiles.sum(isolated) == 0) return false;
  for (std::size_t c = 0; c < candidates.size(); ++c) s.spacing[candidates[c]] = spacing[c];
  return true;
}

template bool isolated_points_found<2>(const NearestPointIndex<2>&, const LargeVector<Index>&, bool, double, int, const TileRuns&, LocalSampling<2>&);
template bool isolated_points_found<3>(const NearestPointIndex<3>&, const LargeVector<Index>&, bool, double, int, const TileRuns&, LocalSampling<3>&);

}  // namespace lsr
