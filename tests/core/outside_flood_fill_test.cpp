// SPDX-License-Identifier: BSD-3-Clause
/// @file outside_flood_fill_test.cpp
/// @brief Components of vertex subsets and the flood from the box walls.
#include "mesh/kuhn_bisection.h"
#include "start/outside_flood_fill.h"

#include <gtest/gtest.h>

#include <set>

namespace lsr {
namespace {

SimplexMesh<3> uniform_mesh(int cells) {
  KuhnBisectionForest<3> forest(cells);
  forest.finish_refinement();
  SimplexMesh<3> mesh;
  mesh.vertices = forest.vertices();
  for (Index s = 0; s < Index(forest.simplices().size()); ++s) {
    if (forest.is_leaf(s)) mesh.simplices.push_back(forest.simplices()[s].v);
  }
  return mesh;
}

TEST(OutsideFloodFill, ReachesTheOutsideOfAShellButNotItsCavity) {
  // Passable everywhere but a spherical shell 0.2 < |x - c| < 0.3: the cavity inside is sealed.
  const SimplexMesh<3> mesh = uniform_mesh(32);
  std::vector<char> passable(mesh.vertices.size());
  for (std::size_t v = 0; v < passable.size(); ++v) {
    const double r = (mesh.vertices[v] - Vec<3>::Constant(0.5)).norm();
    passable[v] = r < 0.2 || r > 0.3;
  }
  const std::vector<char> out = flood_from_walls(mesh, passable);
  for (std::size_t v = 0; v < out.size(); ++v) {
    const double r = (mesh.vertices[v] - Vec<3>::Constant(0.5)).norm();
    EXPECT_EQ(bool(out[v]), r > 0.3) << "vertex " << v << " at radius " << r;
  }
  // Three components: the outside, the cavity and the shell's non-members (-1).
  const std::vector<Index> root = vertex_components(mesh, passable);
  std::set<Index> roots(root.begin(), root.end());
  EXPECT_EQ(roots.size(), 3u);
}

TEST(OutsideFloodFill, ALeakOfOneEdgeLetsTheFloodIn) {
  // The same shell with a hole one cell wide: a sampling hole wider than the gap.
  const SimplexMesh<3> mesh = uniform_mesh(32);
  std::vector<char> passable(mesh.vertices.size());
  for (std::size_t v = 0; v < passable.size(); ++v) {
    const Vec<3> x = mesh.vertices[v] - Vec<3>::Constant(0.5);
    const bool hole = std::abs(x.x()) < 0.04 && std::abs(x.y()) < 0.04 && x.z() > 0.0;
    passable[v] = x.norm() < 0.2 || x.norm() > 0.3 || hole;
  }
  const std::vector<char> out = flood_from_walls(mesh, passable);
  EXPECT_TRUE(out[mesh.vertices.size() / 2]);  // the centre (0.5, 0.5, 0.5) of a 33^3 grid
  EXPECT_TRUE((mesh.vertices[mesh.vertices.size() / 2] - Vec<3>::Constant(0.5)).norm() < 1e-12);
}

}  // namespace
}  // namespace lsr
