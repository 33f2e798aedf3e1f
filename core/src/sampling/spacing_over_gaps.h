// SPDX-License-Identifier: BSD-3-Clause
/// @file spacing_over_gaps.h
/// @brief The spacing where a point's nearest hide the gaps of the sample: 3D scan lines, whose
/// kNeighbours nearest lie along one line, and random samples of a curve (2D), whose gaps are
/// exponential. There the spacing is raised to the width of the gaps among each point's
/// kHoleNeighbours nearest, median-filtered, over kHoleToSpacing (local_sampling.h; the reasons
/// and measurements in spacing_over_gaps.cpp).
#pragma once

#include "sampling/local_sampling.h"
#include "sampling/tile_runs.h"

#include <vector>

namespace lsr {

/// @brief The median of raw over one point's k nearest (k at most 32).
double neighbourhood_median(const std::vector<double>& raw, const Index* nearest, int k);

/// @brief neighbourhood_median of each of this worker's points, whose k nearest `nearest` holds
/// in order: out[first + r] for the r-th (out sized as raw).
void neighbourhood_medians(const std::vector<double>& raw, const LargeVector<Index>& nearest, int k, std::size_t first,
                           std::vector<double>& out, int threads);

/// @brief Whether the spacing is raised over gaps: in 3D when the cloud reads as scan lines (its
/// median elongation, or its narrow and wide normals disagreeing; `mode` may say), in 2D once
/// there are kHoleNeighbours points. `elongation` and s.normals: the kNeighbours PCA's.
template <int D>
bool spacing_over_gaps(const NearestPointIndex<D>& data, const std::vector<double>& elongation, const LocalSampling<D>& s,
                       int threads, const TileRuns& tiles, ScanLines mode);

/// @brief The width of the gaps around point i among its kHoleNeighbours nearest `around`. 3D:
/// the radius of the largest disc free of them in the plane of their PCA, whose normal and
/// thickness replace `normal` and set `noise`; 2D: half the widest gap between consecutive ones
/// along the tangent of `normal` (the kNeighbours one, unchanged; `noise` unchanged).
template <int D>
double gap_width(const Points<D>& p, const Index* around, std::size_t i, Vec<D>& normal, double& noise);

/// @brief Raises the spacing of each of this worker's points to its neighbours' median
/// gap_width over kHoleToSpacing; in 3D their normals and noise (median-filtered) become those
/// of their kHoleNeighbours nearest. `neighbours`: the kNeighbours nearest of this worker's
/// points. Holds one tile's kHoleNeighbours lists at a time.
template <int D>
void raise_spacing_over_gaps(const NearestPointIndex<D>& data, const LargeVector<Index>& neighbours, int threads,
                             LocalSampling<D>& s, const Progress& progress, const TileRuns& tiles);

}  // namespace lsr
