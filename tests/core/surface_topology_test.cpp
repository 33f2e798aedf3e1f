// SPDX-License-Identifier: BSD-3-Clause
/// @file surface_topology_test.cpp
#include "surface/surface_topology.h"

#include <gtest/gtest.h>

namespace lsr {
namespace {

// The boundary of the unit tetrahedron, outward oriented.
Points<3> tet_points() { return {Vec<3>(0, 0, 0), Vec<3>(1, 0, 0), Vec<3>(0, 1, 0), Vec<3>(0, 0, 1)}; }
std::vector<std::array<Index, 3>> tet_faces() { return {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}; }

TEST(SurfaceTopology, ClosedTetrahedron) {
  const SurfaceTopology t = analyze_surface(tet_points(), tet_faces());
  EXPECT_TRUE(t.watertight && t.edge_manifold && t.vertex_manifold && t.oriented);
  EXPECT_EQ(t.components, 1);
  EXPECT_EQ(t.genus, std::vector<int>{0});
  EXPECT_NEAR(t.signed_volume, 1.0 / 6.0, 1e-15);
}

TEST(SurfaceTopology, OpenFlippedAndPinchedSurfacesAreDetected) {
  auto faces = tet_faces();
  faces.pop_back();
  EXPECT_FALSE(analyze_surface(tet_points(), faces).watertight);

  faces = tet_faces();
  std::swap(faces[3][0], faces[3][1]);
  const SurfaceTopology flipped = analyze_surface(tet_points(), faces);
  EXPECT_TRUE(flipped.watertight);
  EXPECT_FALSE(flipped.oriented);

  // Two tetrahedra sharing only vertex 0: watertight and edge-manifold, not vertex-manifold.
  Points<3> p = tet_points();
  for (int k = 1; k < 4; ++k) p.push_back(-p[k]);
  faces = tet_faces();
  for (auto f : tet_faces()) {
    for (Index& v : f) v = v == 0 ? 0 : v + 3;
    faces.push_back(f);
  }
  const SurfaceTopology pinched = analyze_surface(p, faces);
  EXPECT_TRUE(pinched.watertight);
  EXPECT_FALSE(pinched.vertex_manifold);
}

TEST(SurfaceTopology, TwoSeparateTetrahedraAreTwoComponents) {
  Points<3> p = tet_points();
  auto faces = tet_faces();
  for (int k = 0; k < 4; ++k) p.push_back(p[k] + Vec<3>(5, 0, 0));
  for (auto f : tet_faces()) faces.push_back({f[0] + 4, f[1] + 4, f[2] + 4});
  const SurfaceTopology t = analyze_surface(p, faces);
  EXPECT_EQ(t.components, 2);
  EXPECT_EQ(t.genus, (std::vector<int>{0, 0}));
}

}  // namespace
}  // namespace lsr
