// SPDX-License-Identifier: BSD-3-Clause
/// @file shape_corpus.cpp
#include "lsrecon/testdata/shape_corpus.h"

#include "geometry/facet_mesh_distance.h"
#include "geometry/nearest_point_index.h"
#include "lsrecon/core/errors.h"
#include "stanford_bunny.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>

namespace lsr {
namespace {


// Torus around axis `axis` (0 = x, 2 = z) through c.
double torus(const Vec<3>& p, const Vec<3>& c, double major, double minor, int axis = 2) {
  const Vec<3> q = p - c;
  const int a = (axis + 1) % 3, b = (axis + 2) % 3;
  return std::hypot(std::hypot(q[a], q[b]) - major, q[axis]) - minor;
}

double segment_distance(const Vec<3>& p, const Vec<3>& a, const Vec<3>& b) {
  const Vec<3> ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (p - a - t * ab).norm();
}

// Distance in the meridian half-plane (rho, z) to a polyline: the exact distance to the
// surface swept by revolving it around z.
double revolved_polyline(const Vec<3>& p, const std::vector<Vec<3>>& profile) {
  const Vec<3> q(std::hypot(p.x(), p.y()), p.z(), 0.0);
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i + 1 < profile.size(); ++i) best = std::min(best, segment_distance(q, profile[i], profile[i + 1]));
  return best;
}

// A tube of radius r around the trefoil knot, by its distance to a dense sample of the curve
// (20,000 points: the error of a nearest-sample distance at r is below 1e-6 of the diagonal).
std::function<double(const Vec<3>&)> trefoil_tube(double r) {
  Points<3> curve;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    const double t = 2 * kPi * i / n;
    curve.emplace_back(std::sin(t) + 2 * std::sin(2 * t), std::cos(t) - 2 * std::cos(2 * t), -std::sin(3 * t));
  }
  auto index = std::make_shared<NearestPointIndex<3>>(std::move(curve));
  return [index, r](const Vec<3>& p) { return index->distance(p) - r; };
}

TestShape shape(std::string name, std::function<double(const Vec<3>&)> sdf, Vec<3> lo, Vec<3> hi,
                std::vector<int> genus, std::string description) {
  TestShape s;
  s.name = std::move(name);
  s.sdf = std::move(sdf);
  s.lo = lo;
  s.hi = hi;
  s.genus = std::move(genus);
  s.description = std::move(description);
  return s;
}

TestShape bunny() {
  Points<3> vertices;
  for (const auto& v : kBunnyVertices) vertices.emplace_back(v[0], v[1], v[2]);
  std::vector<std::array<Index, 3>> triangles;
  for (const auto& t : kBunnyTriangles) triangles.push_back({Index(t[0]), Index(t[1]), Index(t[2])});
  auto distance = std::make_shared<TriangleMeshDistance>(vertices, triangles);
  TestShape s = shape("bunny", [distance](const Vec<3>& p) { return distance->signed_distance(p); },
                      Vec<3>(-5.1, -0.1, -3.9), Vec<3>(5.1, 9.8, 3.9), {0},
                      "the Stanford bunny (closed, 3,674 triangles): thin ears");
  s.mesh_vertices = std::move(vertices);
  s.mesh_triangles = std::move(triangles);
  return s;
}

// Area-uniform points of a triangle mesh with the triangles' unit normals.
void sample_triangles(const Points<3>& v, const std::vector<std::array<Index, 3>>& triangles, int n,
                      std::uint64_t seed, Points<3>& points, Points<3>& normals) {
  std::vector<double> cumulative_area;
  double total = 0.0;
  for (const auto& t : triangles) {
    total += 0.5 * (v[t[1]] - v[t[0]]).cross(v[t[2]] - v[t[0]]).norm();
    cumulative_area.push_back(total);
  }
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < n; ++i) {
    const double pick = unit(rng) * total;
    const auto f = std::size_t(std::upper_bound(cumulative_area.begin(), cumulative_area.end(), pick) - cumulative_area.begin());
    const auto& t = triangles[std::min(f, triangles.size() - 1)];
    // Uniform on the triangle: the square root folds the unit square onto it.
    const double r = std::sqrt(unit(rng)), s = unit(rng);
    points.push_back((1.0 - r) * v[t[0]] + r * (1.0 - s) * v[t[1]] + r * s * v[t[2]]);
    normals.push_back((v[t[1]] - v[t[0]]).cross(v[t[2]] - v[t[0]]).normalized());
  }
}

}  // namespace

