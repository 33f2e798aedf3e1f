// SPDX-License-Identifier: BSD-3-Clause
/// @file sampled_data.cpp
#include "sampling/sampled_data.h"

#include "limits/option_checks.h"
#include "start/start_fields.h"

namespace lsr::detail {

template <int D>
SampledData<D> sampled_data(const Points<D>& input, const ReconstructionOptions& o, HeightFieldsAt fields, const Progress& progress,
                            ReconstructionResult<D>& r, StageClock& clock) {
  DataPoints<D> in = distinct_finite_points(input);
  r.skipped_points = input.size() - in.finite.size();
  r.duplicate_points = in.finite.size() - in.points.size();
  require_spanning(in.points);
  auto box = UnitBoxTransform<D>::fit_ball(in.points, kDataRadius);
  if constexpr (D == 3) in_z_order(box, in.points, in.kept);
  NearestPointIndex<D> data(box.to_unit(in.points));
  clock.end("unit box");
  progress.update("sampling", -1.0);
  const SamplingTiles tiles{o.limits.tiles, nullptr};
  LocalSampling<D> sampling =
      estimate_local_sampling(data, o.limits.threads, fields, progress, tiles, o.sampling.scan_lines, o.sampling.outlier_factor);
  if (sampling.stopped_at_isolated) {
    // The box and every scale follow the data without them.
    drop_isolated(sampling, o.sampling.outlier_factor, in.points, in.kept);
    r.outlier_points = input.size() - r.skipped_points - r.duplicate_points - in.points.size();
    require_spanning(in.points);
    box = UnitBoxTransform<D>::fit_ball(in.points, kDataRadius);
    data = NearestPointIndex<D>(box.to_unit(in.points));
    sampling = estimate_local_sampling(data, o.limits.threads, fields, progress, tiles, o.sampling.scan_lines);
  }
  const double spacing = median(sampling.spacing), noise = median(sampling.noise);
  std::vector<double> point_scale = local_scales(sampling);
  const ReconstructionOptions unit = in_unit_box(o, box.scale());
  LeftOut<D> left_out =
      keep_mesh_resolution(data, sampling, point_scale, local_mesh_sizes<D>(point_scale, unit.mesh.h_min, unit.mesh.max_resolution), o.limits.threads);
  return {std::move(in), box, std::move(data), std::move(sampling), std::move(point_scale), std::move(left_out), spacing, noise};
}

template SampledData<2> sampled_data<2>(const Points<2>&, const ReconstructionOptions&, HeightFieldsAt, const Progress&, ReconstructionResult<2>&, StageClock&);
template SampledData<3> sampled_data<3>(const Points<3>&, const ReconstructionOptions&, HeightFieldsAt, const Progress&, ReconstructionResult<3>&, StageClock&);

}  // namespace lsr::detail
