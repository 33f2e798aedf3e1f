// SPDX-License-Identifier: BSD-3-Clause
/// @file analytic_shapes.cpp
#include "lsrecon/testdata/analytic_shapes.h"

#include <cmath>

namespace lsr {
namespace {
}

Points<2> Circle::sample(int n) const {
  Points<2> pts;
  pts.reserve(n);
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * kPi * i / n;
    pts.push_back(center + radius * Vec<2>(std::cos(a), std::sin(a)));
  }
  return pts;
}

Points<2> sample_star(int n, const Vec<2>& center, double radius) {
  Points<2> pts;
  pts.reserve(n);
  for (int i = 0; i < n; ++i) {
    const double t = 2.0 * kPi * i / n;
    pts.push_back(center + radius * (1.0 + 0.3 * std::cos(5.0 * t)) * Vec<2>(std::cos(t), std::sin(t)));
  }
  return pts;
}

Points<3> Sphere::sample(int n) const {
  Points<3> pts;
  pts.reserve(n);
  const double golden = kPi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / n;
    const double rho = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double a = golden * i;
    pts.push_back(center + radius * Vec<3>(rho * std::cos(a), rho * std::sin(a), z));
  }
  return pts;
}

double Torus::signed_distance(const Vec<3>& p) const {
  const Vec<3> q = p - center;
  const double ring = std::hypot(q.x(), q.y()) - major_radius;
  return std::hypot(ring, q.z()) - minor_radius;
}

Points<3> Torus::sample(int n) const {
  // Area element is proportional to (R + r cos v): sample v by inverting its distribution
  // on a regular lattice so the density is uniform on the surface.
  const int nv = std::max(3, int(std::round(std::sqrt(n * minor_radius / major_radius))));
  const int nu = std::max(3, n / nv);
  Points<3> pts;
  pts.reserve(std::size_t(nu) * nv);
  for (int j = 0; j < nv; ++j) {
    const double target = (j + 0.5) / nv;  // CDF of v: (v + (r/R) sin v) / 2pi
    double v = 2.0 * kPi * target;
    for (int it = 0; it < 30; ++it) {
      const double f = (v + minor_radius / major_radius * std::sin(v)) / (2.0 * kPi) - target;
      v -= f / ((1.0 + minor_radius / major_radius * std::cos(v)) / (2.0 * kPi));
    }
    for (int i = 0; i < nu; ++i) {
      const double u = 2.0 * kPi * (i + 0.5 * (j % 2)) / nu;
      const double ring = major_radius + minor_radius * std::cos(v);
      pts.push_back(center + Vec<3>(ring * std::cos(u), ring * std::sin(u), minor_radius * std::sin(v)));
    }
  }
  return pts;
}

}  // namespace lsr
