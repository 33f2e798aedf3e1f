// SPDX-License-Identifier: BSD-3-Clause
/// @file data_metric.h
/// @brief The metric the data ask of the mesh (paper section 6.2, issue 46): at a point x, the
/// level-set metric of the distance to the curve (surface) through the data point p nearest to
/// x. Across it, p's mesh size (what the isotropic mesh has there), growing with the distance
/// |x - p|; along it, sqrt(8 error / kappa) with kappa the curvature of p's height field, so
/// that a chord of the mesh stays within `error` of the curve, never finer than across.
/// In 3D, isotropic from kAnisotropicReach sizes away from the data on.
#pragma once

#include "geometry/nearest_point_index.h"
#include "mesh/level_set_metric.h"
#include "mesh/metric_adaptation.h"
#include "sampling/local_sampling.h"

#include <limits>
#include <vector>

namespace lsr {

/// @brief Past this many sizes from the data the metric is isotropic, in 3D. The front's level
/// sets follow the data only once it has settled there: on its way through slots and gaps, and
/// where it pinches off a bridge, it runs across the data's directions, on elements long along
/// them. Calibrated (docs/calibration.md). In 2D none: the curves separate without it.
template <int D>
inline constexpr double kAnisotropicReach = D == 2 ? std::numeric_limits<double>::infinity() : 2.0;

/// @brief The field over the data. It refers to its arguments, which must outlive it.
/// @param sampling the data's normals and height fields (HeightFieldsAt::all)
/// @param point_size #N: the mesh size at each point
/// @param relative_error the chord error allowed, in units of the point's mesh size
/// @param h_max the largest size
template <int D>
MetricField<D> data_metric(const NearestPointIndex<D>& data, const LocalSampling<D>& sampling, const std::vector<double>& point_size,
                           double relative_error, double h_max);

}  // namespace lsr
