// SPDX-License-Identifier: BSD-3-Clause
/// @file compare_cases.cpp
#include "compare_cases.h"

#include "lsrecon/core/analytic_shapes.h"
#include "lsrecon/core/errors.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace lsr::demos {
namespace {

// Exact signed distance of a capsule-free bar: a cylinder of radius r along x, |x| <= half.
double bar_sdf(const Vec<3>& p, double r, double half) {
  const double dr = std::hypot(p.y(), p.z()) - r;
  const double dx = std::abs(p.x()) - half;
  return std::min(std::max(dr, dx), 0.0) + std::hypot(std::max(dr, 0.0), std::max(dx, 0.0));
}

Vec<3> gradient(const std::function<double(const Vec<3>&)>& f, const Vec<3>& p) {
  const double h = 1e-6;
  Vec<3> g;
  for (int d = 0; d < 3; ++d) {
    Vec<3> e = Vec<3>::Zero();
    e[d] = h;
    g[d] = (f(p + e) - f(p - e)) / (2 * h);
  }
  return g.normalized();
}

// Points on the boundary of a union: samples of each part that no other part covers.
Points<3> union_surface(const std::vector<Points<3>>& parts, const std::function<double(const Vec<3>&)>& sdf) {
  Points<3> out;
  for (const auto& part : parts) {
    for (const auto& p : part) {
      if (std::abs(sdf(p)) < 1e-9) out.push_back(p);
    }
  }
  return out;
}

Points<3> bar_sample(double r, double half, int n) {
  Points<3> p;
  const int rings = std::max(2, int(std::sqrt(n * half / (3.141592653589793 * r))));
  const int around = std::max(3, n / rings);
  for (int i = 0; i < rings; ++i) {
    for (int j = 0; j < around; ++j) {
      const double x = -half + 2 * half * (i + 0.5) / rings, a = 2 * 3.141592653589793 * (j + 0.5 * (i % 2)) / around;
      p.emplace_back(x, r * std::cos(a), r * std::sin(a));
    }
  }
  return p;
}

}  // namespace

std::vector<std::string> case_names() { return {"sphere", "torus", "two-spheres", "dumbbell"}; }

CompareCase make_case(const std::string& name, int n, double noise, double holes, bool nonuniform) {
  CompareCase c;
  c.name = name;
  const int dense = 60000;
  Points<3> clean;
  if (name == "sphere") {
    const Sphere s{Vec<3>(0, 0, 0), 1.0};
    c.sdf = [s](const Vec<3>& p) { return s.signed_distance(p); };
    clean = s.sample(n);
    c.truth = s.sample(dense);
  } else if (name == "torus") {
    const Torus t{Vec<3>(0, 0, 0), 1.0, 0.4};
    c.sdf = [t](const Vec<3>& p) { return t.signed_distance(p); };
    clean = t.sample(n);
    c.truth = t.sample(dense);
  } else if (name == "two-spheres") {
    const std::vector<Sphere> s{{Vec<3>(-1.3, 0, 0), 1.0}, {Vec<3>(1.3, 0, 0), 1.0}};
    c.sdf = [s](const Vec<3>& p) { return union_signed_distance<Sphere, 3>(s, p); };
    clean = s[0].sample(n / 2);
    for (const auto& p : s[1].sample(n - n / 2)) clean.push_back(p);
    c.truth = s[0].sample(dense / 2);
    for (const auto& p : s[1].sample(dense / 2)) c.truth.push_back(p);
  } else if (name == "dumbbell") {
    const Sphere a{Vec<3>(-1, 0, 0), 0.55}, b{Vec<3>(1, 0, 0), 0.55};
    const double r = 0.15, half = 1.0;
    c.sdf = [a, b, r, half](const Vec<3>& p) {
      return std::min({a.signed_distance(p), b.signed_distance(p), bar_sdf(p, r, half)});
    };
    // Area shares: balls 2 x 4 pi 0.55^2 = 7.6, bar 2 pi 0.15 x 2 = 1.9.
    auto sample = [&](int m) {
      const int bar = m * 19 / 95;
      return union_surface({a.sample((m - bar) / 2 + m / 20), b.sample((m - bar) / 2 + m / 20), bar_sample(r, half, bar)}, c.sdf);
    };
    clean = sample(n);
    c.truth = sample(dense);
  } else {
    throw InvalidInput("unknown case '" + name + "'", "use sphere, torus, two-spheres or dumbbell");
  }
  Vec<3> lo = c.truth[0], hi = c.truth[0];
  for (const auto& p : c.truth) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  c.diagonal = (hi - lo).norm();

  std::mt19937 rng(2011);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> gauss(0.0, 1.0);
  // Holes: remove the points within a cap radius of a few fixed surface points.
  Points<3> centres;
  if (holes > 0.0) {
    for (int k = 0; k < 3; ++k) centres.push_back(clean[std::size_t(unit(rng) * clean.size())]);
  }
  const double cap = std::sqrt(holes / 3.0) * c.diagonal * 0.5;
  for (const auto& p : clean) {
    bool drop = false;
    for (const auto& q : centres) drop = drop || (p - q).norm() < cap;
    // Nonuniform: keep a point with a probability falling from 1 to 0.1 along x.
    if (nonuniform) drop = drop || unit(rng) > 0.1 + 0.9 * (p.x() - lo.x()) / (hi.x() - lo.x());
    if (drop) continue;
    const Vec<3> n = gradient(c.sdf, p);
    c.normals.push_back(n);
    c.points.push_back(noise > 0 ? Vec<3>(p + noise * c.diagonal * Vec<3>(gauss(rng), gauss(rng), gauss(rng))) : p);
  }
  return c;
}

}  // namespace lsr::demos
