// SPDX-License-Identifier: BSD-3-Clause
/// @file data_metric.h
/// @brief The metric the data ask of the mesh (paper section 6.2, issue 46): at a point x, the
/// level-set metric of the distance to the curve (surface) through the data point p nearest to
/// x. Across it, p's mesh size (what the isotropic mesh has there), growing with the distance
/// |x - p|; along it, sqrt(8 error / kappa) with kappa the curvature of p's height field, so
/// that a chord of the mesh stays within `error` of the curve, never finer than across, and
/// at most half the distance to another sheet of data facing p: a front entering a slot between
/// two sheets moves along them, and stalled at the slot's mouth on elements longer than the
/// slot is wide (measured: two unit spheres 0.12 apart, at 20k points, merged).
#pragma once

#include "geometry/nearest_point_index.h"
#include "mesh/level_set_metric.h"
#include "mesh/metric_adaptation.h"
#include "sampling/local_sampling.h"

#include <vector>

namespace lsr {

/// @brief The field over the data. It refers to its arguments, which must outlive it.
/// @param sampling the data's normals and height fields (HeightFieldsAt::all)
/// @param point_size #N: the mesh size at each point
/// @param relative_error the chord error allowed, in units of the point's mesh size
/// @param h_max the largest size
/// @param other_sheet #N: the distance from each point to another sheet facing it (other_sheets)
template <int D>
MetricField<D> data_metric(const NearestPointIndex<D>& data, const LocalSampling<D>& sampling, const std::vector<double>& point_size,
                           double relative_error, double h_max, const std::vector<double>& other_sheet);

/// @brief For each point p, the distance to the nearest of its kOtherSheetNeighbours nearest
/// points that lies off p's tangent plane: higher over it than half its distance to p (on
/// p's own sheet, only past a curvature radius) and than two mesh sizes at p (the noise); +inf
/// where none does.
template <int D>
std::vector<double> other_sheets(const NearestPointIndex<D>& data, const LocalSampling<D>& sampling, const std::vector<double>& point_size,
                                 int threads);

/// The neighbours other_sheets looks at: within about 4.5 spacings on a surface, 2.5 times the
/// along sizes' usual reach on the 3D corpus.
inline constexpr int kOtherSheetNeighbours = 64;

}  // namespace lsr
