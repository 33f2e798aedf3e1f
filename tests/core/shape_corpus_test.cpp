// SPDX-License-Identifier: BSD-3-Clause
/// @file shape_corpus_test.cpp
/// @brief The corpus's mesh shape (the bunny): its samples lie on the mesh, spread by area,
/// with outward normals; its signed distance agrees with the mesh's orientation.
#include "lsrecon/testdata/shape_corpus.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace lsr {
namespace {

double triangle_area(const TestShape& s, std::size_t f) {
  const auto& t = s.mesh_triangles[f];
  const auto& v = s.mesh_vertices;
  return 0.5 * (v[t[1]] - v[t[0]]).cross(v[t[2]] - v[t[0]]).norm();
}

// The triangle holding p: barycentric coordinates in [0, 1] and p in its plane.
std::size_t triangle_of(const TestShape& s, const Vec<3>& p) {
  for (std::size_t f = 0; f < s.mesh_triangles.size(); ++f) {
    const auto& t = s.mesh_triangles[f];
    const Vec<3> a = s.mesh_vertices[t[0]], e1 = s.mesh_vertices[t[1]] - a, e2 = s.mesh_vertices[t[2]] - a;
    const Vec<3> n = e1.cross(e2);
    if (std::abs((p - a).dot(n)) > 1e-9 * n.norm()) continue;
    const double b1 = (p - a).cross(e2).dot(n) / n.squaredNorm(), b2 = e1.cross(p - a).dot(n) / n.squaredNorm();
    if (b1 >= -1e-9 && b2 >= -1e-9 && b1 + b2 <= 1.0 + 1e-9) return f;
  }
  return s.mesh_triangles.size();
}

TEST(ShapeCorpus, BunnySamplesLieOnTheMeshSpreadByArea) {
  const TestShape bunny = make_test_shape("bunny");
  ASSERT_EQ(bunny.mesh_triangles.size(), 3674u);
  const int n = 8000;
  Points<3> p, normals;
  sample_shape_surface(bunny, n, 5, p, normals);
  ASSERT_EQ(p.size(), std::size_t(n));
  // Triangles in 4 classes by area quartile (a sampler picking triangles uniformly would give
  // each a quarter): each class's share of the samples is binomial around its share of the
  // area; 5 standard deviations.
  const std::size_t nf = bunny.mesh_triangles.size();
  std::vector<std::size_t> by_area(nf);
  for (std::size_t f = 0; f < nf; ++f) by_area[f] = f;
  std::sort(by_area.begin(), by_area.end(),
            [&](std::size_t a, std::size_t b) { return triangle_area(bunny, a) < triangle_area(bunny, b); });
  std::vector<int> quartile(nf);
  for (std::size_t r = 0; r < nf; ++r) quartile[by_area[r]] = int(4 * r / nf);
  std::array<double, 4> area{}, count{};
  double total = 0.0;
  for (std::size_t f = 0; f < nf; ++f) {
    area[quartile[f]] += triangle_area(bunny, f);
    total += triangle_area(bunny, f);
  }
  for (int i = 0; i < n; ++i) {
    const std::size_t f = triangle_of(bunny, p[i]);
    ASSERT_LT(f, bunny.mesh_triangles.size()) << "sample " << i << " is on no triangle";
    count[quartile[f]] += 1.0;
    EXPECT_NEAR(normals[i].norm(), 1.0, 1e-12);
    EXPECT_LT(std::abs(bunny.sdf(p[i])), 1e-9);
  }
  for (int c = 0; c < 4; ++c) {
    const double q = area[c] / total;
    EXPECT_NEAR(count[c] / n, q, 5.0 * std::sqrt(q * (1.0 - q) / n)) << "class " << c;
  }
}

TEST(ShapeCorpus, BunnyNormalsPointWhereItsSignedDistanceGrows) {
  // A step of 1e-3 (the bunny spans 10 units, its triangles 0.1-0.8) along the normal leaves the
  // solid and against it enters, except within about 1e-3 of a concave edge: at most 1% of them.
  const TestShape bunny = make_test_shape("bunny");
  Points<3> p, normals;
  sample_shape_surface(bunny, 2000, 9, p, normals);
  int wrong = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    wrong += bunny.sdf(p[i] + 1e-3 * normals[i]) <= 0.0 || bunny.sdf(p[i] - 1e-3 * normals[i]) >= 0.0;
  }
  EXPECT_LE(wrong, 20);
}

}  // namespace
}  // namespace lsr
