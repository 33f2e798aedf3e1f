// SPDX-License-Identifier: BSD-3-Clause
/// @file front_evolution_test.cpp
/// @brief The time loop alone, on a circle's samples from the tagged start: it converges within
/// the steps ln(d0 / eps) / (alpha dt) predicts, keeps its best iterate, honours max_iterations
/// and cancellation.
#include "evolution/evolution_settings.h"
#include "evolution/front_evolution.h"
#include "start/start_fields.h"

#include "lsrecon/core/errors.h"
#include "lsrecon/testdata/analytic_shapes.h"
#include "mesh/adaptive_refinement.h"
#include "sampling/local_sampling.h"

#include <gtest/gtest.h>

#include <cmath>

namespace lsr::detail {
namespace {

struct Loop {
  NearestPointIndex<2> data{Circle{Vec<2>(0.5, 0.5), 0.3}.sample(800)};
  AdaptiveMesh<2> adaptive;
  VertexNeighbours neighbours;
  P1Operators<2> ops;
  LocalSampling<2> sampling;
  std::vector<double> dist;
  std::vector<Index> nearest;
  Eigen::VectorXd distance, scale, noise;
  std::vector<Location<2>> at;
  VertexCells cells;
  ReconstructionOptions o;
  EvolutionSettings settings;
  Points<2> away;
  std::vector<char> near_hole;
  std::vector<Index> represented;  // one point each
  std::vector<char> tested_points, tested_vertices;  // every point and vertex
  Eigen::VectorXd u0;

  Loop() {
    AdaptiveMeshOptions mo;
    mo.h_min = 1.0 / 256;
    adaptive = build_adaptive_mesh(data, mo);
    const SimplexGeometry<2> geometry = compute_simplex_geometry(adaptive.mesh, false);
    neighbours = vertex_neighbours(adaptive.mesh, geometry, 1);
    ops = assemble_p1_operators(adaptive.mesh, geometry, false, &neighbours, 1);
    sampling = estimate_local_sampling(data, 1, HeightFieldsAt::none);
    data.query(adaptive.mesh.vertices, dist, &nearest, 1);
    distance = Eigen::Map<const Eigen::VectorXd>(dist.data(), Eigen::Index(dist.size()));
    const double l = std::max(median(sampling.spacing), 1.0 / 256);
    scale = Eigen::VectorXd::Constant(distance.size(), l);
    noise = Eigen::VectorXd::Zero(distance.size());
    at = locate_all(adaptive, data.points(), 1);
    cells = pin_cells(scale, data.points().size(), dist, nearest, o.evolution.pin_factor);
    settings = resolve_evolution_settings(o, scale, noise, std::vector<double>(data.points().size(), l), l, false);
    u0 = start_field<2>(adaptive.mesh, neighbours, data, sampling, distance, distance, dist, scale, o, 0.0, settings.schedule.band,
                     1.0 / 256, nullptr, UnitBoxTransform<2>::fit_ball(data.points(), kDataRadius)).u;
    away = Points<2>(dist.size(), Vec<2>::Zero());
    for (std::size_t v = 0; v < dist.size(); ++v) {
      if (dist[v] > 0.0) away[v] = (adaptive.mesh.vertices[v] - data.points()[std::size_t(nearest[v])]) / dist[v];
    }
  }
  FrontProblem<2> problem() const {
    return {adaptive.mesh, neighbours, ops,  at,   cells,     settings.eps, settings.reach, settings.front_tolerance,
            scale,         dist,       away, near_hole, represented, tested_points, tested_vertices};
  }
};

TEST(FrontEvolution, ConvergesFromTheTaggedStartInThePredictedSteps) {
  const Loop l;
  const FrontProblem<2> p = l.problem();
  FrontEvolution<2> e(p, l.o, l.settings.schedule, l.settings.step);
  ReconstructionResult<2> r;
  std::map<std::string, double> seconds;
  std::vector<std::string> stages;
  StageClock clock(seconds, stages);
  Eigen::VectorXd d = l.distance;
  e.run(l.u0, d, r, Progress(), clock, l.settings.median_eps, 1.0);
  EXPECT_EQ(r.status, ReconstructionStatus::converged);
  EXPECT_LE(e.best_residual(), 1.0);
  EXPECT_EQ(r.best_iteration, r.iterations);
  // The start lies gap_factor + 1/2... scales out; the gap closes by exp(-|alpha| dt) a step:
  // ln(d0 / eps) / (alpha dt) steps, d0 <= (gap_factor + 1) l, eps = l.
  const double predicted = std::log(l.o.sampling.gap_factor + 1.0) / (std::abs(l.settings.step.alpha) * l.settings.step.time_step);
  EXPECT_LE(r.iterations, int(std::ceil(predicted)) + 2 * l.settings.schedule.interval);
  EXPECT_EQ(r.residual_history.size(), std::size_t(r.iterations));
  EXPECT_EQ(stages, (std::vector<std::string>{"solve", "stopping test", "renormalize"}));
  // The best iterate is a front on the circle: u at the data within eps.
  for (const auto& loc : l.at) EXPECT_LE(std::abs(interpolate(loc, e.best())), l.settings.eps[0]);
}

TEST(FrontEvolution, StopsAtMaxIterationsOrWhenCancelledWithItsBestIterate) {
  Loop l;
  // Two steps: the front side is first measured at the renormalisation of step 2.
  l.o.stopping.max_iterations = 2;
  const FrontProblem<2> p = l.problem();
  std::map<std::string, double> seconds;
  std::vector<std::string> stages;
  StageClock clock(seconds, stages);
  {
    FrontEvolution<2> e(p, l.o, l.settings.schedule, l.settings.step);
    ReconstructionResult<2> r;
    Eigen::VectorXd d = l.distance;
    e.run(l.u0, d, r, Progress(), clock, l.settings.median_eps, 1.0);
    EXPECT_EQ(r.status, ReconstructionStatus::not_converged);
    EXPECT_EQ(r.iterations, 2);
    EXPECT_EQ(r.best_iteration, 2);
    EXPECT_TRUE(std::isinf(r.residual_history[0]));
  }
  l.o.stopping.max_iterations = 1000;
  FrontEvolution<2> e(p, l.o, l.settings.schedule, l.settings.step);
  ReconstructionResult<2> r;
  Eigen::VectorXd d = l.distance;
  int calls = 0;
  e.run(l.u0, d, r, Progress([&](const std::string&, double) { return ++calls < 3; }), clock, l.settings.median_eps, 1.0);
  EXPECT_EQ(r.status, ReconstructionStatus::cancelled);
  EXPECT_EQ(r.iterations, 2);
  EXPECT_EQ(r.best_iteration, 2);
  EXPECT_TRUE(std::isfinite(e.best_residual()));
}

}  // namespace
}  // namespace lsr::detail
