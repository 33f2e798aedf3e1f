// SPDX-License-Identifier: BSD-3-Clause
/// @file surface_distance_test.cpp
/// @brief The comparison metrics against an independent analytic check.
#include "lsrecon/core/level_set_extraction.h"
#include "lsrecon/testdata/analytic_shapes.h"
#include "lsrecon/testdata/surface_distance.h"
#include "mesh/adaptive_refinement.h"

#include <gtest/gtest.h>

namespace lsr {
namespace {

// A fine mesh of the sphere r = 0.3 (marching tetrahedra of its exact signed distance).
LevelSetMesh<3> sphere_mesh(double r) {
  const Sphere s{Vec<3>(0.5, 0.5, 0.5), r};
  AdaptiveMeshOptions o;
  o.h_min = 1.0 / 128;
  const AdaptiveMesh<3> m = build_adaptive_mesh(NearestPointIndex<3>(s.sample(40000)), o);
  std::vector<double> u(m.mesh.vertices.size());
  for (std::size_t i = 0; i < u.size(); ++i) u[i] = s.signed_distance(m.mesh.vertices[i]);
  return extract_zero_level_set(m.mesh, u);
}

TEST(SurfaceDistance, AnInflatedSphereIsDeltaAwayAndTheMetricsSaySo) {
  const Sphere truth{Vec<3>(0.5, 0.5, 0.5), 0.3};
  const Points<3> samples = truth.sample(50000);
  auto sdf = [&](const Vec<3>& p) { return truth.signed_distance(p); };
  const LevelSetMesh<3> exact = sphere_mesh(0.3);
  const SurfaceDistances base = compare_to_truth(exact.vertices, exact.facets, sdf, samples);
  // The mesh of the sphere itself: within the chordal error of its triangles (edge <= sqrt 3 h).
  const double chord = 3.0 / (128.0 * 128.0) / (8 * 0.3);
  EXPECT_LE(base.hausdorff, 2 * chord);
  EXPECT_GT(base.normal_consistency, 0.999);
  for (double delta : {0.01, 0.03}) {
    const LevelSetMesh<3> inflated = sphere_mesh(0.3 + delta);
    const SurfaceDistances d = compare_to_truth(inflated.vertices, inflated.facets, sdf, samples);
    EXPECT_NEAR(d.chamfer, delta, 2 * chord);
    EXPECT_NEAR(d.hausdorff, delta, 2 * chord);
    EXPECT_NEAR(d.mean_to_truth, delta, 2 * chord);
    EXPECT_NEAR(d.mean_from_truth, delta, 2 * chord);
  }
  // Flipped triangles: normal consistency -1.
  auto flipped = exact.facets;
  for (auto& f : flipped) std::swap(f[0], f[1]);
  EXPECT_LT(compare_to_truth(exact.vertices, flipped, sdf, samples).normal_consistency, -0.999);
  EXPECT_TRUE(std::isinf(compare_to_truth(exact.vertices, {}, sdf, samples).chamfer));
}

}  // namespace
}  // namespace lsr
