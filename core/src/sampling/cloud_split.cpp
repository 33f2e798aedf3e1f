// SPDX-License-Identifier: BSD-3-Clause
/// @file cloud_split.cpp
#include "sampling/cloud_split.h"

#include "sampling/data_preparation.h"
#include "sampling/exact_duplicates.h"
#include "sampling/worker_collectives.h"
#include "sampling/z_order.h"

#include <algorithm>
#include <array>
#include <limits>

namespace lsr::detail {
namespace {

template <int D>
struct Record {
  std::uint64_t key;
  std::size_t input;
  std::array<double, D> x;
  bool operator<(const Record& o) const { return key != o.key ? key < o.key : input < o.input; }
};

template <int D>
Vec<D> vec(const std::array<double, D>& a) {
  Vec<D> v;
  for (int d = 0; d < D; ++d) v[d] = a[std::size_t(d)];
  return v;
}

// One cut of the curve per worker: the keys at regular ranks among every worker's s regular
// samples (parallel sorting by regular sampling). A run then holds a share plus at most about
// n / s points: s = 16 K, a sixteenth of a share.
template <int D>
std::vector<std::uint64_t> cuts_of(const std::vector<Record<D>>& sorted, const TileExchange* x) {
  const std::size_t workers = workers_of(x), s = 16 * workers;
  std::vector<std::uint64_t> samples;
  for (std::size_t j = 0; j < s && !sorted.empty(); ++j) samples.push_back(sorted[j * sorted.size() / s].key);
  std::vector<std::uint64_t> all;
  for (const auto& from : exchange_values(x, std::vector<std::vector<std::uint64_t>>(workers, samples))) all.insert(all.end(), from.begin(), from.end());
  std::sort(all.begin(), all.end());
  std::vector<std::uint64_t> cuts;
  for (std::size_t w = 1; w < workers; ++w) cuts.push_back(all.empty() ? 0 : all[w * all.size() / workers]);
  return cuts;
}

}  // namespace

template <int D>
void require_spanning_over_workers(const Points<D>& points, const TileExchange* x) {
  const std::size_t n = sum_over_workers(x, points.size());
  Vec<D> mean = Vec<D>::Zero();
  for (const auto& p : points) mean += p / double(n);
  std::array<double, D> part{};
  for (int d = 0; d < D; ++d) part[std::size_t(d)] = mean[d];
  mean.setZero();
  for (const auto& each : all_gather(x, part)) mean += vec<D>(each);
  double extent = 0.0;
  for (const auto& p : points) extent = std::max(extent, (p - mean).cwiseAbs().maxCoeff());
  for (const double e : all_gather(x, extent)) extent = std::max(extent, e);
  std::array<double, D * D> c{};
  if (extent > 0.0 && std::isfinite(extent)) {
    for (const auto& p : points) {
      const Vec<D> y = (p - mean) / extent;
      for (int a = 0; a < D; ++a) {
        for (int b = 0; b < D; ++b) c[std::size_t(a * D + b)] += y[a] * y[b];
      }
    }
  }
  Eigen::Matrix<double, D, D> cov = Eigen::Matrix<double, D, D>::Zero();
  for (const auto& each : all_gather(x, c)) {
    for (int a = 0; a < D; ++a) {
      for (int b = 0; b < D; ++b) cov(a, b) += each[std::size_t(a * D + b)];
    }
  }
  require_spread<D>(n, mean, extent, cov);
}

template <int D>
UnitBoxTransform<D> ball_over_workers(const Points<D>& points, std::size_t count, const TileExchange* x, double radius) {
  std::array<double, 2 * D> bounds;
  for (int d = 0; d < D; ++d) {
    bounds[std::size_t(d)] = std::numeric_limits<double>::infinity();
    bounds[std::size_t(D + d)] = -std::numeric_limits<double>::infinity();
  }
  for (const auto& p : points) {
    for (int d = 0; d < D; ++d) {
      bounds[std::size_t(d)] = std::min(bounds[std::size_t(d)], p[d]);
      bounds[std::size_t(D + d)] = std::max(bounds[std::size_t(D + d)], p[d]);
    }
  }
  Vec<D> lo = Vec<D>::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const auto& each : all_gather(x, bounds)) {
    for (int d = 0; d < D; ++d) {
      lo[d] = std::min(lo[d], each[std::size_t(d)]);
      hi[d] = std::max(hi[d], each[std::size_t(D + d)]);
    }
  }
  const UnitBoxTransform<D> box = UnitBoxTransform<D>::fit_bounds(lo, hi, count, 0.0);
  double reach = 0.0;
  for (const auto& p : points) reach = std::max(reach, (p - box.center()).norm());
  for (const double r : all_gather(x, reach)) reach = std::max(reach, r);
  return box.with_ball(reach, radius);
}

