// SPDX-License-Identifier: BSD-3-Clause
/// @file types.h
/// @brief Small value types shared by every part of the core.
#pragma once

#include "lsrecon/core/large_array_allocator.h"

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products on Vec<3>

#include <array>
#include <cstdint>
#include <vector>

namespace lsr {

inline constexpr double kPi = 3.14159265358979323846;

/// Index of a vertex or simplex. 32 bits: meshes are capped far below 2^31 entries.
using Index = std::int32_t;

/// A point or vector of R^D. DontAlign makes it safe inside std::vector whatever the C++
/// standard or Eigen's over-alignment setting (see docs/design.md section 8).
template <int D>
using Vec = Eigen::Matrix<double, D, 1, Eigen::DontAlign>;

/// A list of points of R^D: a std::vector whose storage, once large, lies on huge pages (mesh
/// vertices, fronts, queries: fresh arrays of tens of MiB each, see large_array_allocator.h).
template <int D>
using Points = LargeVector<Vec<D>>;

/// A mesh edge (a, b) with a < b and the parameter t of a point (1 - t) x_a + t x_b on it.
struct EdgePoint {
  Index a = -1;
  Index b = -1;
  double t = 0.0;
};

}  // namespace lsr
