// SPDX-License-Identifier: BSD-3-Clause
/// @file point_location.h
/// @brief Locating points in an adaptive mesh and P1 (barycentric) interpolation of nodal fields.
#pragma once

#include "mesh/adaptive_refinement.h"

#include <array>
#include <vector>

namespace lsr {

/// @brief The simplex containing a point and the point's barycentric weights in it.
template <int D>
struct Location {
  Index simplex = -1;                 ///< mesh simplex, -1 when the point is outside [0,1]^D
  std::array<Index, D + 1> vertices{};  ///< the simplex's vertices, in the order of weights
  std::array<double, D + 1> weights{};  ///< barycentric weights, >= 0 up to round-off, sum 1
  bool found() const { return simplex >= 0; }
};

/// @brief Locates p by descending the bisection forest from its Kuhn root: exact on the
/// forest's own geometry, O(levels) per point, no geometric search.
/// @param tolerance points up to this far outside [0,1]^D are clamped onto it.
template <int D>
Location<D> locate(const AdaptiveMesh<D>& mesh, const Vec<D>& p, double tolerance = 1e-12);

/// @brief locate() for many points, on several threads (0: all cores).
template <int D>
std::vector<Location<D>> locate_all(const AdaptiveMesh<D>& mesh, const Points<D>& points,
                                    int threads = 0);

/// @brief Locates each point in any conforming simplicial mesh (an adapted mesh has no forest)
/// through a uniform grid of buckets, each listing the simplices whose bounding box meets it
/// (grid_point_location.cpp); a point on a face shared by two simplices goes to either.
template <int D>
std::vector<Location<D>> locate_all(const SimplexMesh<D>& mesh, const Points<D>& points, int threads = 0);

/// @brief The P1 interpolant of the nodal field u (std::vector or Eigen vector) at a located
/// point.
template <int D, class Field>
double interpolate(const Location<D>& at, const Field& u) {
  double value = 0.0;
  for (int k = 0; k <= D; ++k) value += at.weights[k] * u[at.vertices[k]];
  return value;
}

}  // namespace lsr
