// SPDX-License-Identifier: BSD-3-Clause
/// @file metric_gradation.h
/// @brief Bounds how fast a metric field's sizes grow from vertex to vertex (Borouchaki, Hecht
/// and Frey 1997, "Mesh gradation control"): a size field that jumps from h_min to h_max over
/// one edge cannot be met by any mesh of good elements. Along an edge pq of length l = |pq|_Mp
/// in the metric at p, p allows at q the metric M_p scaled by (1 + l ln(beta))^-2, i.e. sizes
/// growing at most linearly, by the factor beta over a unit length of p's metric; q keeps the
/// intersection of its own metric with what p allows.
#pragma once

#include "lsrecon/core/simplex_geometry.h"
#include "mesh/level_set_metric.h"

#include <vector>

namespace lsr {

/// @brief The largest metric (smallest sizes in every direction) of two: by simultaneous
/// reduction, in the basis where both are diagonal, the larger eigenvalue of each direction.
template <int D>
Metric<D> metric_intersection(const Metric<D>& a, const Metric<D>& b);

/// @brief Limits the growth of the metrics (one per mesh vertex) along the mesh's edges to the
/// factor beta > 1 per unit length, sweeping the edges until no metric changes by more than 1e-9
/// in relative terms (or `max_sweeps`). Returns the number of sweeps.
template <int D>
int limit_gradation(const SimplexMesh<D>& mesh, std::vector<Metric<D>>& metrics, double beta, int max_sweeps = 100);

}  // namespace lsr
