// SPDX-License-Identifier: BSD-3-Clause
/// @file level_set_extraction_test.cpp
/// @brief Marching triangles / tetrahedra on analytic signed distances: topology, orientation
/// and O(h^2) accuracy.
#include "core/mesh_checks.h"
#include "lsrecon/core/level_set_extraction.h"
#include "lsrecon/testdata/analytic_shapes.h"
#include "mesh/adaptive_refinement.h"
#include "surface/surface_topology.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace lsr {
namespace {

const double kPi = std::acos(-1.0);

template <int D>
struct Extracted {
  LevelSetMesh<D> zero_set;
  double max_error = 0.0;  // max |sdf| over output vertices
  double rms_error = 0.0;
};

template <int D>
Extracted<D> extract(const Points<D>& samples, double h_min,
                     const std::function<double(const Vec<D>&)>& sdf) {
  const testing::SampledField<D> f = testing::sampled_field<D>(samples, h_min, sdf);
  const SimplexMesh<D>& mesh = f.adaptive.mesh;
  Extracted<D> out;
  out.zero_set = extract_zero_level_set(mesh, f.values);
  double sum2 = 0.0;
  for (std::size_t i = 0; i < out.zero_set.vertices.size(); ++i) {
    const double e = std::abs(sdf(out.zero_set.vertices[i]));
    out.max_error = std::max(out.max_error, e);
    sum2 += e * e;
    const EdgePoint& src = out.zero_set.sources[i];
    EXPECT_LT(src.a, src.b);
    EXPECT_GT(src.t, 0.0);
    EXPECT_LT(src.t, 1.0);
    const Vec<D> rebuilt = (1 - src.t) * mesh.vertices[src.a] + src.t * mesh.vertices[src.b];
    EXPECT_LE((rebuilt - out.zero_set.vertices[i]).norm(), 1e-15);
  }
  out.rms_error = std::sqrt(sum2 / double(out.zero_set.vertices.size()));
  return out;
}

// Linear interpolation along an edge of length L <= sqrt(D) h (the longest edge of a simplex
// of size h) misplaces the zero of a function with second derivative <= kappa by at most
// kappa L^2 / 8; near the surface the Hessian of a signed distance has eigenvalues
// kappa_i / (1 + kappa_i phi), so kappa is the largest principal curvature inflated by the
// offset |phi| <= L.
double interpolation_bound(int dim, double h, double kappa_max) {
  const double L = std::sqrt(double(dim)) * h;
  return kappa_max * L * L / (8.0 * (1.0 - kappa_max * L));
}

TEST(LevelSetExtraction, CircleIsOneClosedCounterClockwiseLoopWithSecondOrderError) {
  const Circle c{Vec<2>(0.5, 0.5), 0.3};
  auto sdf = [&](const Vec<2>& p) { return c.signed_distance(p); };
  double previous = 0.0;
  for (double h : {1.0 / 256, 1.0 / 512}) {
    const Extracted<2> e = extract<2>(c.sample(20000), h, sdf);
    const auto loops = closed_loops(e.zero_set);
    ASSERT_EQ(loops.size(), 1u);
    EXPECT_EQ(loops[0].size(), e.zero_set.vertices.size());
    double area = 0.0;  // shoelace: > 0 for counter-clockwise
    for (std::size_t i = 0; i < loops[0].size(); ++i) {
      const Vec<2>& a = e.zero_set.vertices[loops[0][i]];
      const Vec<2>& b = e.zero_set.vertices[loops[0][(i + 1) % loops[0].size()]];
      area += 0.5 * (a.x() * b.y() - a.y() * b.x());
    }
    EXPECT_NEAR(area, kPi * c.radius * c.radius, 2 * kPi * c.radius * e.max_error + 1e-12);
    EXPECT_LE(e.max_error, interpolation_bound(2, h, 1.0 / c.radius));
    if (previous > 0.0) {
      EXPECT_GE(std::log2(previous / e.rms_error), 1.5);
    }
    previous = e.rms_error;
  }
}

TEST(LevelSetExtraction, SphereIsAClosedGenusZeroSurfaceWithSecondOrderError) {
  const Sphere s{Vec<3>(0.5, 0.5, 0.5), 0.3};
  auto sdf = [&](const Vec<3>& p) { return s.signed_distance(p); };
  const Points<3> samples = s.sample(60000);
  double previous = 0.0;
  for (double h : {1.0 / 64, 1.0 / 128}) {
    const Extracted<3> e = extract<3>(samples, h, sdf);
    testing::expect_closed_surface(e.zero_set, 1, {0});
    EXPECT_LE(e.max_error, interpolation_bound(3, h, 1.0 / s.radius));
    if (previous > 0.0) {
      EXPECT_GE(std::log2(previous / e.rms_error), 1.5);
    }
    previous = e.rms_error;
  }
}

TEST(LevelSetExtraction, TorusHasGenusOne) {
  const Torus t{Vec<3>(0.5, 0.5, 0.5), 0.25, 0.1};
  const double h = 1.0 / 128;
  const Extracted<3> e =
      extract<3>(t.sample(80000), h, [&](const Vec<3>& p) { return t.signed_distance(p); });
  testing::expect_closed_surface(e.zero_set, 1, {1});
  EXPECT_LE(e.max_error, interpolation_bound(3, h, 1.0 / t.minor_radius));
}

TEST(LevelSetExtraction, TwoDisjointSpheresAreTwoComponents) {
  const std::vector<Sphere> spheres{{Vec<3>(0.3, 0.5, 0.5), 0.15}, {Vec<3>(0.7, 0.5, 0.5), 0.15}};
  Points<3> samples;
  for (const auto& s : spheres) {
    const Points<3> p = s.sample(20000);
    samples.insert(samples.end(), p.begin(), p.end());
  }
  const double h = 1.0 / 128;
  const Extracted<3> e = extract<3>(
      samples, h, [&](const Vec<3>& p) { return union_signed_distance<Sphere, 3>(spheres, p); });
  testing::expect_closed_surface(e.zero_set, 2, {0, 0});
  EXPECT_LE(e.max_error, interpolation_bound(3, h, 1.0 / 0.15));
}

TEST(LevelSetExtraction, ZerosOnMeshVerticesCountAsPositive) {
  // A cube level set on dyadic coordinates: thousands of mesh vertices have u == 0 exactly.
  const Sphere guide{Vec<3>(0.5, 0.5, 0.5), 0.25};
  auto cube = [](const Vec<3>& p) { return (p - Vec<3>::Constant(0.5)).cwiseAbs().maxCoeff() - 0.25; };
  const Extracted<3> e = extract<3>(guide.sample(5000), 1.0 / 32, cube);
  testing::expect_closed_surface(e.zero_set, 1, {0});
}

// Vertices numbered by their edges and facets in simplex order: the same surface whatever the
// thread count.
TEST(LevelSetExtraction, IsTheSameOnAnyNumberOfThreads) {
  const Sphere s{Vec<3>(0.5, 0.5, 0.5), 0.3};
  const testing::SampledField<3> f =
      testing::sampled_field<3>(s.sample(4000), 1.0 / 32, [&](const Vec<3>& x) { return s.signed_distance(x); });
  const SimplexMesh<3>& mesh = f.adaptive.mesh;
  const LevelSetMesh<3> one = extract_zero_level_set(mesh, f.values, 1e-9, 1);
  const LevelSetMesh<3> two = extract_zero_level_set(mesh, f.values, 1e-9, 2);
  ASSERT_GT(one.facets.size(), 1000u);
  EXPECT_TRUE(one.facets == two.facets);
  EXPECT_TRUE(one.vertices == two.vertices);
  for (std::size_t i = 1; i < one.sources.size(); ++i) {
    const EdgePoint& a = one.sources[i - 1];
    const EdgePoint& b = one.sources[i];
    EXPECT_TRUE(a.a < b.a || (a.a == b.a && a.b < b.b)) << i;
  }
}

TEST(LevelSetExtraction, RejectsMismatchedOrNonFiniteFields) {
  SimplexMesh<2> m;
  m.vertices = {Vec<2>(0, 0), Vec<2>(1, 0), Vec<2>(0, 1)};
  m.simplices = {{0, 1, 2}};
  EXPECT_THROW(extract_zero_level_set(m, {1.0, -1.0}), InvalidInput);
  EXPECT_THROW(extract_zero_level_set(m, {1.0, -1.0, std::nan("")}), InvalidInput);
  EXPECT_EQ(extract_zero_level_set(m, {1.0, 2.0, 3.0}).facets.size(), 0u);
}

}  // namespace
}  // namespace lsr
