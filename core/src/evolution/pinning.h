// SPDX-License-Identifier: BSD-3-Clause
/// @file pinning.h
/// @brief Data points the front has reached hold their cells still.
#pragma once

#include "lsrecon/core/types.h"
#include "mesh/point_location.h"

#include <Eigen/Core>

#include <vector>

namespace lsr::detail {

// Mesh vertices each data point holds once reached: those whose nearest data point it is (its
// Voronoi cell), within pin_factor s of it. A vertex path that avoids every such ball crosses
// the surface only through an empty disc wider than pin_factor s, which a random sample of
// 2e5 points leaves with probability ~ N exp(-6 pin_factor^2) (local_sampling.h).
// CSR: vertices of point i at [offsets[i], offsets[i+1]).
struct VertexCells {
  std::vector<Index> offsets, vertices;
};

VertexCells pin_cells(const Eigen::VectorXd& scale, std::size_t points, const std::vector<double>& d,
                      const std::vector<Index>& nearest, double pin_factor);

// A data point counts as reached once the moving front is within `reach` of it (u rises to 0
// at the data when alpha > 0, falls to 0 when alpha < 0); its cell then stops moving: d := 0
// there and the vertices are held.
template <int D>
void pin_reached_data(const std::vector<Location<D>>& at, const VertexCells& cells,
                      const Eigen::VectorXd& u, double alpha, const std::vector<double>& reach,
                      std::vector<char>& pinned, Eigen::VectorXd& d, std::vector<char>& held);

}  // namespace lsr::detail
