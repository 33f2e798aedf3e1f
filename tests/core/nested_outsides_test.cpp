// SPDX-License-Identifier: BSD-3-Clause
/// @file nested_outsides_test.cpp
/// @brief Sheets inside sheets alternate inside and outside: the depth parity on a grid, then an
/// annulus (2D) and a hollow ball (3D) end to end.
#include "start/nested_outsides.h"

#include "geometry/nearest_point_index.h"
#include "lsrecon/core/level_set_reconstruction.h"
#include "lsrecon/testdata/analytic_shapes.h"
#include "mesh/adaptive_refinement.h"
#include "mesh/kuhn_bisection.h"
#include "start/outside_flood_fill.h"
#include "surface/surface_topology.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace lsr {
namespace {

const double kPi = std::acos(-1.0);

// Data on spheres round the box's centre, with radial normals (either sense: unoriented),
// and the free vertices: farther than `gap` from the data.
struct Shells {
  SimplexMesh<3> mesh;
  VertexNeighbours neighbours;
  Points<3> points, normals;
  std::vector<Index> nearest;
  std::vector<char> passable, reached;
  Shells(int cells, const std::vector<double>& radii, double gap)
      : mesh(leaf_mesh(KuhnBisectionForest<3>(cells)).mesh), neighbours(vertex_neighbours(mesh)) {
    for (std::size_t k = 0; k < radii.size(); ++k) {
      for (const auto& x : Sphere{Vec<3>::Zero(), radii[k]}.sample(int(4000 * radii[k] * radii[k] / 0.04))) {
        points.push_back(x + Vec<3>::Constant(0.5));
        normals.push_back((k % 2 ? -1.0 : 1.0) * x.normalized());
      }
    }
    std::vector<double> distance;
    NearestPointIndex<3>(points).query(mesh.vertices, distance, &nearest);
    for (const double d : distance) passable.push_back(d > gap);
    reached = flood_from_walls(mesh, passable);
  }
  double radius(std::size_t v) const { return (mesh.vertices[v] - Vec<3>::Constant(0.5)).norm(); }
  std::vector<char> nested() const {
    return detail::nested_outsides(mesh, neighbours, vertex_components(mesh, passable), reached, points, normals, nearest);
  }
};

TEST(NestedOutsides, ThreeNestedShellsMakeTheSecondGapOutsideAndTheCoreInside) {
  // Spheres of radius 0.41, 0.27 and 0.13, free beyond 0.03 of them (wider than the grid's
  // longest edge, sqrt(3) / 32 = 0.054, over both sides: no edge jumps a band). Depths: beyond
  // 0.44 the flood (0), 0.30-0.38 inside the outer sphere (1), 0.16-0.24 inside the middle one
  // (2: outside), the core inside the inner one (3: inside).
  const Shells s(32, {0.41, 0.27, 0.13}, 0.03);
  const std::vector<char> nested = s.nested();
  int marked = 0;
  for (std::size_t v = 0; v < nested.size(); ++v) {
    const double r = s.radius(v);
    EXPECT_EQ(bool(nested[v]), s.passable[v] && r > 0.13 && r < 0.27) << "vertex " << v << " at radius " << r;
    marked += nested[v];
  }
  EXPECT_GT(marked, 0);
}

TEST(NestedOutsides, BandsJoinedAcrossAThinRegionDoNotFlipTheCore) {
  // The same spheres with the region between the outer two blocked along a slab |z| < 0.04
  // (as where two sheets' bands touch): a path crossing bands counts the outer two as one
  // there and would give the core depth 2. Facing points, it is still 3: only the gap
  // between the inner two is outside.
  Shells s(32, {0.41, 0.27, 0.13}, 0.03);
  for (std::size_t v = 0; v < s.passable.size(); ++v) {
    const double r = s.radius(v), z = s.mesh.vertices[v].z() - 0.5;
    if (r > 0.27 && r < 0.41 && std::abs(z) < 0.04) s.passable[v] = 0;
  }
  const std::vector<char> nested = s.nested();
  for (std::size_t v = 0; v < nested.size(); ++v) {
    const double r = s.radius(v);
    EXPECT_EQ(bool(nested[v]), s.passable[v] && r > 0.13 && r < 0.27) << "vertex " << v << " at radius " << r;
  }
}

TEST(NestedOutsides, NothingEnclosedMarksNothing) {
  // One sphere: its inside is at depth 1.
  const Shells s(16, {0.25}, 0.05);
  const std::vector<char> nested = s.nested();
  EXPECT_EQ(std::count(nested.begin(), nested.end(), 1), 0);
}

// End to end. Tolerances follow from the stopping test (level_set_reconstruction_test.cpp):
// when converged every output vertex lies within 2 eps (r.tolerance) of the sampled curves.
TEST(NestedOutsides, AnAnnulusGivesBothCurvesTheInnerOneReversed) {
  const Circle outer{Vec<2>(0, 0), 1.0}, inner{Vec<2>(0, 0), 0.5};
  Points<2> data = outer.sample(1600);
  for (const auto& p : inner.sample(800)) data.push_back(p);
  const auto r = reconstruct<2>(data);
  EXPECT_EQ(r.status, ReconstructionStatus::converged);
  ASSERT_EQ(r.loops.size(), 2u);
  const double eps = r.tolerance;
  double outer_area = 0.0, inner_area = 0.0;  // signed, from the oriented segments
  for (const auto& f : r.surface.facets) {
    const Vec<2>& a = r.surface.vertices[f[0]];
    const Vec<2>& b = r.surface.vertices[f[1]];
    EXPECT_LE(std::min(std::abs(outer.signed_distance(a)), std::abs(inner.signed_distance(a))), 2 * eps);
    (a.norm() > 0.75 ? outer_area : inner_area) += 0.5 * (a.x() * b.y() - a.y() * b.x());
  }
  // Opposite senses (the annulus's inside lies on one side of both), each area within the
  // band of 2 eps round its circle.
  EXPECT_LT(outer_area * inner_area, 0.0);
  EXPECT_NEAR(std::abs(outer_area), kPi, kPi * (std::pow(1.0 + 2 * eps, 2) - 1.0));
  EXPECT_NEAR(std::abs(inner_area), kPi * 0.25, kPi * (std::pow(0.5 + 2 * eps, 2) - 0.25));
}

TEST(NestedOutsides, AHollowBallGivesTwoSpheresTheInnerOneFacingItsCentre) {
  const Sphere outer{Vec<3>(0, 0, 0), 1.0}, inner{Vec<3>(0, 0, 0), 0.5};
  Points<3> data = outer.sample(12000);
  for (const auto& p : inner.sample(3000)) data.push_back(p);  // the same density
  const auto r = reconstruct<3>(data);
  EXPECT_EQ(r.status, ReconstructionStatus::converged);
  const SurfaceTopology t = analyze_surface(r.surface.vertices, r.surface.facets);
  EXPECT_TRUE(t.watertight && t.edge_manifold && t.vertex_manifold && t.oriented);
  EXPECT_EQ(t.components, 2);
  EXPECT_EQ(t.genus, (std::vector<int>{0, 0}));
  const double eps = r.tolerance;
  for (const auto& v : r.surface.vertices) {
    EXPECT_LE(std::min(std::abs(outer.signed_distance(v)), std::abs(inner.signed_distance(v))), 2 * eps);
  }
  // Each sphere's signed volume (the divergence theorem on its facets): the inner one faces its
  // centre, so its volume is negative, and each lies within the band of 2 eps round its sphere.
  double outer_volume = 0.0, inner_volume = 0.0;
  for (const auto& f : r.surface.facets) {
    const Vec<3>& a = r.surface.vertices[f[0]];
    (a.norm() > 0.75 ? outer_volume : inner_volume) += a.dot(r.surface.vertices[f[1]].cross(r.surface.vertices[f[2]])) / 6.0;
  }
  const auto ball = [](double radius) { return 4.0 / 3.0 * kPi * std::pow(radius, 3); };
  EXPECT_GT(outer_volume, ball(1.0 - 2 * eps));
  EXPECT_LT(outer_volume, ball(1.0 + 2 * eps));
  EXPECT_LT(inner_volume, -ball(0.5 - 2 * eps));
  EXPECT_GT(inner_volume, -ball(0.5 + 2 * eps));
}

}  // namespace
}  // namespace lsr
