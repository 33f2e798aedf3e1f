// SPDX-License-Identifier: BSD-3-Clause
/// @file surface_distance.h
/// @brief How far a triangle surface is from a ground truth given by its signed distance and
/// a dense sample: two-sided Chamfer and Hausdorff distances and normal consistency.
#pragma once

#include "lsrecon/core/types.h"

#include <array>
#include <functional>
#include <vector>

namespace lsr {

/// @brief Distances between a reconstruction and the truth, in the input's units.
struct SurfaceDistances {
  double mean_to_truth = 0.0;    ///< mean |sdf| over points sampled on the reconstruction
  double max_to_truth = 0.0;     ///< max |sdf| over those points
  double mean_from_truth = 0.0;  ///< mean distance from the truth samples to the reconstruction
  double max_from_truth = 0.0;   ///< max of those
  double chamfer = 0.0;          ///< (mean_to_truth + mean_from_truth) / 2
  double hausdorff = 0.0;        ///< max(max_to_truth, max_from_truth)
  /// Area-weighted mean of n_face . grad sdf: 1 for outward normals on the true surface,
  /// -1 inverted, about 0 for inconsistent orientation.
  double normal_consistency = 0.0;
};

/// @brief Compares triangles over vertices with the surface {sdf = 0}, sampled densely by
/// truth_samples. The reconstruction is sampled at its vertices and at `samples` points spread
/// over its area (deterministic). Distances to the reconstruction are exact point-to-triangle
/// distances (the cost grows with the longest edge: for evaluation, not inner loops). An empty
/// reconstruction gives infinite distances.
SurfaceDistances compare_to_truth(const Points<3>& vertices, const std::vector<std::array<Index, 3>>& triangles,
                                  const std::function<double(const Vec<3>&)>& sdf, const Points<3>& truth_samples,
                                  int samples = 200000);

}  // namespace lsr
