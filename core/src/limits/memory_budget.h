// SPDX-License-Identifier: BSD-3-Clause
/// @file memory_budget.h
/// @brief How many mesh vertices fit in the memory budget beside the points.
#pragma once

#include "lsrecon/core/level_set_reconstruction.h"
#include "lsrecon/core/types.h"

#include <string>

namespace lsr::detail {

// Peak memory per input point and per mesh vertex, calibrated and rounded up
// (docs/calibration.md). The sampling's peak is over before the mesh is built. From the mesh on,
// a run holds the sample at the mesh's size (mesh_resolution_data.h) at kBytesPerPoint a point,
// each point left out of it at kBytesPerLeftOutPoint (its place in the input, its normal, the
// kept point it counts with), and the mesh at kBytesPerVertex.
constexpr double kBytesPerPoint = 1000.0;
constexpr double kBytesPerLeftOutPoint = 150.0;
template <int D>
constexpr double kBytesPerVertex = D == 3 ? 1300.0 : 2000.0;

// max_memory, or half the physical memory (a 10M-point cloud needs about 8 GiB).
double memory_budget(const ReconstructionOptions& o);

std::string gib(double bytes);

// Refuses a cloud whose sampling, with the smallest mesh (1e4 vertices), would not fit.
template <int D>
void require_cloud_fits(const ReconstructionOptions& o, std::size_t points);

// The mesh vertices that fit in the budget beside `points` of which `sample` were kept (all of
// them: sample = points; under MPI, rank 0 holds its share of the points and the whole sample).
template <int D>
Index memory_limited_vertices(const ReconstructionOptions& o, std::size_t points, std::size_t sample);

}  // namespace lsr::detail
