// SPDX-License-Identifier: BSD-3-Clause
/// @file simulated_scan.cpp
#include "lsrecon/testdata/simulated_scan.h"

#include <Eigen/Geometry>

#include <omp.h>

#include <cmath>
#include <random>

namespace lsr {
namespace {

// A counter-based generator: the draws of a ray depend on (seed, view, ray) only.
std::mt19937_64 generator(std::uint64_t seed, std::uint64_t view, std::uint64_t ray) {
  std::uint64_t x = seed * 0x9E3779B97F4A7C15ull + view * 0xBF58476D1CE4E5B9ull + ray * 0x94D049BB133111EBull;
  x ^= x >> 31;
  return std::mt19937_64(x);
}

// The view directions: a Fibonacci spiral over the sphere, or over the upper half (z > 0.1:
// a scanner's tripod does not see under the table).
Points<3> view_directions(int views, bool from_above) {
  Points<3> d;
  const double golden = M_PI * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < views; ++i) {
    const double t = (i + 0.5) / views;
    const double z = from_above ? 0.1 + 0.8 * t : 1.0 - 2.0 * t;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    d.emplace_back(r * std::cos(golden * i), r * std::sin(golden * i), z);
  }
  return d;
}

// The first hit of the ray o + t u, t in (0, t_max], on {sdf = 0}: sphere tracing, safe with a
// signed distance that is exact or a lower bound. False if it leaves without a hit.
bool trace(const std::function<double(const Vec<3>&)>& sdf, const Vec<3>& o, const Vec<3>& u, double t_max, double tolerance,
           Vec<3>& hit) {
  double t = 0.0;
  for (int step = 0; step < 2000 && t <= t_max; ++step) {
    const Vec<3> p = o + t * u;
    const double d = sdf(p);
    if (d < tolerance) {
      hit = p;
      return d > -10.0 * tolerance;  // started inside: no hit
    }
    t += d;
  }
  return false;
}

}  // namespace

SampledShape simulate_scan(const TestShape& shape, const ScannerSettings& s, std::uint64_t seed) {
  const Vec<3> centre = 0.5 * (shape.lo + shape.hi);
  const double diagonal = (shape.hi - shape.lo).norm();
  const double radius = 0.5 * diagonal;  // a ball around the shape
  const double range = s.distance * diagonal;
  // The field of view just holds that ball; rays are spread evenly in angle.
  const double half_angle = std::asin(std::min(1.0, radius / range));
  const Points<3> directions = view_directions(s.views, s.from_above);
  const double tolerance = 1e-7 * diagonal;
  SampledShape out;
  out.diagonal = diagonal;
  for (int v = 0; v < s.views; ++v) {
    const Vec<3> eye = centre + range * directions[std::size_t(v)];
    const Vec<3> forward = -directions[std::size_t(v)];
    const Vec<3> side = (std::abs(forward.z()) < 0.9 ? forward.cross(Vec<3>::UnitZ()) : forward.cross(Vec<3>::UnitX())).normalized();
    const Vec<3> up = side.cross(forward);
    const long rays = long(s.lines) * s.samples_per_line;
    std::vector<char> kept(std::size_t(rays), 0);
    Points<3> points(std::size_t(rays), Vec<3>::Zero()), normals(std::size_t(rays), Vec<3>::Zero());
#pragma omp parallel for schedule(dynamic, 256)
    for (long r = 0; r < rays; ++r) {
      const int line = int(r / s.samples_per_line), along = int(r % s.samples_per_line);
      const double a = half_angle * (2.0 * (along + 0.5) / s.samples_per_line - 1.0);
      const double b = half_angle * (2.0 * (line + 0.5) / s.lines - 1.0);
      const Vec<3> u = (forward + std::tan(a) * side + std::tan(b) * up).normalized();
      Vec<3> hit;
      if (!trace(shape.sdf, eye, u, range + radius, tolerance, hit)) continue;
      const Vec<3> n = sdf_normal(shape.sdf, hit);
      std::mt19937_64 rng = generator(seed, std::uint64_t(v), std::uint64_t(r));
      // Grazing hits return too little light: lost below grazing_cos, more and more kept up to twice it.
      const double c = std::abs(n.dot(u));
      if (c < s.grazing_cos || (c < 2.0 * s.grazing_cos && std::uniform_real_distribution<double>(s.grazing_cos, 2.0 * s.grazing_cos)(rng) > c)) {
        continue;
      }
      const double t = (hit - eye).norm();
      points[std::size_t(r)] = hit + std::normal_distribution<double>(0.0, s.range_noise * t)(rng) * u;
      normals[std::size_t(r)] = n;
      kept[std::size_t(r)] = 1;
    }
    // The view as registered: turned about a random axis through the centre, and shifted.
    std::mt19937_64 rng = generator(seed, std::uint64_t(v), ~0ull);
    std::normal_distribution<double> gauss(0.0, 1.0);
    const Vec<3> axis = Vec<3>(gauss(rng), gauss(rng), gauss(rng)).normalized();
    const Eigen::Matrix3d turn = Eigen::AngleAxisd(s.registration_angle, axis).toRotationMatrix();
    const Vec<3> shift = s.registration_shift * diagonal * Vec<3>(gauss(rng), gauss(rng), gauss(rng)).normalized();
    for (long r = 0; r < rays; ++r) {
      if (!kept[std::size_t(r)]) continue;
      out.points.push_back(centre + turn * (points[std::size_t(r)] - centre) + shift);
      out.normals.push_back(normals[std::size_t(r)]);
    }
  }
  return out;
}

}  // namespace lsr
