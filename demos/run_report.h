// SPDX-License-Identifier: BSD-3-Clause
/// @file run_report.h
/// @brief What the command line says about a run: the JSON report, the summary on stderr and
/// the hint of a run that stopped short.
#pragma once

#include "cli_options.h"

#include "lsrecon/core/level_set_reconstruction.h"
#include "lsrecon/core/level_set_volume_mesh.h"

#include <string>
#include <utility>
#include <vector>

namespace lsr::demos {

// The input as 3D points and its dimension.
struct Input {
  lsr::Points<3> points;
  int dim = 3;
  std::size_t skipped = 0;
  std::size_t statistical_outliers = 0;  ///< left out by pcl::StatisticalOutlierRemoval
  std::size_t other_ranks = 0;           ///< lsrecon-mpi: the points the other ranks took (points: this rank's share)
};

// What was written: for the report and the summary line.
struct Outcome {
  std::size_t vertices = 0, faces = 0, curves = 0;
  int components = 0;
  bool watertight = false;
  std::size_t intersecting_pairs = 0;  ///< pairs of facets that intersect (exact): 0 when embedded
  std::string summary;  ///< e.g. "3 closed curve(s), 812 vertices"
  lsr::VolumeMeshQuality volume;  ///< with --volume-mesh
};

// Seconds of the stages outside the solver (read, postprocess, write), in pipeline order.
using OuterStages = std::vector<std::pair<std::string, double>>;

/// @brief Writes the figures of the run to `file` (the report's temporary) as JSON.
template <int D>
void write_report(const Cli& c, const Input& in, const lsr::ReconstructionResult<D>& r, const Outcome& out,
                  const std::string& output, double total, const OuterStages& extra_seconds, const std::string& file);

/// @brief Stage times (unless quiet), what was left out or closed, and why a run stopped short.
template <int D>
void summarize(const lsr::ReconstructionResult<D>& r, double outlier_factor, bool quiet);

}  // namespace lsr::demos
