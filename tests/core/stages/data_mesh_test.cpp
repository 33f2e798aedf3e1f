// SPDX-License-Identifier: BSD-3-Clause
/// @file data_mesh_test.cpp
/// @brief The mesh stage: sizes within the resolution limits, the points' scales raised to a
/// coarser mesh; and what each vertex takes from its nearest data point.
#include "mesh/data_mesh.h"
#include "mesh/vertex_fields.h"

#include "lsrecon/testdata/analytic_shapes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace lsr::detail {
namespace {

TEST(DataMesh, AResolutionCapRaisesThePointsScalesToTheMeshSize) {
  const NearestPointIndex<3> data(Sphere{Vec<3>(0.5, 0.5, 0.5), 0.3}.sample(4000));
  std::vector<double> scale(data.points().size(), 0.001);  // finer than any cap
  ReconstructionOptions o;
  o.mesh.max_resolution = 64;
  double h_min = 0.0;
  const AdaptiveMesh<3> m = data_mesh(data, scale, o, 1 << 30, Progress(), h_min);
  EXPECT_EQ(h_min, 1.0 / 64);
  for (double s : scale) EXPECT_EQ(s, 1.0 / 64);
  EXPECT_GT(m.mesh.vertices.size(), 1000u);
}

TEST(VertexFields, DistanceNearestScaleAndTheWayAwayFromTheData) {
  const Points<3> points = {Vec<3>(0.5, 0.5, 0.5), Vec<3>(0.2, 0.3, 0.4)};
  const NearestPointIndex<3> data(points);
  SimplexMesh<3> mesh;
  mesh.vertices = {Vec<3>(0.5, 0.5, 0.9), Vec<3>(0.2, 0.3, 0.4), Vec<3>(0.1, 0.3, 0.4)};
  LocalSampling<3> sampling;
  sampling.noise = {0.01, 0.02};
  const VertexFields<3> f = vertex_fields(data, mesh, sampling, {0.1, 0.2}, 1);
  EXPECT_NEAR(f.dist[0], 0.4, 1e-12);
  EXPECT_EQ(f.dist[1], 0.0);
  EXPECT_EQ(f.nearest, (std::vector<Index>{0, 1, 1}));
  EXPECT_EQ(f.scale[2], 0.2);
  EXPECT_EQ(f.noise[0], 0.01);
  EXPECT_EQ(f.distance[0], f.dist[0]);
  const Points<3> away = away_from_data(data, mesh, f);
  EXPECT_NEAR((away[0] - Vec<3>(0, 0, 1)).norm(), 0.0, 1e-12);
  EXPECT_EQ(away[1], Vec<3>::Zero());  // on the data
  EXPECT_NEAR((away[2] - Vec<3>(-1, 0, 0)).norm(), 0.0, 1e-12);
}

}  // namespace
}  // namespace lsr::detail
