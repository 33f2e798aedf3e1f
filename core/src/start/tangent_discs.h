// SPDX-License-Identifier: BSD-3-Clause
/// @file tangent_discs.h
/// @brief Distance to the union of the data points' tangent discs, bent to each point's fitted
/// height field: how lsrecon spans sampling holes (occlusions of a scan) without closing the
/// gaps between close sheets.
///
/// A point carries a disc in its tangent frame, lifted onto the quadric height field fitted to
/// its neighbours (local_sampling.h): an ellipse whose half-axis along each principal direction
/// is the radius asked for or the radius of curvature there, the smaller (disc_shape). Over a
/// hole narrower than the radius the discs of its rim meet and cover it, continuing the surface
/// with its curvature, so a flood that stops at the discs cannot enter, and an attraction to
/// them holds the front where the rim says the surface goes. Between two close sheets the discs
/// lie in the sheets and the gap stays open, and at a concave crease a face's disc continues
/// into the material, not the air. In the reconstruction only the rim points carry discs
/// (LocalSampling::rim): every other point is its own surface, and discs of noisy points stood
/// off it by up to a spacing. A closing by empty balls of radius H would fill every gap
/// narrower than 2 H, close sheets and creases included; flat discs stand off convex parts by
/// kappa r^2 / 2 and bridge close strands.
#pragma once

#include "sampling/local_sampling.h"

#include <vector>

namespace lsr {

/// Discs examined per query: its nearest points. Over a hole those are the near side of its rim,
/// whose discs reach across it; over sampled parts the nearest discs are the nearest surface.
/// A radius search over every disc that could reach (all points within the largest radius plus
/// the query's distance) took a third of the run.
constexpr int kDiscNeighbours = 32;

/// @brief Distance from each query whose point_distance is at most cap to the union of the
/// discs of its kDiscNeighbours nearest points (at most point_distance); the other queries keep
/// point_distance. Deterministic; parallel over the queries.
/// @param sampling normals and height fields of the data points
/// @param radius the discs' largest radius, the widest hole spanned
/// @param point_distance #Q distances from the queries to the data
/// @param cap #Q: beyond it the caller needs no disc
/// @param threads 0 for all cores
/// @param rims_only discs on the rim points only (sampling.rim; they need height fields only
/// there): a hole is spanned from its rim, and elsewhere the points alone attract, so that the
/// discs of noisy points do not stand off the surface
template <int D>
std::vector<double> tangent_disc_distance(const NearestPointIndex<D>& data, const LocalSampling<D>& sampling,
                                          double radius, const Points<D>& queries,
                                          const std::vector<double>& point_distance, const std::vector<double>& cap,
                                          int threads = 0, bool rims_only = false);

/// @brief S with the disc {x : |S x| <= 1} in tangent coordinates: along each principal
/// direction of the height field, half-axis min(radius, 1 / |kappa_i|). Beyond about one
/// radius of curvature a quadric no longer follows a round surface (a tube's quadric at
/// 1 / kappa from its point lies 0.12 / kappa outside the tube); along a flat direction (a
/// tube's axis) the disc reaches the full radius, across a joint where a hole may sit.
template <int D>
Eigen::Matrix<double, D - 1, D - 1> disc_shape(const HeightField<D>& f, double radius);

}  // namespace lsr
