// SPDX-License-Identifier: BSD-3-Clause
/// @file start_fields_test.cpp
/// @brief The starts: circles around or inside the data, the tagged start hugging it from
/// outside, the caller's function and its refusal.
#include "start/start_fields.h"

#include "lsrecon/core/errors.h"
#include "lsrecon/testdata/analytic_shapes.h"
#include "mesh/adaptive_refinement.h"
#include "sampling/local_sampling.h"

#include <gtest/gtest.h>

namespace lsr::detail {
namespace {

struct Circle2D {
  NearestPointIndex<2> data;
  AdaptiveMesh<2> adaptive;
  VertexNeighbours neighbours;
  LocalSampling<2> sampling;
  std::vector<double> dist;
  Eigen::VectorXd distance, scale;
  UnitBoxTransform<2> box;
  Circle2D()
      : data(Circle{Vec<2>(0.5, 0.5), 0.3}.sample(600)),
        box(UnitBoxTransform<2>::fit_ball(data.points(), kDataRadius)) {
    AdaptiveMeshOptions o;
    o.h_min = 1.0 / 256;
    adaptive = build_adaptive_mesh(data, o);
    neighbours = vertex_neighbours(adaptive.mesh, compute_simplex_geometry(adaptive.mesh, false), 1);
    sampling = estimate_local_sampling(data, 1, HeightFieldsAt::none);
    data.query(adaptive.mesh.vertices, dist, nullptr, 1);
    distance = Eigen::Map<const Eigen::VectorXd>(dist.data(), Eigen::Index(dist.size()));
    scale = Eigen::VectorXd::Constant(distance.size(), median(sampling.spacing));
  }
  StartField<2> start(const ReconstructionOptions& o, const SignedDistance<2>* custom = nullptr) const {
    return start_field<2>(adaptive.mesh, neighbours, data, sampling, distance, distance, dist, scale, o, 0.0,
                       std::numeric_limits<double>::infinity(), 1.0 / 256, custom, box);
  }
  double radius(std::size_t v) const { return (adaptive.mesh.vertices[v] - Vec<2>(0.5, 0.5)).norm(); }
};

TEST(StartFields, TheTaggedStartHugsTheDataAGapAway) {
  const Circle2D c;
  ReconstructionOptions o;
  const StartField<2> s = c.start(o);
  ASSERT_TRUE(s.tagged);
  // Negative inside the flood's boundary (which lies gap_factor scales outside the circle, up
  // to a mesh size), positive in the flood: u0 < 0 at the data and at the centre.
  const double gap = o.sampling.gap_factor * c.scale[0], h = 1.0 / 256;
  for (std::size_t v = 0; v < c.adaptive.mesh.vertices.size(); ++v) {
    const double r = c.radius(v);
    if (r < 0.3 + gap - 2 * h) {
      EXPECT_LT(s.u[Eigen::Index(v)], 0.0) << r;
    }
    if (r > 0.3 + gap + 2 * h && c.dist[v] > gap + 2 * h) {
      EXPECT_GT(s.u[Eigen::Index(v)], 0.0) << r;
    }
  }
}

TEST(StartFields, CirclesAroundOrInsideTheData) {
  const Circle2D c;
  ReconstructionOptions o;
  o.start.initial_front = InitialFront::enclosing;
  const StartField<2> around = c.start(o);
  o.start.initial_front = InitialFront::inside;
  const StartField<2> inside = c.start(o);
  EXPECT_FALSE(around.tagged);
  for (std::size_t v = 0; v < c.adaptive.mesh.vertices.size(); ++v) {
    // Around: the circle of radius 0.45 about the box centre, a signed distance.
    EXPECT_NEAR(around.u[Eigen::Index(v)], c.radius(v) - kEnclosingRadius, 1e-12);
  }
  // Inside: half the centroid's distance to the data, about 0.15 about (0.5, 0.5).
  EXPECT_LT(inside.u.minCoeff(), -0.1);
  for (std::size_t v = 0; v < c.adaptive.mesh.vertices.size(); ++v) {
    if (c.radius(v) > 0.2) {
      EXPECT_GT(inside.u[Eigen::Index(v)], 0.0);
    }
  }
}

TEST(StartFields, TheCallersFunctionIsTakenInInputUnitsOrRefused) {
  const Circle2D c;
  ReconstructionOptions o;
  // In input coordinates: the box maps the unit box onto them, u is scaled back.
  const SignedDistance<2> f = [&](const Vec<2>& x) { return (x - c.box.from_unit(Vec<2>(0.5, 0.5))).norm() - 0.2 / c.box.scale(); };
  const StartField<2> s = c.start(o, &f);
  for (std::size_t v = 0; v < c.adaptive.mesh.vertices.size(); v += 97) EXPECT_NEAR(s.u[Eigen::Index(v)], c.radius(v) - 0.2, 1e-9);
  const SignedDistance<2> positive = [](const Vec<2>&) { return 1.0; };
  EXPECT_THROW(c.start(o, &positive), InvalidInput);
  const SignedDistance<2> throws = [](const Vec<2>&) -> double { throw std::runtime_error("no"); };
  EXPECT_THROW(c.start(o, &throws), InvalidInput);
}

}  // namespace
}  // namespace lsr::detail
