// SPDX-License-Identifier: BSD-3-Clause
/// @file shared_sampled_data.cpp
/// @brief sampled_data shared among workers: split_cloud, with_halo, estimate_local_sampling on
/// the run and its halo, the isolated points dropped where they lie, and every run's points and
/// values gathered to worker 0 in the cloud's order.
#include "sampling/cloud_halo.h"
#include "sampling/cloud_split.h"
#include "sampling/sampled_data.h"
#include "sampling/worker_collectives.h"
#include "start/start_fields.h"

#include <algorithm>

namespace lsr::detail {
namespace {

// This worker's values of its own points [first, end) to worker 0, which gets them all in order.
template <class T, class A>
void gather_run(const TileExchange* x, std::vector<T, A>& values, std::size_t first, std::size_t end) {
  std::vector<std::vector<T>> out(workers_of(x));
  out[0].assign(values.begin() + long(first), values.begin() + long(end));
  values.clear();
  for (auto& from : exchange_values(x, out)) values.insert(values.end(), from.begin(), from.end());
}

// The finite input indices and each one's first copy, from the points' and those left out.
template <int D>
void with_left_out(DataPoints<D>& in, std::vector<std::pair<std::size_t, std::size_t>> left_out) {
  for (const std::size_t i : in.kept) left_out.emplace_back(i, i);
  std::sort(left_out.begin(), left_out.end());
  for (const auto& [input, first] : left_out) {
    in.finite.push_back(input);
    in.first.push_back(first);
  }
}

}  // namespace

template <int D>
std::optional<SampledData<D>> shared_sampled_data(const Points<D>& share, const ReconstructionOptions& o, HeightFieldsAt fields, const Progress& progress,
                                   ReconstructionResult<D>& r, StageClock& clock) {
  const TileExchange* x = o.limits.exchange.get();
  UnitBoxTransform<D> box;
  SplitCloud<D> run = split_cloud(share, x, kDataRadius, box);
  r.input_points = run.input_points;
  r.skipped_points = run.skipped_points;
  r.duplicate_points = run.duplicate_points;
  clock.end("unit box");
  progress.update("sampling", -1.0);
  LocalSampling<D> sampling;
  CloudHalo halo;
  for (int pass = 0;; ++pass) {
    HaloCloud<D> local = with_halo(box.to_unit(run.points), run.global_first, run.global_size, x, o.limits.threads, progress);
    halo = std::move(local.halo);
    const NearestPointIndex<D> index(std::move(local.points));
    sampling = estimate_local_sampling(index, o.limits.threads, fields, progress, {o.limits.tiles, x, &halo}, o.sampling.scan_lines);
    if (pass == 1 || o.sampling.outlier_factor <= 0.0) break;
    // drop_isolated on this worker's points; the box and every scale follow the data without them.
    std::size_t n = 0;
    for (std::size_t i = 0; i < run.points.size(); ++i) {
      const std::size_t at = halo.first + i;
      if (sampling.gap[at] > o.sampling.outlier_factor * sampling.spacing[at]) {
        run.left_out.emplace_back(run.kept[i], run.kept[i]);
        continue;
      }
      run.points[n] = run.points[i];
      run.kept[n++] = run.kept[i];
    }
    const std::size_t dropped = sum_over_workers(x, run.points.size() - n);
    if (dropped == 0) break;
    run.points.resize(n);
    run.kept.resize(n);
    const std::vector<std::size_t> runs = all_gather(x, n);
    run.global_first = 0;
    for (std::size_t w = 0; w < worker_of(x); ++w) run.global_first += runs[w];
    run.global_size -= dropped;
    r.outlier_points = dropped;
    require_spanning_over_workers(run.points, x);
    box = ball_over_workers(run.points, run.global_size, x, kDataRadius);
  }
  // Worker 0 gets every run's points and values, in the cloud's order.
  const std::size_t first = halo.first, end = halo.end;
  gather_run(x, sampling.spacing, first, end);
  gather_run(x, sampling.noise, first, end);
  gather_run(x, sampling.normals, first, end);
  gather_run(x, sampling.gap, first, end);
  if (!sampling.rim.empty()) gather_run(x, sampling.rim, first, end);
  if (!sampling.height_fields.empty()) gather_run(x, sampling.height_fields, first, end);
  gather_run(x, run.points, 0, run.points.size());
  gather_run(x, run.kept, 0, run.kept.size());
  gather_run(x, run.left_out, 0, run.left_out.size());
  if (worker_of(x) != 0) return std::nullopt;
  DataPoints<D> in;
  in.points = std::move(run.points);
  in.kept = std::move(run.kept);
  with_left_out(in, std::move(run.left_out));
  NearestPointIndex<D> data(box.to_unit(in.points));
  return SampledData<D>{std::move(in), box, std::move(data), std::move(sampling)};
}

template std::optional<SampledData<3>> shared_sampled_data<3>(const Points<3>&, const ReconstructionOptions&, HeightFieldsAt, const Progress&,
                                               ReconstructionResult<3>&, StageClock&);

}  // namespace lsr::detail
