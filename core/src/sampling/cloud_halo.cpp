// SPDX-License-Identifier: BSD-3-Clause
/// @file cloud_halo.cpp
#include "sampling/cloud_halo.h"

#include "geometry/nearest_point_index.h"
#include "sampling/local_sampling.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace lsr {
namespace {

// Consecutive own points per box: compact pieces of space along the Z-order curve.
constexpr std::size_t kBoxPoints = 4096;

template <int D>
struct Box {
  std::array<double, D> lo, hi;
  bool overlaps(const Box& b) const {
    for (int d = 0; d < D; ++d) {
      if (b.lo[std::size_t(d)] > hi[std::size_t(d)] || b.hi[std::size_t(d)] < lo[std::size_t(d)]) return false;
    }
    return true;
  }
  bool holds(const Vec<D>& x) const {
    for (int d = 0; d < D; ++d) {
      if (x[d] < lo[std::size_t(d)] || x[d] > hi[std::size_t(d)]) return false;
    }
    return true;
  }
};

// The reach of each own point: 1.5 times its 32nd nearest among own points (a bound on the
// distance among all), infinite when there are too few own points to bound it.
template <int D>
std::vector<double> reach_of(const Points<D>& own, int threads, const Progress& progress) {
  constexpr int k = LocalSampling<D>::kHoleNeighbours;
  std::vector<double> reach(own.size(), std::numeric_limits<double>::infinity());
  if (own.size() <= std::size_t(k)) return reach;
  const NearestPointIndex<D> index(own);
  for (std::size_t begin = 0; begin < own.size(); begin += std::size_t(1) << 16) {
    progress.update("sampling", -1.0);
    const std::size_t end = std::min(own.size(), begin + (std::size_t(1) << 16));
    LargeVector<Index> nearest;
    index.query_k(Points<D>(own.begin() + long(begin), own.begin() + long(end)), k, nearest, threads);
    for (std::size_t i = begin; i < end; ++i) {
      const double r = (own[std::size_t(nearest[(i - begin) * k + k - 1])] - own[i]).norm();
      reach[i] = 1.5 * r * (1.0 + 1e-9) + 1e-300;  // round-off: a bound, never short
    }
  }
  return reach;
}

}  // namespace

template <int D>
HaloCloud<D> with_halo(const Points<D>& own, std::size_t global_first, std::size_t global_size, const TileExchange* exchange,
                       int threads, const Progress& progress) {
  const std::size_t workers = workers_of(exchange), me = worker_of(exchange);
  const std::vector<double> reach = reach_of(own, threads, progress);
  // Each block's box (`tight`) and the box its points' reach covers (`wide`, to every worker).
  std::vector<Box<D>> tight, wide;
  for (std::size_t begin = 0; begin < own.size(); begin += kBoxPoints) {
    Box<D> t, w;
    t.lo.fill(std::numeric_limits<double>::infinity());
    t.hi.fill(-std::numeric_limits<double>::infinity());
    w = t;
    for (std::size_t i = begin; i < std::min(own.size(), begin + kBoxPoints); ++i) {
      for (int d = 0; d < D; ++d) {
        const std::size_t a = std::size_t(d);
        t.lo[a] = std::min(t.lo[a], own[i][d]);
        t.hi[a] = std::max(t.hi[a], own[i][d]);
        w.lo[a] = std::min(w.lo[a], own[i][d] - reach[i]);
        w.hi[a] = std::max(w.hi[a], own[i][d] + reach[i]);
      }
    }
    tight.push_back(t);
    wide.push_back(w);
  }
  const std::vector<std::vector<Box<D>>> reaches = exchange_values(exchange, std::vector<std::vector<Box<D>>>(workers, wide));
  HaloCloud<D> out;
  CloudHalo& h = out.halo;
  h.exchange = exchange;
  h.global_first = global_first;
  h.global_size = global_size;
  h.send.resize(workers);
  std::vector<std::vector<Vec<D>>> points(workers);
  for (std::size_t v = 0; v < workers; ++v) {
    if (v == me) continue;
    for (std::size_t b = 0; b < tight.size(); ++b) {
      std::vector<const Box<D>*> near;
      for (const Box<D>& r : reaches[v]) {
        if (r.overlaps(tight[b])) near.push_back(&r);
      }
      if (near.empty()) continue;
      for (std::size_t i = b * kBoxPoints; i < std::min(own.size(), (b + 1) * kBoxPoints); ++i) {
        if (std::any_of(near.begin(), near.end(), [&](const Box<D>* r) { return r->holds(own[i]); })) {
          h.send[v].push_back(i);
          points[v].push_back(own[i]);
        }
      }
    }
  }
  const std::vector<std::vector<Vec<D>>> halo = exchange_values(exchange, points);
  h.from.assign(workers + 1, 0);
  for (std::size_t u = 0; u < workers; ++u) {
    const std::size_t count = u == me ? own.size() : halo[u].size();
    h.from[u + 1] = h.from[u] + count;
    if (u == me) {
      h.first = h.from[u];
      h.end = h.from[u + 1];
      out.points.insert(out.points.end(), own.begin(), own.end());
    } else {
      out.points.insert(out.points.end(), halo[u].begin(), halo[u].end());
    }
  }
  for (std::size_t v = 0; v < workers; ++v) {
    for (std::size_t& i : h.send[v]) i += h.first;
  }
  return out;
}

template HaloCloud<2> with_halo<2>(const Points<2>&, std::size_t, std::size_t, const TileExchange*, int, const Progress&);
template HaloCloud<3> with_halo<3>(const Points<3>&, std::size_t, std::size_t, const TileExchange*, int, const Progress&);

}  // namespace lsr
