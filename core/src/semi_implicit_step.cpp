// SPDX-License-Identifier: BSD-3-Clause
/// @file semi_implicit_step.cpp
#include "lsrecon/core/semi_implicit_step.h"

#include <unsupported/Eigen/IterativeSolvers>

#include <stdexcept>

namespace lsr {
namespace {

// 1 on the vertices the solve updates, 0 on the walls and the held vertices.
template <int D>
Eigen::VectorXd wall_mask(const P1Operators<D>& ops, const StepParameters& p) {
  Eigen::VectorXd interior(ops.on_boundary.size());
  for (std::size_t i = 0; i < ops.on_boundary.size(); ++i) {
    interior[i] = ops.on_boundary[i] || (p.held && (*p.held)[i]) ? 0.0 : 1.0;
  }
  return interior;
}

// Explicit data-term update, used as it is on the walls and as the start elsewhere.
Eigen::VectorXd advance_by_data(const Eigen::VectorXd& u, const Eigen::VectorXd& a,
                                const Eigen::VectorXd& d, const StepParameters& p) {
  return u + p.time_step * p.alpha * a.cwiseProduct(d);
}

template <int D>
Eigen::VectorXd step_cg(const P1Operators<D>& ops, const Eigen::VectorXd& d,
                        const Eigen::VectorXd& u, const Eigen::VectorXd& a,
                        const StepParameters& p, SolverReport* report) {
  const Eigen::VectorXd interior = wall_mask(ops, p);
  const Eigen::VectorXd lambda_over_a = ops.ball_measure.cwiseQuotient(a);
  const bool per_vertex = p.curvature_weights.size() > 0;
  const SymmetricCurvatureOperator<D> curvature(ops, a, per_vertex ? &p.curvature_weights : nullptr);
  const double c = p.time_step * (per_vertex ? 1.0 : p.curvature_weight);
  auto apply = [&](const Eigen::VectorXd& v) -> Eigen::VectorXd {
    Eigen::VectorXd out = lambda_over_a.cwiseProduct(v);
    if (c > 0.0) out += c * curvature.apply(v);
    return out;
  };
  const Eigen::VectorXd b = lambda_over_a.cwiseProduct(u) +
                            p.time_step * p.alpha * ops.ball_measure.cwiseProduct(d);

  // Walls take their data-term value; the interior starts from u (warm start) and solves for
  // a correction delta that is zero on the walls.
  Eigen::VectorXd x = interior.cwiseProduct(u) +
                      (Eigen::VectorXd::Ones(u.size()) - interior).cwiseProduct(advance_by_data(u, a, d, p));
  const Eigen::VectorXd residual = interior.cwiseProduct(b - apply(x));
  Eigen::VectorXd diag = lambda_over_a;
  if (c > 0.0) diag += c * curvature.diagonal();
  const Eigen::VectorXd inverse_diag = interior.cwiseQuotient(diag);
  auto masked = [&](const Eigen::VectorXd& v) -> Eigen::VectorXd {
    return interior.cwiseProduct(apply(interior.cwiseProduct(v)));
  };
  Eigen::VectorXd delta = Eigen::VectorXd::Zero(u.size());
  const SolverReport r = conjugate_gradient(masked, inverse_diag, residual, delta, p.solver_tolerance,
                                            p.max_solver_iterations, interior.cwiseProduct(b).norm());
  if (report) *report = r;
  return x + delta;
}

template <int D>
Eigen::VectorXd step_gmres(const P1Operators<D>& ops, const Eigen::VectorXd& d,
                           const Eigen::VectorXd& u, const Eigen::VectorXd& a,
                           const StepParameters& p, SolverReport* report) {
  if (ops.divergence.rows() == 0) {
    throw std::logic_error("the GMRES reference needs operators assembled with_divergence");
  }
  // M = Div A^-1 G, literally (eq. 14).
  Eigen::VectorXd inverse_a(D * a.size());
  for (Eigen::Index j = 0; j < a.size(); ++j) inverse_a.template segment<D>(D * j).setConstant(1.0 / a[j]);
  const SparseRowMatrix m = ops.divergence * inverse_a.asDiagonal() * ops.gradient_matrix();
  // Rows scaled by -dt beta a_i; wall rows by 0, so that they become identity rows below.
  Eigen::VectorXd row_scale = -p.time_step * p.curvature_weight * a;
  if (p.curvature_weights.size() > 0) row_scale = -p.time_step * p.curvature_weights.cwiseProduct(a);
  const Eigen::VectorXd interior = wall_mask(ops, p);
  row_scale = row_scale.cwiseProduct(interior);
  SparseRowMatrix system = row_scale.asDiagonal() * m;
  SparseRowMatrix identity(u.size(), u.size());
  identity.setIdentity();
  system += identity;
  system.prune(0.0);
  const Eigen::VectorXd rhs = advance_by_data(u, a, d, p);
  Eigen::GMRES<Eigen::SparseMatrix<double>, Eigen::DiagonalPreconditioner<double>> gmres;
  gmres.setTolerance(p.solver_tolerance);
  gmres.setMaxIterations(p.max_solver_iterations);
  gmres.set_restart(50);
  const Eigen::SparseMatrix<double> col_major = system;
  gmres.compute(col_major);
  Eigen::VectorXd x = gmres.solveWithGuess(rhs, u);
  if (report) {
    report->converged = gmres.info() == Eigen::Success;
    report->iterations = int(gmres.iterations());
    report->error = gmres.error();
  }
  return x;
}

}  // namespace

template <int D>
Eigen::VectorXd semi_implicit_step(const P1Operators<D>& ops, const Eigen::VectorXd& d,
                                   const Eigen::VectorXd& u, const StepParameters& p,
                                   SolverReport* report) {
  const Eigen::VectorXd a = ops.gradient_norms(u).cwiseMax(p.min_gradient);
  return p.solver == LinearSolver::conjugate_gradient ? step_cg(ops, d, u, a, p, report)
                                                      : step_gmres(ops, d, u, a, p, report);
}

template Eigen::VectorXd semi_implicit_step<2>(const P1Operators<2>&, const Eigen::VectorXd&,
                                               const Eigen::VectorXd&, const StepParameters&, SolverReport*);
template Eigen::VectorXd semi_implicit_step<3>(const P1Operators<3>&, const Eigen::VectorXd&,
                                               const Eigen::VectorXd&, const StepParameters&, SolverReport*);

}  // namespace lsr