template <int D>
SplitCloud<D> split_cloud(const Points<D>& share, const TileExchange* x, double data_radius, UnitBoxTransform<D>& box) {
  const std::size_t workers = workers_of(x), me = worker_of(x);
  SplitCloud<D> out;
  std::size_t input_first = 0;
  const std::vector<std::size_t> shares = all_gather(x, share.size());
  for (std::size_t w = 0; w < workers; ++w) {
    out.input_points += shares[w];
    if (w < me) input_first += shares[w];
  }
  std::vector<Record<D>> records;
  Points<D> finite;
  for (std::size_t i = 0; i < share.size(); ++i) {
    if (!share[i].allFinite()) continue;
    finite.push_back(share[i]);
    records.push_back({0, input_first + i, {}});
  }
  const std::size_t finite_points = sum_over_workers(x, finite.size());
  out.skipped_points = out.input_points - finite_points;
  if (finite_points == 0) require_spread<D>(0, Vec<D>::Zero(), 0.0, Eigen::Matrix<double, D, D>::Zero());
  // Copies change neither the bounds nor the farthest point: the box of the distinct points.
  box = ball_over_workers(finite, finite_points, x, data_radius);
  for (std::size_t i = 0; i < finite.size(); ++i) {
    records[i].key = morton_key<D>(box.to_unit(finite[i]));
    for (int d = 0; d < D; ++d) records[i].x[std::size_t(d)] = finite[i][d];
  }
  Points<D>().swap(finite);
  std::sort(records.begin(), records.end());
  // Each worker's run of the curve; equal points have equal keys, so their copies meet.
  const std::vector<std::uint64_t> cuts = cuts_of(records, x);
  std::vector<std::vector<Record<D>>> out_records(workers);
  for (const Record<D>& r : records) out_records[std::size_t(std::upper_bound(cuts.begin(), cuts.end(), r.key) - cuts.begin())].push_back(r);
  std::vector<Record<D>>().swap(records);
  for (auto& from : exchange_values(x, out_records)) {
    records.insert(records.end(), from.begin(), from.end());
    std::vector<Record<D>>().swap(from);
  }
  out_records.clear();
  std::sort(records.begin(), records.end());
  // Each point once, in the order of its first copy (the least input index), as
  // distinct_finite_points gives them.
  for (std::size_t begin = 0, end = 0; begin < records.size(); begin = end) {
    for (end = begin + 1; end < records.size() && records[end].key == records[begin].key; ++end) {
    }
    Points<D> run;
    for (std::size_t i = begin; i < end; ++i) run.push_back(vec<D>(records[i].x));
    for (const Vec<D>& p : merge_exact_duplicates(run).points) out.points.push_back(p);
  }
  const std::vector<std::size_t> runs = all_gather(x, out.points.size());
  for (std::size_t w = 0; w < workers; ++w) {
    out.global_size += runs[w];
    if (w < me) out.global_first += runs[w];
  }
  out.duplicate_points = finite_points - out.global_size;
  require_spanning_over_workers(out.points, x);
  return out;
}

template SplitCloud<3> split_cloud<3>(const Points<3>&, const TileExchange*, double, UnitBoxTransform<3>&);
template void require_spanning_over_workers<3>(const Points<3>&, const TileExchange*);
template UnitBoxTransform<3> ball_over_workers<3>(const Points<3>&, std::size_t, const TileExchange*, double);

}  // namespace lsr::detail
