// SPDX-License-Identifier: BSD-3-Clause
/// @file closed_surface_test.cpp
/// @brief The output surface is closed even where the field reaches the box, and keeps only
/// parts that data support.
#include "surface/closed_surface.h"

#include "mesh/kuhn_bisection.h"
#include "surface/surface_topology.h"

#include <gtest/gtest.h>

namespace lsr::detail {
namespace {

TEST(ClosedSurface, AFieldThatReachesTheWallsIsCappedInsideThem) {
  // A slab |z - 0.5| < 0.6 crosses the whole box: uncapped, its zero set would be open at the walls.
  const SimplexMesh<3> mesh = leaf_mesh(KuhnBisectionForest<3>(12)).mesh;
  std::vector<double> values;
  for (const auto& x : mesh.vertices) values.push_back(std::abs(x.z() - 0.5) - 0.6);
  const Points<3> data = {Vec<3>(0.5, 0.5, 0.5), Vec<3>(0.2, 0.5, 0.5), Vec<3>(0.5, 0.2, 0.5), Vec<3>(0.5, 0.5, 0.2)};
  const LevelSetMesh<3> s = extract_closed_surface(mesh, data, values, 1);
  const SurfaceTopology t = analyze_surface(s.vertices, s.facets);
  EXPECT_TRUE(t.watertight);
  EXPECT_EQ(t.components, 1);
  EXPECT_EQ(t.genus, std::vector<int>{0});
  for (const auto& x : s.vertices) {
    for (int k = 0; k < 3; ++k) EXPECT_TRUE(x[k] >= 0.0 && x[k] <= 1.0);
  }
}

TEST(ClosedSurface, APartNoDataPointIsNearestToGoes) {
  // Two balls; the data sample one.
  const SimplexMesh<3> mesh = leaf_mesh(KuhnBisectionForest<3>(24)).mesh;
  std::vector<double> values;
  for (const auto& x : mesh.vertices) {
    values.push_back(std::min((x - Vec<3>(0.3, 0.5, 0.5)).norm() - 0.15, (x - Vec<3>(0.75, 0.5, 0.5)).norm() - 0.1));
  }
  Points<3> data;
  for (int i = 0; i < 50; ++i) {
    const double a = 0.4 * i, b = 0.13 * i;
    data.push_back(Vec<3>(0.3, 0.5, 0.5) + 0.15 * Vec<3>(std::cos(a) * std::sin(b), std::sin(a) * std::sin(b), std::cos(b)));
  }
  const LevelSetMesh<3> s = extract_closed_surface(mesh, data, values, 1);
  EXPECT_EQ(analyze_surface(s.vertices, s.facets).components, 1);
  for (const auto& x : s.vertices) EXPECT_LT(x.x(), 0.5);
}

}  // namespace
}  // namespace lsr::detail
