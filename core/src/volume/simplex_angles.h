// SPDX-License-Identifier: BSD-3-Clause
/// @file simplex_angles.h
/// @brief Signed measure and angles of a simplex, as a simulation user judges an element: the
/// dihedral angles of a tetrahedron, the angles of a triangle.
#pragma once

#include "lsrecon/core/types.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace lsr {

template <int D>
double signed_measure_of(const Points<D>& x, const std::array<Index, D + 1>& s) {
  Eigen::Matrix<double, D, D> e;
  for (int k = 0; k < D; ++k) e.col(k) = x[s[k + 1]] - x[s[0]];
  return e.determinant() / (D == 2 ? 2.0 : 6.0);
}

/// Appends the simplex's angles (radians): 3 in 2D, the 6 dihedral angles in 3D.
template <int D>
void add_angles(const Points<D>& x, const std::array<Index, D + 1>& s, std::vector<double>& angles) {
  if constexpr (D == 2) {
    for (int k = 0; k < 3; ++k) {
      const Vec<2> b = x[s[(k + 1) % 3]] - x[s[k]], c = x[s[(k + 2) % 3]] - x[s[k]];
      angles.push_back(std::atan2(std::abs(b.x() * c.y() - b.y() * c.x()), b.dot(c)));
    }
  } else {
    // At edge (i, j): the angle between the components of the two other vertices orthogonal to it.
    for (int i = 0; i < 4; ++i) {
      for (int j = i + 1; j < 4; ++j) {
        int k = 0;
        while (k == i || k == j) ++k;
        const int l = 6 - i - j - k;
        const Vec<3> e = x[s[j]] - x[s[i]];
        Vec<3> pk = x[s[k]] - x[s[i]], pl = x[s[l]] - x[s[i]];
        pk -= e * (pk.dot(e) / e.squaredNorm());
        pl -= e * (pl.dot(e) / e.squaredNorm());
        angles.push_back(std::atan2(pk.cross(pl).norm(), pk.dot(pl)));
      }
    }
  }
}

/// The smallest angle of the simplex, or -1 if it is flat or inverted.
template <int D>
double min_angle(const Points<D>& x, const std::array<Index, D + 1>& s) {
  if (!(signed_measure_of<D>(x, s) > 0.0)) return -1.0;
  std::vector<double> angles;
  angles.reserve(6);
  add_angles<D>(x, s, angles);
  return *std::min_element(angles.begin(), angles.end());
}

}  // namespace lsr
