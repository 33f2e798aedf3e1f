// SPDX-License-Identifier: BSD-3-Clause
/// @file analytic_shapes.h
/// @brief Shapes with exact signed distances and deterministic samplers: the default clouds of
/// the demos and the ground truth of the tests and benchmarks.
#pragma once

#include "lsrecon/core/types.h"

#include <vector>

namespace lsr {

/// @brief Circle of centre c and radius r in the plane.
struct Circle {
  Vec<2> center;
  double radius;
  double signed_distance(const Vec<2>& p) const { return (p - center).norm() - radius; }
  /// n points, evenly spaced in angle.
  Points<2> sample(int n) const;
};

/// @brief Sphere of centre c and radius r.
struct Sphere {
  Vec<3> center;
  double radius;
  double signed_distance(const Vec<3>& p) const { return (p - center).norm() - radius; }
  /// n points on a Fibonacci spiral (near-uniform, deterministic).
  Points<3> sample(int n) const;
};

/// @brief Torus around the z axis through center: major radius R, minor radius r.
struct Torus {
  Vec<3> center;
  double major_radius;
  double minor_radius;
  double signed_distance(const Vec<3>& p) const;
  /// About n points, area-uniform on a lattice in the two angles (deterministic).
  Points<3> sample(int n) const;
};

/// @brief n points, evenly spaced in angle, on the star r(t) = radius (1 + 0.3 cos 5t): five
/// concave valleys (no closed-form signed distance; measure against a dense sample).
Points<2> sample_star(int n, const Vec<2>& center, double radius);

/// @brief Signed distance of a union of shapes: the minimum of their signed distances (exact
/// outside the shapes and for disjoint shapes).
template <class Shape, int D>
double union_signed_distance(const std::vector<Shape>& shapes, const Vec<D>& p) {
  double d = shapes.front().signed_distance(p);
  for (const auto& s : shapes) d = std::min(d, s.signed_distance(p));
  return d;
}

}  // namespace lsr