std::vector<std::string> test_shape_names() {
  return {"sphere", "torus", "double-torus", "triple-torus", "trefoil", "linked-rings", "cup", "limb", "two-spheres", "bunny"};
}

TestShape make_test_shape(const std::string& name) {
  const Vec<3> one = Vec<3>::Ones();
  if (name == "sphere") {
    return shape(name, [](const Vec<3>& p) { return p.norm() - 1.0; }, -1.1 * one, 1.1 * one, {0}, "unit sphere");
  }
  if (name == "torus") {
    return shape(name, [](const Vec<3>& p) { return torus(p, Vec<3>::Zero(), 1.0, 0.4); }, Vec<3>(-1.5, -1.5, -0.5),
                 Vec<3>(1.5, 1.5, 0.5), {1}, "R = 1, r = 0.4");
  }
  if (name == "double-torus") {
    // Centre lines 0.4 apart, tubes of radius 0.35: the tubes merge once, between the holes.
    return shape(name,
                 [](const Vec<3>& p) {
                   return std::min(torus(p, Vec<3>(-1.2, 0, 0), 1.0, 0.35), torus(p, Vec<3>(1.2, 0, 0), 1.0, 0.35));
                 },
                 Vec<3>(-2.6, -1.4, -0.4), Vec<3>(2.6, 1.4, 0.4), {2}, "two merged tori (crease at the join)");
  }
  if (name == "triple-torus") {
    // Centre lines crossing at two points, a graph with 3 independent cycles; the middle
    // (lens) hole is 0.2 wide where the tubes pass closest.
    return shape(name,
                 [](const Vec<3>& p) {
                   return std::min(torus(p, Vec<3>(-0.7, 0, 0), 1.0, 0.2), torus(p, Vec<3>(0.7, 0, 0), 1.0, 0.2));
                 },
                 Vec<3>(-1.9, -1.3, -0.3), Vec<3>(1.9, 1.3, 0.3), {3}, "two tori crossing twice");
  }
  if (name == "trefoil") {
    return shape(name, trefoil_tube(0.35), Vec<3>(-3.4, -3.4, -1.4), Vec<3>(3.4, 3.4, 1.4), {1},
                 "knotted tube of radius 0.35");
  }
  if (name == "linked-rings") {
    // Two rings through each other's holes; the tubes are 0.5 apart at the closest.
    return shape(name,
                 [](const Vec<3>& p) {
                   return std::min(torus(p, Vec<3>::Zero(), 1.0, 0.25), torus(p, Vec<3>(1, 0, 0), 1.0, 0.25, 1));
                 },
                 Vec<3>(-1.3, -1.3, -1.3), Vec<3>(2.3, 1.3, 1.3), {1, 1}, "two linked tori");
  }
  if (name == "cup") {
    // A U-shaped profile of half-thickness 0.08 revolved: walls 0.16 thick, 2.4 tall.
    const std::vector<Vec<3>> profile{Vec<3>(1.0, 1.2, 0), Vec<3>(1.0, -1.2, 0), Vec<3>(0.0, -1.2, 0)};
    return shape(name, [profile](const Vec<3>& p) { return revolved_polyline(p, profile) - 0.08; },
                 Vec<3>(-1.15, -1.15, -1.35), Vec<3>(1.15, 1.15, 1.35), {0}, "thin-walled cup, walls 1/15 of its height");
  }
  if (name == "limb") {
    // A unit ball with a capsule of radius 0.1 reaching 2 units out: 10:1.
    return shape(name,
                 [](const Vec<3>& p) {
                   return std::min(p.norm() - 1.0, segment_distance(p, Vec<3>(0.5, 0, 0), Vec<3>(2.9, 0, 0)) - 0.1);
                 },
                 Vec<3>(-1.1, -1.1, -1.1), Vec<3>(3.1, 1.1, 1.1), {0}, "ball with a thin limb (radius 1/10)");
  }
  if (name == "two-spheres") {
    return shape(name,
                 [](const Vec<3>& p) {
                   return std::min((p - Vec<3>(-1.06, 0, 0)).norm() - 1.0, (p - Vec<3>(1.06, 0, 0)).norm() - 1.0);
                 },
                 Vec<3>(-2.2, -1.1, -1.1), Vec<3>(2.2, 1.1, 1.1), {0, 0}, "two unit spheres 0.12 apart");
  }
  if (name == "bunny") return bunny();
  std::string names;
  for (const auto& n : test_shape_names()) names += (names.empty() ? "" : ", ") + n;
  throw InvalidInput("unknown test shape '" + name + "'", "use one of " + names);
}

