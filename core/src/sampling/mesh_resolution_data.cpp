// SPDX-License-Identifier: BSD-3-Clause
/// @file mesh_resolution_data.cpp
#include "sampling/mesh_resolution_data.h"

#include "sampling/mesh_resolution_sample.h"

#include <algorithm>
#include <limits>
#include <optional>

namespace lsr::detail {
namespace {

// Points queried at a time: bounds the copies at 10M points.
constexpr std::size_t kBlock = std::size_t(1) << 16;

template <typename Values>
Values kept_of(const Values& all, const std::vector<Index>& kept) {
  Values out;
  if (all.empty()) return out;
  out.reserve(kept.size());
  for (Index i : kept) out.push_back(all[std::size_t(i)]);
  return out;
}

// The kept points' index (a worker's with the others' kept points as near as its own nearest),
// and for every point left out its nearest kept point (out.nearest without a halo) and what each
// kept point stands for (out.represented). Returns, in 2D, the points left out farther than
// their mesh size from every kept point.
template <int D>
std::vector<Index> stand_with_nearest(const NearestPointIndex<D>& data, const std::vector<double>& mesh_size, const std::vector<char>& is_kept,
                                      LeftOut<D>& out, std::optional<NearestPointIndex<D>>& kept_index, int threads,
                                      const CloudHalo* halo) {
  const std::size_t first = halo ? halo->first : 0, end = halo ? halo->end : is_kept.size();
  const Points<D> own_kept = kept_of(data.points(), out.kept);
  HaloCloud<D> local = with_halo<D>(own_kept, 0, 0, halo ? halo->exchange : nullptr, [&] {
    HaloQueries<D> q;
    for (std::size_t i = first; i < end; ++i) {
      if (!is_kept[i]) q.at.push_back(data.points()[i]);
    }
    if (own_kept.empty()) {
      q.reach.assign(q.at.size(), std::numeric_limits<double>::infinity());
    } else {
      NearestPointIndex<D>(own_kept).query(q.at, q.reach, nullptr, threads);
      for (double& r : q.reach) r = r * (1.0 + 1e-9) + 1e-300;
    }
    return q;
  });
  kept_index.emplace(std::move(local.points));
  if (!halo) out.nearest.assign(is_kept.size(), 0);
  std::vector<Index> represented(kept_index->points().size(), 0);
  for (std::size_t j = 0; j < out.kept.size(); ++j) {
    represented[local.halo.first + j] = 1;
    if (!halo) out.nearest[std::size_t(out.kept[j])] = Index(j);
  }
  std::vector<Index> far;
  std::vector<std::size_t> left;
  Points<D> at;
  std::vector<double> distance;
  std::vector<Index> nearest;
  for (std::size_t begin = first; begin < end; begin += kBlock) {
    const std::size_t end_block = std::min(end, begin + kBlock);
    left.clear();
    at.clear();
    for (std::size_t i = begin; i < end_block; ++i) {
      if (is_kept[i]) continue;
      left.push_back(i);
      at.push_back(data.points()[i]);
    }
    kept_index->query(at, distance, &nearest, threads);
    for (std::size_t q = 0; q < left.size(); ++q) {
      represented[std::size_t(nearest[q])] += 1;
      if (!halo) out.nearest[left[q]] = nearest[q];
      if (D == 2 && distance[q] > mesh_size[left[q]]) far.push_back(Index(left[q]));
    }
  }
  local.halo.add_to_owners(represented);
  out.represented.assign(represented.begin() + long(local.halo.first), represented.begin() + long(local.halo.end));
  return far;
}

}  // namespace

template <int D>
LeftOut<D> keep_mesh_resolution(NearestPointIndex<D>& data, LocalSampling<D>& sampling, std::vector<double>& point_scale,
                                const std::vector<double>& mesh_size, int threads, const CloudHalo* halo) {
  const std::size_t first = halo ? halo->first : 0, end = halo ? halo->end : point_scale.size();
  const TileExchange* x = halo ? halo->exchange : nullptr;
  std::vector<double> raised = point_scale;
  for (std::size_t i = first; i < end; ++i) raised[i] = std::max(raised[i], mesh_size[i]);
  LeftOut<D> out;
  out.kept = mesh_resolution_sample<D>(data, point_scale, raised, sampling.scan_lines, threads, halo);
  // Every rim point stays (a line's worth): the discs over holes and the closure of open sides
  // stand on them.
  std::vector<char> is_kept(point_scale.size(), 0);
  for (const Index j : out.kept) is_kept[std::size_t(j)] = 1;
  for (std::size_t i = first; i < end; ++i) is_kept[i] = is_kept[i] || (!sampling.rim.empty() && sampling.rim[i]);
  const auto kept_list = [&] {
    out.kept.clear();
    for (std::size_t i = first; i < end; ++i) {
      if (is_kept[i]) out.kept.push_back(Index(i));
    }
  };
  kept_list();
  if (sum_over_workers(x, out.kept.size()) == (halo ? halo->global_size : point_scale.size())) return {};
  // Each point left out stands with its nearest kept point. On a curve, within its mesh size:
  // there the random choice's gaps are exponential, one in 55 over the 4 sizes through which the
  // tagged start's flood passes, so the points left out farther than their size come back. On a
  // surface, holes that wide are e^(-4 pi) rare, and the points farther than a size are mostly
  // the noise's and the other views'.
  std::optional<NearestPointIndex<D>> kept;
  const std::vector<Index> far = stand_with_nearest(data, raised, is_kept, out, kept, threads, halo);
  if (sum_over_workers(x, far.size()) > 0) {
    for (const Index i : far) is_kept[std::size_t(i)] = 1;
    kept_list();
    stand_with_nearest(data, raised, is_kept, out, kept, threads, halo);
  }
  if (halo) {
    sampling.normals = kept_of(sampling.normals, out.kept);
  } else {
    data = std::move(*kept);
    out.normals = std::move(sampling.normals);
    sampling.normals = kept_of(out.normals, out.kept);
  }
  sampling.spacing = kept_of(sampling.spacing, out.kept);
  sampling.noise = kept_of(sampling.noise, out.kept);
  sampling.height_fields = kept_of(sampling.height_fields, out.kept);
  sampling.gap = kept_of(sampling.gap, out.kept);
  sampling.rim = kept_of(sampling.rim, out.kept);
  point_scale = kept_of(point_scale, out.kept);
  return out;
}

template <int D>
Points<D> every_point_normals(const LeftOut<D>& out, Points<D> oriented) {
  if (out.kept.empty()) return oriented;
  Points<D> normals = out.normals;
  for (std::size_t i = 0; i < normals.size(); ++i) {
    const Vec<D>& to = oriented[std::size_t(out.nearest[i])];
    if (normals[i].dot(to) < 0.0) normals[i] = -normals[i];
  }
  for (std::size_t j = 0; j < out.kept.size(); ++j) normals[std::size_t(out.kept[j])] = oriented[j];
  return normals;
}

template LeftOut<2> keep_mesh_resolution<2>(NearestPointIndex<2>&, LocalSampling<2>&, std::vector<double>&, const std::vector<double>&, int,
                                             const CloudHalo*);
template LeftOut<3> keep_mesh_resolution<3>(NearestPointIndex<3>&, LocalSampling<3>&, std::vector<double>&, const std::vector<double>&, int,
                                             const CloudHalo*);
template Points<2> every_point_normals<2>(const LeftOut<2>&, Points<2>);
template Points<3> every_point_normals<3>(const LeftOut<3>&, Points<3>);

}  // namespace lsr::detail
