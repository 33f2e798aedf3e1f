// SPDX-License-Identifier: BSD-3-Clause
/// @file semi_implicit_step_test.cpp
/// @brief The SPD/CG step against the paper's unsymmetric form with GMRES, and its basic
/// properties.
#include "evolution/semi_implicit_step.h"
#include "lsrecon/testdata/analytic_shapes.h"
#include "mesh/adaptive_refinement.h"

#include <gtest/gtest.h>

namespace lsr {
namespace {

struct Problem2D {
  AdaptiveMesh<2> mesh;
  P1Operators<2> ops;
  Eigen::VectorXd d, u;
};

Problem2D problem(double h_min) {
  const Circle data{Vec<2>(0.5, 0.5), 0.25};
  const Circle start{Vec<2>(0.5, 0.5), 0.4};
  AdaptiveMeshOptions o;
  o.h_min = h_min;
  const NearestPointIndex<2> index(data.sample(4000));
  Problem2D p{build_adaptive_mesh(index, o), {}, {}, {}};
  p.ops = assemble_p1_operators(p.mesh.mesh, compute_simplex_geometry(p.mesh.mesh), true);
  std::vector<double> d;
  index.query(p.mesh.mesh.vertices, d);
  p.d = Eigen::Map<Eigen::VectorXd>(d.data(), Eigen::Index(d.size()));
  p.u.resize(p.d.size());
  for (Eigen::Index i = 0; i < p.u.size(); ++i) p.u[i] = start.signed_distance(p.mesh.mesh.vertices[i]);
  return p;
}

TEST(SemiImplicitStep, SymmetricCgMatchesThePaperFormWithGmres) {
  const Problem2D p = problem(1.0 / 128);
  for (double beta : {1e-4, 1e-2, 1.0}) {
    StepParameters s;
    s.time_step = 10.0 / 128;
    s.curvature_weight = beta;
    s.solver_tolerance = 1e-12;
    SolverReport cg, gmres;
    const Eigen::VectorXd a = semi_implicit_step(p.ops, p.d, p.u, s, &cg);
    s.solver = LinearSolver::gmres_reference;
    const Eigen::VectorXd b = semi_implicit_step(p.ops, p.d, p.u, s, &gmres);
    ASSERT_TRUE(cg.converged) << beta;
    ASSERT_TRUE(gmres.converged) << beta;
    // Both solve the same system to relative residual 1e-12; the solutions agree to that
    // times the condition number, far below the O(h) changes of a step.
    EXPECT_LE((a - b).cwiseAbs().maxCoeff(), 1e-8) << "beta " << beta;
    std::printf("beta %.0e: CG %d iterations, GMRES %d iterations\n", beta, cg.iterations, gmres.iterations);
  }
}

TEST(SemiImplicitStep, WithoutCurvatureItIsTheExplicitDataStep) {
  const Problem2D p = problem(1.0 / 64);
  StepParameters s;
  s.time_step = 0.1;
  s.curvature_weight = 0.0;
  const Eigen::VectorXd next = semi_implicit_step(p.ops, p.d, p.u, s);
  const Eigen::VectorXd a = p.ops.gradient_norms(p.u).cwiseMax(s.min_gradient);
  EXPECT_LE((next - (p.u + s.time_step * s.alpha * a.cwiseProduct(p.d))).cwiseAbs().maxCoeff(), 1e-12);
}

// The stepper keeps its vectors from one step to the next; nothing of a step may leak into the
// next: reused over steps whose parameters change, it gives the fresh step's u to the bit.
// Also after its vectors were released between two steps.
TEST(SemiImplicitStep, AReusedStepperGivesTheFreshStep) {
  const Problem2D p = problem(1.0 / 64);
  SemiImplicitStepper<2> stepper(p.ops);
  Eigen::VectorXd reused = p.u, fresh = p.u;
  std::vector<char> held(std::size_t(p.u.size()), 0);
  for (int n = 0; n < 6; ++n) {
    StepParameters s;
    s.time_step = 0.05;
    s.curvature_weight = n == 2 ? 0.0 : 1e-3;
    if (n >= 3) s.curvature_weights = Eigen::VectorXd::Constant(p.u.size(), 1e-3 * (n - 2));
    if (n >= 4) {
      for (std::size_t v = 0; v < held.size(); v += 7) held[v] = 1;
      s.held = &held;
    }
    SolverReport a, b;
    if (n == 1 || n == 4) stepper.release();  // as the time loop does before a renormalisation
    stepper.advance(p.d, reused, s, &a);
    fresh = semi_implicit_step(p.ops, p.d, fresh, s, &b);
    ASSERT_EQ(a.iterations, b.iterations) << "step " << n;
    ASSERT_TRUE((reused.array() == fresh.array()).all()) << "step " << n;
  }
  EXPECT_GT((reused - p.u).cwiseAbs().maxCoeff(), 0.0);
}

}  // namespace
}  // namespace lsr
