// SPDX-License-Identifier: BSD-3-Clause
/// @file stopping_test_test.cpp
/// @brief Both sides of the stopping test, and the pins, on fields whose values are known at
/// the data: linear fields are interpolated exactly by P1.
#include "evolution/pinning.h"
#include "evolution/stopping_test.h"

#include "geometry/nearest_point_index.h"
#include "lsrecon/core/level_set_extraction.h"
#include "mesh/adaptive_refinement.h"

#include <gtest/gtest.h>

namespace lsr::detail {
namespace {

struct Fixture {
  AdaptiveMesh<2> adaptive;
  Points<2> data;
  std::vector<Location<2>> at;
  Eigen::VectorXd u;  // x - 0.5: the front is the line x = 0.5
  Fixture() {
    data = {Vec<2>(0.5, 0.5), Vec<2>(0.6, 0.3), Vec<2>(0.3, 0.7)};
    AdaptiveMeshOptions o;
    o.h_min = 1.0 / 64;
    adaptive = build_adaptive_mesh(NearestPointIndex<2>(data), o);
    at = locate_all(adaptive, data, 1);
    u.resize(Eigen::Index(adaptive.mesh.vertices.size()));
    for (std::size_t v = 0; v < adaptive.mesh.vertices.size(); ++v) u[Eigen::Index(v)] = adaptive.mesh.vertices[v].x() - 0.5;
  }
};

TEST(StoppingTest, TheDataSideIsEachPointsValueInItsTolerance) {
  const Fixture f;
  const std::vector<double> r = data_residuals(f.at, f.u, {0.1, 0.05, 0.4});
  ASSERT_EQ(r.size(), 3u);
  EXPECT_NEAR(r[0], 0.0, 1e-12);
  EXPECT_NEAR(r[1], 0.1 / 0.05, 1e-12);
  EXPECT_NEAR(r[2], 0.2 / 0.4, 1e-12);
  EXPECT_NEAR(median_on_data(f.at, f.u), 0.0, 1e-12);
}

TEST(StoppingTest, TheFrontSideIsTheWorstDistanceAlongTheFront) {
  const Fixture f;
  const std::vector<double> values(f.u.data(), f.u.data() + f.u.size());
  const LevelSetMesh<2> front = extract_zero_level_set(f.adaptive.mesh, values);
  ASSERT_FALSE(front.sources.empty());
  // d = |y - 0.5| (linear on each side of y = 0.5 along the front x = 0.5, exact where the
  // front's edges do not cross y = 0.5), tolerance 0.1: the worst is at the front's ends
  // y = 0 or 1, 0.5 / 0.1.
  Eigen::VectorXd d(f.u.size());
  for (std::size_t v = 0; v < f.adaptive.mesh.vertices.size(); ++v) d[Eigen::Index(v)] = std::abs(f.adaptive.mesh.vertices[v].y() - 0.5);
  const Eigen::VectorXd tolerance = Eigen::VectorXd::Constant(f.u.size(), 0.1);
  EXPECT_NEAR(max_front_distance(front, d, tolerance, {}), 5.0, 1e-9);
  // Vertices ignored count as on the data.
  EXPECT_EQ(max_front_distance(front, d, tolerance, std::vector<char>(std::size_t(f.u.size()), 1)), 0.0);
}

TEST(Pinning, AReachedPointHoldsItsSimplexAndItsCell) {
  const Fixture f;
  const std::size_t nv = f.adaptive.mesh.vertices.size();
  std::vector<double> dist;
  std::vector<Index> nearest;
  NearestPointIndex<2>(f.data).query(f.adaptive.mesh.vertices, dist, &nearest, 1);
  const Eigen::VectorXd scale = Eigen::VectorXd::Constant(Eigen::Index(nv), 0.02);
  const VertexCells cells = pin_cells(scale, f.data.size(), dist, nearest, 2.0);
  // The cells: every vertex within 2 scales of its nearest point, listed under that point.
  std::size_t listed = 0;
  for (std::size_t i = 0; i < f.data.size(); ++i) {
    for (Index k = cells.offsets[i]; k < cells.offsets[i + 1]; ++k) {
      EXPECT_EQ(std::size_t(nearest[std::size_t(cells.vertices[std::size_t(k)])]), i);
      EXPECT_LE(dist[std::size_t(cells.vertices[std::size_t(k)])], 0.04);
      ++listed;
    }
  }
  EXPECT_EQ(listed, std::size_t(std::count_if(dist.begin(), dist.end(), [](double x) { return x <= 0.04; })));
  // With alpha > 0 the front reaches a point once u >= -reach there: only the first (u = 0).
  std::vector<char> pinned(3, 0), held(nv, 0);
  Eigen::VectorXd d = Eigen::VectorXd::Ones(Eigen::Index(nv));
  pin_reached_data(f.at, cells, f.u, 2.0, {0.01, 0.01, 0.01}, pinned, d, held);
  EXPECT_EQ(pinned, (std::vector<char>{1, 1, 0}));  // the second: u = +0.1, passed
  for (Index k = cells.offsets[0]; k < cells.offsets[1]; ++k) {
    EXPECT_EQ(held[std::size_t(cells.vertices[std::size_t(k)])], 1);
    EXPECT_EQ(d[cells.vertices[std::size_t(k)]], 0.0);
  }
  for (Index k = cells.offsets[2]; k < cells.offsets[3]; ++k) EXPECT_EQ(held[std::size_t(cells.vertices[std::size_t(k)])], 0);
}

}  // namespace
}  // namespace lsr::detail
