// SPDX-License-Identifier: BSD-3-Clause
/// @file sampled_data.h
/// @brief Stages 1 to 3 of the pipeline: the data normalised (distinct finite points in the
/// unit box, along a Z-order curve), its local sampling, isolated points left out, and the
/// sample at the mesh's size that the stages after read; in one process, or shared among
/// workers (lsrecon/core/tile_exchange.h), each holding a run of the cloud and its halo, with
/// worker 0 receiving the sample.
#pragma once

#include "geometry/nearest_point_index.h"
#include "lsrecon/core/progress.h"
#include "lsrecon/core/reconstruction_options.h"
#include "lsrecon/core/reconstruction_result.h"
#include "sampling/data_preparation.h"
#include "sampling/local_sampling.h"
#include "sampling/mesh_resolution_data.h"
#include "sampling/unit_box_transform.h"
#include "stage_clock.h"

#include <optional>

namespace lsr::detail {

template <int D>
struct SampledData {
  DataPoints<D> in;              ///< every point (empty when shared among workers)
  UnitBoxTransform<D> box;
  NearestPointIndex<D> data;     ///< the sample at the mesh's size (keep_mesh_resolution), unit box
  LocalSampling<D> sampling;     ///< of data's points
  std::vector<double> point_scale;  ///< of data's points (local_scales)
  LeftOut<D> left_out;           ///< when shared among workers: represented only
  double spacing = 0.0, noise = 0.0;  ///< the medians over every point (unit box)
};

/// @brief The points' sampling in one process (`limits.exchange` null or one worker). Sets r's
/// point counts.
template <int D>
SampledData<D> sampled_data(const Points<D>& input, const ReconstructionOptions& o, HeightFieldsAt fields, const Progress& progress,
                            ReconstructionResult<D>& r, StageClock& clock);

/// @brief The same shared among o.limits.exchange's workers, each passing its share of the
/// input; worker 0 ends with what sampled_data gives for the whole input, to the bit, the others
/// with nothing (their counts in r only). 3D.
template <int D>
std::optional<SampledData<D>> shared_sampled_data(const Points<D>& share, const ReconstructionOptions& o, HeightFieldsAt fields, const Progress& progress,
                                   ReconstructionResult<D>& r, StageClock& clock);

}  // namespace lsr::detail
