// SPDX-License-Identifier: BSD-3-Clause
/// @file simplex_geometry_test.cpp
#include "lsrecon/core/simplex_geometry.h"
#include "lsrecon/testdata/analytic_shapes.h"
#include "mesh/adaptive_refinement.h"

#include <gtest/gtest.h>

namespace lsr {
namespace {

template <int D>
void check_geometry(const SimplexMesh<D>& mesh) {
  const SimplexGeometry<D> g = compute_simplex_geometry(mesh);
  const Vec<D> a = Vec<D>::LinSpaced(1.5, -0.5);
  double total = 0.0;
  for (std::size_t s = 0; s < mesh.simplices.size(); ++s) {
    total += g.measure[s];
    Vec<D> sum = Vec<D>::Zero();
    Vec<D> grad_linear = Vec<D>::Zero();
    for (int k = 0; k <= D; ++k) {
      sum += g.gradients[s][k];
      grad_linear += a.dot(mesh.vertices[mesh.simplices[s][k]]) * g.gradients[s][k];
      // grad lambda_k . (x_j - x_0) = delta_kj - delta_k0
      for (int j = 1; j <= D; ++j) {
        const double expected = (k == j) - (k == 0);
        const Vec<D> e = mesh.vertices[mesh.simplices[s][j]] - mesh.vertices[mesh.simplices[s][0]];
        EXPECT_NEAR(g.gradients[s][k].dot(e), expected, 1e-9);
      }
    }
    EXPECT_LE(sum.norm(), 1e-9 / g.measure[s]);
    EXPECT_LE((grad_linear - a).norm(), 1e-9);  // P1 gradient of a linear function is exact
  }
  EXPECT_NEAR(total, 1.0, 1e-10);  // the mesh tiles the unit box (round-off ~ #S eps)
  double balls = 0.0;
  for (double b : g.ball_measure) balls += b;
  EXPECT_NEAR(balls, (D + 1) * total, 1e-10);  // each simplex is in D + 1 balls
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    for (Index k = g.ball_offsets[v]; k < g.ball_offsets[v + 1]; ++k) {
      const auto& s = mesh.simplices[g.ball_simplices[k]];
      EXPECT_NE(std::find(s.begin(), s.end(), Index(v)), s.end());
    }
  }
  // The edge graph from these balls is the one listed from the mesh alone.
  const VertexNeighbours from_mesh = vertex_neighbours(mesh), from_balls = vertex_neighbours(mesh, g);
  EXPECT_EQ(from_balls.offsets, from_mesh.offsets);
  EXPECT_EQ(from_balls.neighbours, from_mesh.neighbours);
  EXPECT_GT(from_mesh.neighbours.size(), mesh.vertices.size());
}

TEST(SimplexGeometry, GradientsMeasuresAndBalls2D) {
  AdaptiveMeshOptions o;
  o.h_min = 1.0 / 128;
  check_geometry(
      build_adaptive_mesh(NearestPointIndex<2>(Circle{Vec<2>(0.5, 0.5), 0.3}.sample(500)), o).mesh);
}

TEST(SimplexGeometry, GradientsMeasuresAndBalls3D) {
  AdaptiveMeshOptions o;
  o.h_min = 1.0 / 32;
  check_geometry(
      build_adaptive_mesh(NearestPointIndex<3>(Sphere{Vec<3>(0.5, 0.5, 0.5), 0.3}.sample(2000)), o)
          .mesh);
}

TEST(SimplexGeometry, RejectsDegenerateSimplices) {
  SimplexMesh<2> flat;
  flat.vertices = {Vec<2>(0, 0), Vec<2>(1, 0), Vec<2>(2, 0)};
  flat.simplices = {{0, 1, 2}};
  EXPECT_THROW(compute_simplex_geometry(flat), InvalidInput);
}

}  // namespace
}  // namespace lsr
