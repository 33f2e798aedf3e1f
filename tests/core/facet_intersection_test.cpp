// SPDX-License-Identifier: BSD-3-Clause
/// @file facet_intersection_test.cpp
/// @brief lsrecon's exact facet-intersection test and self-intersection search against CGAL's
/// (checks/exact_self_intersections.h), on configurations built to be degenerate: corners on a
/// small integer lattice give coplanar, collinear and touching facets in large numbers, the
/// cases a floating-point test gets wrong.
#include "checks/exact_self_intersections.h"
#include "core/mesh_checks.h"
#include "geometry/exact_predicates.h"
#include "geometry/facet_intersection.h"
#include "geometry/self_intersections.h"
#include "lsrecon/testdata/analytic_shapes.h"

#include <gtest/gtest.h>

#include <random>

namespace lsr {
namespace {

using detail::count_self_intersections;
using detail::facets_intersect;
using testing::cgal_self_intersections;

// A lattice point of {0..3}^D, times `unit` (0.1 is not a binary fraction: the coordinates
// are rounded, and coplanar lattice points no longer exactly so).
template <int D>
Vec<D> lattice(std::mt19937_64& random, double unit) {
  std::uniform_int_distribution<int> k(0, 3);
  Vec<D> p;
  for (int i = 0; i < D; ++i) p[i] = unit * k(random);
  return p;
}

bool collinear(const Vec<3>& a, const Vec<3>& b, const Vec<3>& c) {
  for (int axis = 0; axis < 3; ++axis) {
    const int i = (axis + 1) % 3, j = (axis + 2) % 3;
    if (detail::orient2d(a[i], a[j], b[i], b[j], c[i], c[j]) != 0) return false;
  }
  return true;
}

// Two triangles sharing `shared` (0, 1 or 2) corners by index; CGAL's count on the same two
// facets (a mesh of two faces, consistently oriented across a shared edge).
void expect_agreement(int shared, double unit, int trials) {
  std::mt19937_64 random(42 + std::uint64_t(shared));
  int compared = 0, intersecting = 0;
  for (int trial = 0; trial < trials; ++trial) {
    Points<3> x;
    for (int i = 0; i < 6 - shared; ++i) x.push_back(lattice<3>(random, unit));
    std::array<Index, 3> f{0, 1, 2}, g{};
    if (shared == 0) g = {3, 4, 5};
    if (shared == 1) g = {0, 3, 4};
    if (shared == 2) g = {1, 0, 3};  // the edge 0-1 the other way round
    bool distinct = true;
    for (std::size_t i = 0; i < x.size(); ++i) {
      for (std::size_t j = i + 1; j < x.size(); ++j) distinct = distinct && x[i] != x[j];
    }
    if (!distinct || collinear(x[std::size_t(f[0])], x[std::size_t(f[1])], x[std::size_t(f[2])]) ||
        collinear(x[std::size_t(g[0])], x[std::size_t(g[1])], x[std::size_t(g[2])])) {
      continue;
    }
    const std::size_t cgal = cgal_self_intersections(x, {f, g});
    if (cgal == std::numeric_limits<std::size_t>::max()) continue;  // not a mesh CGAL builds
    ++compared;
    intersecting += cgal > 0 ? 1 : 0;
    ASSERT_EQ(facets_intersect(x, f, g), cgal > 0) << "trial " << trial << ", " << shared << " shared";
    ASSERT_EQ(facets_intersect(x, g, f), cgal > 0) << "trial " << trial << ", " << shared << " shared, swapped";
  }
  // Both outcomes occur often enough for the comparison to mean something.
  EXPECT_GT(compared, trials / 4);
  EXPECT_GT(intersecting, 100);
  EXPECT_GT(compared - intersecting, 100);
}

TEST(FacetIntersection, TrianglesAgreeWithCgalOnALattice) {
  for (int shared = 0; shared <= 2; ++shared) {
    expect_agreement(shared, 1.0, 20000);
    expect_agreement(shared, 0.1, 20000);
  }
}

TEST(FacetIntersection, SegmentsAgreeWithCgalOnALattice) {
  std::mt19937_64 random(7);
  int intersecting = 0;
  const int trials = 20000;
  for (int trial = 0; trial < trials; ++trial) {
    const int shared = trial % 2;
    Points<2> x;
    for (int i = 0; i < 4 - shared; ++i) x.push_back(lattice<2>(random, trial % 4 < 2 ? 1.0 : 0.1));
    const std::array<Index, 2> f{0, 1}, g = shared ? std::array<Index, 2>{1, 2} : std::array<Index, 2>{2, 3};
    if (x[0] == x[1] || x[std::size_t(g[0])] == x[std::size_t(g[1])]) continue;
    const bool cgal = cgal_self_intersections(x, {f, g}) > 0;
    intersecting += cgal ? 1 : 0;
    ASSERT_EQ(facets_intersect(x, f, g), cgal) << "trial " << trial;
  }
  EXPECT_GT(intersecting, trials / 20);
}

// A closed surface whose vertices are thrown about: hundreds of intersecting pairs of every
// kind, counted alike by both.
TEST(SelfIntersections, CountsAsCgalOnATangledSurface) {
  const Sphere sphere{Vec<3>(0.5, 0.5, 0.5), 0.3};
  testing::SampledField<3> f =
      testing::sampled_field<3>(sphere.sample(400), 1.0 / 32.0, [&](const Vec<3>& p) { return sphere.signed_distance(p); });
  LevelSetMesh<3> s = extract_zero_level_set(f.adaptive.mesh, f.values);
  ASSERT_EQ(count_self_intersections(s.vertices, s.facets, 2), 0u);
  EXPECT_EQ(cgal_self_intersections(s.vertices, s.facets), 0u);
  std::mt19937_64 random(3);
  std::normal_distribution<double> move(0.0, 0.02);  // about a mesh size
  for (auto& x : s.vertices) x += Vec<3>(move(random), move(random), move(random));
  const std::size_t ours = count_self_intersections(s.vertices, s.facets, 2);
  EXPECT_GT(ours, 100u);
  EXPECT_EQ(ours, cgal_self_intersections(s.vertices, s.facets));
  // Snapped to a lattice of an eighth of a mesh size: coplanar and touching facets everywhere
  // (the degenerate ones left out: CGAL's count assumes none).
  for (auto& x : s.vertices) x = (x * 256.0).array().round().matrix() / 256.0;
  std::vector<std::array<Index, 3>> kept;
  for (const auto& t : s.facets) {
    if (!collinear(s.vertices[std::size_t(t[0])], s.vertices[std::size_t(t[1])], s.vertices[std::size_t(t[2])])) kept.push_back(t);
  }
  const std::size_t cgal = cgal_self_intersections(s.vertices, kept);
  ASSERT_NE(cgal, std::numeric_limits<std::size_t>::max());
  EXPECT_GT(cgal, 100u);
  EXPECT_EQ(count_self_intersections(s.vertices, kept, 2), cgal);
}

}  // namespace
}  // namespace lsr
