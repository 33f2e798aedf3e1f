// SPDX-License-Identifier: BSD-3-Clause
/// @file simplex_angles.h
/// @brief Signed measure and angles of a simplex, as a simulation user judges an element: the
/// dihedral angles of a tetrahedron, the angles of a triangle.
#pragma once

#include "lsrecon/core/types.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace lsr {

template <int D>
double signed_measure_of(const Points<D>& x, const std::array<Index, D + 1>& s) {
  Eigen::Matrix<double, D, D> e;
  for (int k = 0; k < D; ++k) e.col(k) = x[s[k + 1]] - x[s[0]];
  return e.determinant() / (D == 2 ? 2.0 : 6.0);
}

/// The simplex's angles (radians): the 3 of a triangle, the 6 dihedral angles of a tetrahedron.
template <int D>
std::array<double, D == 2 ? 3 : 6> angles_of(const Points<D>& x, const std::array<Index, D + 1>& s) {
  std::array<double, D == 2 ? 3 : 6> angles{};
  if constexpr (D == 2) {
    for (int k = 0; k < 3; ++k) {
      const Vec<2> b = x[s[(k + 1) % 3]] - x[s[k]], c = x[s[(k + 2) % 3]] - x[s[k]];
      angles[std::size_t(k)] = std::atan2(std::abs(b.x() * c.y() - b.y() * c.x()), b.dot(c));
    }
  } else {
    // At edge (i, j): the angle between the components of the two other vertices orthogonal to it.
    std::size_t n = 0;
    for (int i = 0; i < 4; ++i) {
      for (int j = i + 1; j < 4; ++j) {
        int k = 0;
        while (k == i || k == j) ++k;
        const int l = 6 - i - j - k;
        const Vec<3> e = x[s[j]] - x[s[i]];
        Vec<3> pk = x[s[k]] - x[s[i]], pl = x[s[l]] - x[s[i]];
        pk -= e * (pk.dot(e) / e.squaredNorm());
        pl -= e * (pl.dot(e) / e.squaredNorm());
        angles[n++] = std::atan2(pk.cross(pl).norm(), pk.dot(pl));
      }
    }
  }
  return angles;
}

/// The smallest angle of the simplex, or -1 if it is flat or inverted.
template <int D>
double min_angle(const Points<D>& x, const std::array<Index, D + 1>& s) {
  if (!(signed_measure_of<D>(x, s) > 0.0)) return -1.0;
  const auto angles = angles_of<D>(x, s);
  return *std::min_element(angles.begin(), angles.end());
}

}  // namespace lsr
