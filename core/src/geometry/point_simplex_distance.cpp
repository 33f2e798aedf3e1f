// SPDX-License-Identifier: BSD-3-Clause
/// @file point_simplex_distance.cpp
#include "geometry/point_simplex_distance.h"

#include <algorithm>

namespace lsr {

double segment_distance(const Vec<2>& p, const Vec<2>& a, const Vec<2>& b, int* corner) {
  const Vec<2> ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
  if (corner) *corner = t == 0.0 ? 0 : t == 1.0 ? 1 : -1;
  return (p - (a + t * ab)).norm();
}

double triangle_distance(const Vec<3>& p, const Vec<3>& a, const Vec<3>& b, const Vec<3>& c, int* corner) {
  int unused;
  int& at = corner ? *corner : unused;
  at = -1;
  const Vec<3> ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return at = 0, ap.norm();
  const Vec<3> bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return at = 1, bp.norm();
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return (p - (a + d1 / (d1 - d3) * ab)).norm();
  const Vec<3> cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return at = 2, cp.norm();
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return (p - (a + d2 / (d2 - d6) * ac)).norm();
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    return (p - (b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b))).norm();
  }
  const double denom = 1.0 / (va + vb + vc);
  return (p - (a + ab * (vb * denom) + ac * (vc * denom))).norm();
}

}  // namespace lsr
