// SPDX-License-Identifier: BSD-3-Clause
/// @file shared_sampled_data.cpp
/// @brief sampled_data shared among workers: split_cloud, with_halo, estimate_local_sampling on
/// the run and its halo, the isolated points dropped where they lie, keep_mesh_resolution on
/// each run, and every run's sample gathered to worker 0 in the cloud's order.
#include "limits/option_checks.h"
#include "sampling/cloud_halo.h"
#include "sampling/cloud_split.h"
#include "sampling/mesh_resolution_data.h"
#include "sampling/sampled_data.h"
#include "sampling/worker_collectives.h"
#include "start/start_fields.h"

#include <algorithm>

namespace lsr::detail {
namespace {

// This worker's values of its own points [first, end) to worker 0, or to every worker, which
// gets them all in order.
template <class T, class A>
void gather_run(const TileExchange* x, std::vector<T, A>& values, std::size_t first, std::size_t end, bool everyone) {
  std::vector<std::vector<T>> out(everyone ? workers_of(x) : 1);
  for (auto& to : out) to.assign(values.begin() + long(first), values.begin() + long(end));
  out.resize(workers_of(x));
  values.clear();
  for (auto& from : exchange_values(x, out)) values.insert(values.end(), from.begin(), from.end());
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
  std::optional<NearestPointIndex<D>> index;
  for (int pass = 0;; ++pass) {
    const Points<D> own = box.to_unit(run.points);
    HaloCloud<D> local = with_halo<D>(own, run.global_first, run.global_size, x, [&] {
      return own_neighbourhoods(own, LocalSampling<D>::kHoleNeighbours, 1.5, o.limits.threads, progress);
    });
    halo = std::move(local.halo);
    index.emplace(std::move(local.points));
    sampling = estimate_local_sampling(*index, o.limits.threads, fields, progress, {std::max(1, o.limits.tiles / int(workers_of(x))), &halo},
                                       o.sampling.scan_lines, pass == 0 ? o.sampling.outlier_factor : 0.0);
    if (!sampling.stopped_at_isolated) break;
    // drop_isolated on this worker's points; the box and every scale follow the data without them.
    std::size_t n = 0;
    for (std::size_t i = 0; i < run.points.size(); ++i) {
      const std::size_t at = halo.first + i;
      if (!(sampling.gap[at] > o.sampling.outlier_factor * sampling.spacing[at])) run.points[n++] = run.points[i];
    }
    const std::size_t dropped = sum_over_workers(x, run.points.size() - n);
    run.points.resize(n);
    const std::vector<std::size_t> runs = all_gather(x, n);
    run.global_first = 0;
    for (std::size_t w = 0; w < worker_of(x); ++w) run.global_first += runs[w];
    run.global_size -= dropped;
    r.outlier_points = dropped;
    require_spanning_over_workers(run.points, x);
    box = ball_over_workers(run.points, run.global_size, x, kDataRadius);
  }
  Points<D>().swap(run.points);
  // 3. The sample at the mesh's size, of each run; the medians of every point's.
  const std::size_t first = halo.first, end = halo.end;
  const double spacing = median_over_workers(x, sampling.spacing.data() + first, end - first);
  const double noise = median_over_workers(x, sampling.noise.data() + first, end - first);
  std::vector<double> point_scale = local_scales(sampling);
  const ReconstructionOptions unit = in_unit_box(o, box.scale());
  LeftOut<D> left_out = keep_mesh_resolution(*index, sampling, point_scale,
                                             local_mesh_sizes<D>(point_scale, unit.mesh.h_min, unit.mesh.max_resolution), o.limits.threads, &halo);
  // Worker 0 gets every run's sample, in the cloud's order: the run's values, thinned to its
  // kept points (all its own if the cloud was not thinned; none, maybe, if it was). Every
  // worker does when they share the front's tiles too (tiles/tile_outputs.h).
  const bool everyone = o.limits.solve_tiles > 1;
  const bool thinned = point_scale.size() != index->points().size();
  const std::size_t from = thinned ? 0 : first, to = thinned ? point_scale.size() : end;
  Points<D> points;
  for (std::size_t i = from; i < to; ++i) points.push_back(index->points()[thinned ? std::size_t(left_out.kept[i]) : i]);
  index.reset();
  gather_run(x, points, 0, points.size(), everyone);
  gather_run(x, sampling.spacing, from, to, everyone);
  gather_run(x, sampling.noise, from, to, everyone);
  gather_run(x, sampling.normals, from, to, everyone);
  gather_run(x, sampling.gap, from, to, everyone);
  // A run that kept no point has them empty either way.
  if (sum_over_workers(x, std::size_t(!sampling.rim.empty())) > 0) gather_run(x, sampling.rim, from, to, everyone);
  if (sum_over_workers(x, std::size_t(!sampling.height_fields.empty())) > 0) gather_run(x, sampling.height_fields, from, to, everyone);
  gather_run(x, point_scale, from, to, everyone);
  gather_run(x, left_out.represented, 0, left_out.represented.size(), everyone);  // empty where not thinned
  if (worker_of(x) != 0 && !everyone) return std::nullopt;
  LeftOut<D> sample;
  sample.represented = std::move(left_out.represented);
  return SampledData<D>{{}, box, NearestPointIndex<D>(std::move(points)), std::move(sampling), std::move(point_scale), std::move(sample), spacing, noise};
}

template std::optional<SampledData<3>> shared_sampled_data<3>(const Points<3>&, const ReconstructionOptions&, HeightFieldsAt, const Progress&,
                                               ReconstructionResult<3>&, StageClock&);

}  // namespace lsr::detail
