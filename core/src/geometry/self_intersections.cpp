// SPDX-License-Identifier: BSD-3-Clause
/// @file self_intersections.cpp
#include "geometry/self_intersections.h"

#include "geometry/facet_intersection.h"
#include "thread_count.h"

#include <omp.h>

#include <algorithm>
#include <numeric>

namespace lsr::detail {
namespace {

// The facets whose boxes meet a query box.
template <int D>
struct BoxQuery {
  using Box = Eigen::AlignedBox<double, D>;
  const Box& query;
  const std::vector<Box>& boxes;
  std::vector<Index>& found;

  bool intersectVolume(const Box& volume) const { return volume.intersects(query); }
  bool intersectObject(Index f) const {
    if (boxes[std::size_t(f)].intersects(query)) found.push_back(f);
    return false;  // every one
  }
};

}  // namespace

template <int D>
SelfIntersections<D>::SelfIntersections(const std::vector<Facet>& facets, const Points<D>& from, const Points<D>& to)
    : facets_(facets), boxes_(facets.size()) {
  for (std::size_t f = 0; f < facets.size(); ++f) {
    Box& box = boxes_[f];
    for (Index v : facets[f]) {
      box.extend(from[std::size_t(v)]);
      if (!to.empty()) box.extend(to[std::size_t(v)]);
    }
  }
  std::vector<Index> ids(facets.size());
  std::iota(ids.begin(), ids.end(), Index(0));
  tree_.init(ids.begin(), ids.end(), boxes_.begin(), boxes_.end());
}

template <int D>
std::vector<typename SelfIntersections<D>::Pair> SelfIntersections<D>::pairs(const Points<D>& x, const std::vector<char>& among,
                                                                             int threads) const {
  const std::int64_t n = std::int64_t(facets_.size());
  std::vector<std::vector<Pair>> per_thread(std::size_t(thread_count(threads)));
#pragma omp parallel num_threads(int(per_thread.size()))
  {
    std::vector<Pair>& mine = per_thread[std::size_t(omp_get_thread_num())];
    std::vector<Index> found;
#pragma omp for schedule(dynamic, 256)
    for (std::int64_t i = 0; i < n; ++i) {
      if (!among.empty() && !among[std::size_t(i)]) continue;
      found.clear();
      BoxQuery<D> query{boxes_[std::size_t(i)], boxes_, found};
      Eigen::BVIntersect(tree_, query);
      for (Index j : found) {
        // Each pair once: from its smaller facet, or from the one `among` when only one is.
        const bool j_among = among.empty() || among[std::size_t(j)];
        if (j == Index(i) || (j < Index(i) && j_among)) continue;
        if (facets_intersect(x, facets_[std::size_t(i)], facets_[std::size_t(j)])) {
          mine.emplace_back(std::min(Index(i), j), std::max(Index(i), j));
        }
      }
    }
  }
  std::vector<Pair> all;
  for (const auto& p : per_thread) all.insert(all.end(), p.begin(), p.end());
  std::sort(all.begin(), all.end());
  return all;
}

std::size_t count_self_intersections(const Points<2>& x, const std::vector<std::array<Index, 2>>& facets, int threads) {
  return SelfIntersections<2>(facets, x).pairs(x, {}, threads).size();
}

std::size_t count_self_intersections(const Points<3>& x, const std::vector<std::array<Index, 3>>& facets, int threads) {
  return SelfIntersections<3>(facets, x).pairs(x, {}, threads).size();
}

template class SelfIntersections<2>;
template class SelfIntersections<3>;

}  // namespace lsr::detail