Vec<3> sdf_normal(const std::function<double(const Vec<3>&)>& sdf, const Vec<3>& p) {
  const double h = 1e-6;
  Vec<3> g;
  for (int d = 0; d < 3; ++d) {
    Vec<3> e = Vec<3>::Zero();
    e[d] = h;
    g[d] = sdf(p + e) - sdf(p - e);
  }
  return g.normalized();
}

Points<3> sample_implicit_surface(const std::function<double(const Vec<3>&)>& sdf, const Vec<3>& lo,
                                  const Vec<3>& hi, int n, std::uint64_t seed) {
  // Cells that can meet the shell (|sdf| at the centre within half a cell diagonal + delta;
  // conservative for a 1-Lipschitz sdf), then uniform points in them.
  const int cells = 48;
  const Vec<3> size = hi - lo;
  const double cell = size.maxCoeff() / cells;
  const double delta = 0.3 * cell;
  const Eigen::Vector3i count = (size / cell).array().ceil().cast<int>().max(1);
  Points<3> corners;
  for (int i = 0; i < count.x(); ++i) {
    for (int j = 0; j < count.y(); ++j) {
      for (int k = 0; k < count.z(); ++k) {
        const Vec<3> corner = lo + cell * Vec<3>(i, j, k);
        if (std::abs(sdf(corner + Vec<3>::Constant(0.5 * cell))) <= 0.5 * std::sqrt(3.0) * cell + delta) corners.push_back(corner);
      }
    }
  }
  if (corners.empty()) throw InvalidInput("the surface does not cross the sampling box", "check lo and hi");
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Points<3> out;
  out.reserve(std::size_t(n));
  while (int(out.size()) < n) {
    const Vec<3>& c = corners[std::min(corners.size() - 1, std::size_t(unit(rng) * double(corners.size())))];
    Vec<3> p = c + cell * Vec<3>(unit(rng), unit(rng), unit(rng));
    if (std::abs(sdf(p)) >= delta) continue;
    for (int step = 0; step < 3; ++step) p -= sdf(p) * sdf_normal(sdf, p);
    out.push_back(p);
  }
  return out;
}

void sample_shape_surface(const TestShape& shape, int n, std::uint64_t seed, Points<3>& points, Points<3>& normals) {
  points.clear();
  normals.clear();
  if (!shape.mesh_triangles.empty()) {
    sample_triangles(shape.mesh_vertices, shape.mesh_triangles, n, seed, points, normals);
    return;
  }
  points = sample_implicit_surface(shape.sdf, shape.lo, shape.hi, n, seed);
  for (const auto& p : points) normals.push_back(sdf_normal(shape.sdf, p));
}

SampledShape sample_test_shape(const TestShape& shape, int n, const SamplingVariant& v, std::uint64_t seed) {
  SampledShape s;
  std::mt19937_64 rng(seed ^ 0x9e3779b97f4a7c15ULL);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> gauss(0.0, 1.0);
  // The diagonal and the hole centres come from a first sample, independent of the variant.
  Points<3> probe, batch, batch_normals;
  sample_shape_surface(shape, 2000, seed + 1, probe, batch_normals);
  Vec<3> lo = probe[0], hi = probe[0];
  for (const auto& p : probe) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  s.diagonal = (hi - lo).norm();
  Points<3> holes(probe.begin(), probe.begin() + std::min<std::size_t>(std::size_t(v.holes), probe.size()));
  const double hole = v.hole_radius * s.diagonal;
  std::uint64_t batch_seed = seed;
  while (int(s.points.size()) < n) {
    sample_shape_surface(shape, std::max(1000, n), batch_seed++, batch, batch_normals);
    for (std::size_t i = 0; i < batch.size() && int(s.points.size()) < n; ++i) {
      const Vec<3>& p = batch[i];
      bool keep = true;
      for (const auto& h : holes) keep = keep && (p - h).norm() >= hole;
      // Keep with probability falling linearly from 1 to 1 / ratio along x.
      if (v.density_ratio > 1.0) {
        keep = keep && unit(rng) < 1.0 - (1.0 - 1.0 / v.density_ratio) * (hi.x() - p.x()) / (hi.x() - lo.x());
      }
      if (!keep) continue;
      s.normals.push_back(batch_normals[i]);
      s.points.push_back(v.noise > 0.0 ? Vec<3>(p + v.noise * s.diagonal * Vec<3>(gauss(rng), gauss(rng), gauss(rng))) : p);
    }
  }
  return s;
}

}  // namespace lsr
