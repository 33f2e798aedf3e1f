// SPDX-License-Identifier: BSD-3-Clause
/// @file cloud_halo.cpp
#include "sampling/cloud_halo.h"

#include "geometry/nearest_point_index.h"

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

}  // namespace

template <int D>
HaloQueries<D> own_neighbourhoods(const Points<D>& own, int k, double factor, int threads, const Progress& progress) {
  HaloQueries<D> q{own, std::vector<double>(own.size(), std::numeric_limits<double>::infinity())};
  if (own.size() <= std::size_t(k)) return q;
  const NearestPointIndex<D> index(own);
  for (std::size_t begin = 0; begin < own.size(); begin += std::size_t(1) << 16) {
    progress.update("sampling", -1.0);
    const std::size_t end = std::min(own.size(), begin + (std::size_t(1) << 16));
    LargeVector<Index> nearest;
    index.query_k(Points<D>(own.begin() + long(begin), own.begin() + long(end)), k, nearest, threads);
    for (std::size_t i = begin; i < end; ++i) {
      const double r = (own[std::size_t(nearest[(i - begin) * std::size_t(k) + std::size_t(k - 1)])] - own[i]).norm();
      q.reach[i] = factor * r * (1.0 + 1e-9) + 1e-300;  // round-off: a bound, never short
    }
  }
  return q;
}

template <int D>
HaloCloud<D> with_halo(const Points<D>& own, std::size_t global_first, std::size_t global_size, const TileExchange* exchange,
                       const std::function<HaloQueries<D>()>& queries) {
  const std::size_t workers = workers_of(exchange), me = worker_of(exchange);
  HaloCloud<D> out;
  CloudHalo& h = out.halo;
  h.exchange = exchange;
  h.global_first = global_first;
  h.global_size = global_size;
  h.send.resize(workers);
  h.from.assign(workers + 1, 0);
  for (std::size_t u = 0; u < workers; ++u) h.from[u + 1] = h.from[u] + (u == me ? own.size() : 0);
  h.first = h.from[me];
  h.end = h.from[me + 1];
  if (workers == 1) {
    out.points = own;
    return out;
  }
  // The box of each block of own points (`tight`), and of what each block of queries reaches
  // (`wide`, to every worker).
  const HaloQueries<D> q = queries();
  const auto boxes = [](const Points<D>& x, const std::vector<double>* reach) {
    std::vector<Box<D>> out;
    for (std::size_t begin = 0; begin < x.size(); begin += kBoxPoints) {
      Box<D> b;
      b.lo.fill(std::numeric_limits<double>::infinity());
      b.hi.fill(-std::numeric_limits<double>::infinity());
      for (std::size_t i = begin; i < std::min(x.size(), begin + kBoxPoints); ++i) {
        const double r = reach ? (*reach)[i] : 0.0;
        for (int d = 0; d < D; ++d) {
          b.lo[std::size_t(d)] = std::min(b.lo[std::size_t(d)], x[i][d] - r);
          b.hi[std::size_t(d)] = std::max(b.hi[std::size_t(d)], x[i][d] + r);
        }
      }
      out.push_back(b);
    }
    return out;
  };
  const std::vector<Box<D>> tight = boxes(own, nullptr);
  const std::vector<std::vector<Box<D>>> reaches = exchange_values(exchange, std::vector<std::vector<Box<D>>>(workers, boxes(q.at, &q.reach)));
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
  for (std::size_t u = 0; u < workers; ++u) {
    h.from[u + 1] = h.from[u] + (u == me ? own.size() : halo[u].size());
    if (u == me) {
      out.points.insert(out.points.end(), own.begin(), own.end());
    } else {
      out.points.insert(out.points.end(), halo[u].begin(), halo[u].end());
    }
  }
  h.first = h.from[me];
  h.end = h.from[me + 1];
  for (std::size_t v = 0; v < workers; ++v) {
    for (std::size_t& i : h.send[v]) i += h.first;
  }
  return out;
}

template HaloQueries<2> own_neighbourhoods<2>(const Points<2>&, int, double, int, const Progress&);
template HaloQueries<3> own_neighbourhoods<3>(const Points<3>&, int, double, int, const Progress&);
template HaloCloud<2> with_halo<2>(const Points<2>&, std::size_t, std::size_t, const TileExchange*, const std::function<HaloQueries<2>()>&);
template HaloCloud<3> with_halo<3>(const Points<3>&, std::size_t, std::size_t, const TileExchange*, const std::function<HaloQueries<3>()>&);

}  // namespace lsr
