// SPDX-License-Identifier: BSD-3-Clause
/// @file exact_predicates.h
/// @brief Signs of the orientation determinants and of dot products of point differences,
/// exact for any double input: a floating-point filter decides when its error bound allows,
/// exact integer arithmetic (Boost.Multiprecision) otherwise.
///
/// Each filter compares the value computed in doubles with a bound on its rounding error
/// (Shewchuk, "Adaptive precision floating-point arithmetic and fast robust geometric
/// predicates", 1997: error bound A of orient2d and orient3d; the same reasoning for a dot
/// product of differences); docs/how-it-works.md, Embedded output.
#pragma once

#include "lsrecon/core/types.h"

#include <cmath>

namespace lsr::detail {

/// sign(det[b - a, c - a]) in the plane of the coordinates (i, j) of 3D points, or of 2D points.
int exact_orient2d(double ax, double ay, double bx, double by, double cx, double cy);
/// sign(det[a - d, b - d, c - d]).
int exact_orient3d(const Vec<3>& a, const Vec<3>& b, const Vec<3>& c, const Vec<3>& d);
/// sign((b - a) . (c - a)).
template <int D>
int exact_dot_sign(const Vec<D>& a, const Vec<D>& b, const Vec<D>& c);

namespace predicates {
inline constexpr double kEpsilon = 0x1p-53;  // half an ulp of 1: the unit round-off of double
// Shewchuk's error bounds A: orient2d (3 + 16 eps) eps, orient3d (7 + 56 eps) eps of the
// permanent (the determinant's terms in absolute value).
inline constexpr double kOrient2dBound = (3.0 + 16.0 * kEpsilon) * kEpsilon;
inline constexpr double kOrient3dBound = (7.0 + 56.0 * kEpsilon) * kEpsilon;
// A dot product of D differences: each difference and product rounds once (2 eps), the sum
// of D terms D - 1 more times, relative to the sum of the terms' magnitudes: (D + 2) eps,
// doubled for the second-order terms.
inline constexpr double kDotBound = 10.0 * kEpsilon;
}  // namespace predicates

/// sign(det[b - a, c - a]) of (ax, ay), (bx, by), (cx, cy).
inline int orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
  const double left = (ax - cx) * (by - cy), right = (ay - cy) * (bx - cx), det = left - right;
  const double bound = predicates::kOrient2dBound * (std::abs(left) + std::abs(right));
  if (det > bound) return 1;
  if (-det > bound) return -1;
  return exact_orient2d(ax, ay, bx, by, cx, cy);
}

inline int orient2d(const Vec<2>& a, const Vec<2>& b, const Vec<2>& c) { return orient2d(a[0], a[1], b[0], b[1], c[0], c[1]); }

/// sign(det[a - d, b - d, c - d]): positive when d lies below the plane of a, b, c seen with
/// a, b, c counter-clockwise (Shewchuk's convention).
inline int orient3d(const Vec<3>& a, const Vec<3>& b, const Vec<3>& c, const Vec<3>& d) {
  const Vec<3> ad = a - d, bd = b - d, cd = c - d;
  const double bc = bd[0] * cd[1] - cd[0] * bd[1], ca = cd[0] * ad[1] - ad[0] * cd[1], ab = ad[0] * bd[1] - bd[0] * ad[1];
  const double det = ad[2] * bc + bd[2] * ca + cd[2] * ab;
  const double permanent = (std::abs(bd[0] * cd[1]) + std::abs(cd[0] * bd[1])) * std::abs(ad[2]) +
                           (std::abs(cd[0] * ad[1]) + std::abs(ad[0] * cd[1])) * std::abs(bd[2]) +
                           (std::abs(ad[0] * bd[1]) + std::abs(bd[0] * ad[1])) * std::abs(cd[2]);
  const double bound = predicates::kOrient3dBound * permanent;
  if (det > bound) return 1;
  if (-det > bound) return -1;
  return exact_orient3d(a, b, c, d);
}

/// sign((b - a) . (c - a)).
template <int D>
int dot_sign(const Vec<D>& a, const Vec<D>& b, const Vec<D>& c) {
  double dot = 0.0, magnitude = 0.0;
  for (int k = 0; k < D; ++k) {
    const double term = (b[k] - a[k]) * (c[k] - a[k]);
    dot += term;
    magnitude += std::abs(term);
  }
  const double bound = predicates::kDotBound * magnitude;
  if (dot > bound) return 1;
  if (-dot > bound) return -1;
  return exact_dot_sign<D>(a, b, c);
}

}  // namespace lsr::detail
