// SPDX-License-Identifier: BSD-3-Clause
/// @file data_preparation.h
/// @brief The data as the solver takes it: checked to span a region, isolated points left out,
/// along a Z-order curve, and the local scale of every point.
#pragma once

#include "lsrecon/core/types.h"
#include "sampling/local_sampling.h"
#include "sampling/unit_box_transform.h"

#include <vector>

namespace lsr::detail {

/// @brief The points the solver works on, and where each came from.
template <int D>
struct DataPoints {
  Points<D> points;                ///< distinct finite points, input coordinates
  std::vector<std::size_t> kept;   ///< #points: the input index of each
  std::vector<std::size_t> finite; ///< the input index of each finite input point
  std::vector<std::size_t> first;  ///< #finite: the input index of its first copy (itself if none came before)

  /// @brief Per input point (#input): the normal of its point, or of its first copy; NaN for
  /// points left out (non-finite, isolated). `normals` is #points.
  Points<D> input_normals(const Points<D>& normals, std::size_t input) const;
};

/// @brief The finite points of `input`, each position once (exact_duplicates.h): copies add
/// nothing but cost (a scanner's (0,0,0) for each missing return).
template <int D>
DataPoints<D> distinct_finite_points(const Points<D>& input);

// A closed curve needs (distinct) points spanning the plane, a closed surface points spanning space.
template <int D>
void require_spanning(const Points<D>& points);
// The same from the points' count, mean, largest |x - mean| coordinate and covariance of
// (x - mean) / extent (a cloud split among workers).
template <int D>
void require_spread(std::size_t distinct, const Vec<D>& mean, double extent, const Eigen::Matrix<double, D, D>& cov);

// Drops the isolated points (nearest distinct neighbour beyond `factor` local spacings) from
// points and kept; true if there were any.
template <int D>
bool drop_isolated(const LocalSampling<D>& s, double factor, Points<D>& points, std::vector<std::size_t>& kept);

// The local scale l_i = max(s_i, 1.5 noise_i): what the sampling resolves, but not the noise
// (finer than the noise makes islands). Every length of
// the solver is a multiple of it.
template <int D>
std::vector<double> local_scales(const LocalSampling<D>& s);

// Mesh size near each point: its scale, clamped to [1 / max_resolution, 1/64 (2D) or 1/32
// (3D)], or the size asked for.
template <int D>
std::vector<double> local_mesh_sizes(const std::vector<double>& scale, double fixed, double max_resolution);

// The points (and their input indices) along a Z-order curve: a point's neighbours then lie
// near it in memory. In scanner or i.i.d. order every neighbourhood query of the sampling, the
// fit and the point location misses the cache. 3D only: 2D clouds are mostly pixel lattices,
// small, and full of equidistant neighbours among which the order decides.
template <int D>
void in_z_order(const UnitBoxTransform<D>& box, Points<D>& points, std::vector<std::size_t>& kept);

}  // namespace lsr::detail
