// SPDX-License-Identifier: BSD-3-Clause
/// @file tangent_discs.h
/// @brief Distance to the union of the data points' tangent discs, bent to each point's fitted
/// height field: how lsrecon spans sampling holes (occlusions of a scan) without closing the
/// gaps between close sheets.
///
/// Each point carries a disc of radius r_i in its tangent frame, lifted onto the quadric height
/// field fitted to its neighbours (local_sampling.h). Over a hole narrower than the radius the
/// discs of its rim meet and cover it, continuing the surface with its curvature, so a flood
/// that stops at the discs cannot enter, and an attraction to them holds the front where the
/// rim says the surface goes. Between two close sheets the discs lie in the sheets and the gap
/// stays open, and at a concave crease a face's disc continues into the material, not the air.
/// A closing by empty balls of radius H (the earlier rule) filled every gap narrower than 2 H,
/// close sheets and creases included (measured: README.md). Flat discs stood off convex parts by
/// kappa r^2 / 2 and bridged the close strands of a thin knotted tube (measured).
#pragma once

#include "lsrecon/core/local_sampling.h"

#include <vector>

namespace lsr {

/// @brief Distance from each query to the union of the discs, where it is below
/// min(point_distance, cap); elsewhere point_distance (the distance to the points, an upper
/// bound up to the height fields' offsets). Only the points within that bound plus the largest
/// radius are examined. Deterministic; parallel over the queries.
/// @param sampling normals and height fields of the data points
/// @param radius #N disc radii (disc_radii)
/// @param point_distance #Q distances from the queries to the data
/// @param cap #Q: beyond it the exact value does not matter to the caller
/// @param threads 0 for all cores
template <int D>
std::vector<double> tangent_disc_distance(const NearestPointIndex<D>& data, const LocalSampling<D>& sampling,
                                          const std::vector<double>& radius, const Points<D>& queries,
                                          const std::vector<double>& point_distance, const std::vector<double>& cap,
                                          int threads = 0);

/// @brief min(largest, 1 / curvature_i) per point: beyond about one radius of curvature a
/// quadric no longer follows a round surface (a tube's quadric at 1 / kappa from its point lies
/// 0.12 / kappa outside the tube).
std::vector<double> disc_radii(double largest, const std::vector<double>& curvature);

}  // namespace lsr
