// SPDX-License-Identifier: BSD-3-Clause
/// @file semi_implicit_step.cpp
#include "evolution/semi_implicit_step.h"

#include <unsupported/Eigen/IterativeSolvers>

#include <stdexcept>

namespace lsr {
namespace {

// 1 on the vertices the solve updates, 0 on the walls and the held vertices.
template <int D>
void wall_mask(const P1Operators<D>& ops, const StepParameters& p, Eigen::VectorXd& interior) {
  interior.resize(Eigen::Index(ops.on_boundary.size()));
  for (std::size_t i = 0; i < ops.on_boundary.size(); ++i) {
    interior[i] = ops.on_boundary[i] || (p.held && (*p.held)[i]) ? 0.0 : 1.0;
  }
}

// Explicit data-term update, used as it is on the walls and as the start elsewhere. An
// expression (its operands are held by reference, the scalar by value), evaluated where used.
auto advance_by_data(const Eigen::VectorXd& u, const Eigen::VectorXd& a, const Eigen::VectorXd& d,
                     const StepParameters& p) {
  return u + p.time_step * p.alpha * a.cwiseProduct(d);
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
  Eigen::VectorXd interior;
  wall_mask(ops, p, interior);
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
void SemiImplicitStepper<D>::apply(const Eigen::VectorXd& v, Eigen::VectorXd& out, double c) const {
  if (c > 0.0) {
    curvature_.apply(v, out);
    out = lambda_over_a_.cwiseProduct(v) + c * out;
  } else {
    out = lambda_over_a_.cwiseProduct(v);
  }
}

// Each vector is written in place where the one it replaces is no longer needed: fewer vectors
// to keep (and to fault in again after release()).
template <int D>
void SemiImplicitStepper<D>::advance_cg(const Eigen::VectorXd& d, Eigen::VectorXd& u, const StepParameters& p,
                                        SolverReport* report) {
  wall_mask(ops_, p, interior_);
  lambda_over_a_ = ops_.ball_measure.cwiseQuotient(a_);
  const bool per_vertex = p.curvature_weights.size() > 0;
  curvature_.freeze(a_, per_vertex ? &p.curvature_weights : nullptr);
  const double c = p.time_step * (per_vertex ? 1.0 : p.curvature_weight);
  // The right-hand side b, held in residual_ until A x is subtracted.
  residual_ = lambda_over_a_.cwiseProduct(u) + p.time_step * p.alpha * ops_.ball_measure.cwiseProduct(d);
  const double reference_norm = interior_.cwiseProduct(residual_).norm();

  // Walls take their data-term value; the interior starts from u (warm start) and solves for
  // a correction delta that is zero on the walls. x overwrites u.
  u = interior_.cwiseProduct(u) + (Eigen::VectorXd::Ones(u.size()) - interior_).cwiseProduct(advance_by_data(u, a_, d, p));
  Eigen::VectorXd& ax = cg_.ap;  // free until the solve
  apply(u, ax, c);
  residual_ = interior_.cwiseProduct(residual_ - ax);
  if (c > 0.0) {
    curvature_.diagonal(inverse_diagonal_);
    inverse_diagonal_ = interior_.cwiseQuotient(lambda_over_a_ + c * inverse_diagonal_);
  } else {
    inverse_diagonal_ = interior_.cwiseQuotient(lambda_over_a_);
  }
  auto masked = [&](const Eigen::VectorXd& v, Eigen::VectorXd& out) {
    masked_ = interior_.cwiseProduct(v);
    apply(masked_, out, c);
    out = interior_.cwiseProduct(out);
  };
  delta_.setZero(u.size());
  const SolverReport r = conjugate_gradient(masked, inverse_diagonal_, residual_, delta_, p.solver_tolerance,
                                            p.max_solver_iterations, cg_, reference_norm);
  if (report) *report = r;
  u += delta_;
}

template <int D>
void SemiImplicitStepper<D>::advance(const Eigen::VectorXd& d, Eigen::VectorXd& u, const StepParameters& p,
                                     SolverReport* report) {
  ops_.gradient_norms(u, a_);
  a_ = a_.cwiseMax(p.min_gradient);
  if (p.solver == LinearSolver::conjugate_gradient) {
    advance_cg(d, u, p, report);
  } else {
    u = step_gmres(ops_, d, u, a_, p, report);
  }
}

template <int D>
void SemiImplicitStepper<D>::release() {
  curvature_.release();
  cg_ = ConjugateGradientWorkspace();
  for (Eigen::VectorXd* v : {&a_, &interior_, &lambda_over_a_, &residual_, &inverse_diagonal_, &delta_, &masked_}) {
    v->resize(0);
  }
}

template <int D>
Eigen::VectorXd semi_implicit_step(const P1Operators<D>& ops, const Eigen::VectorXd& d,
                                   const Eigen::VectorXd& u, const StepParameters& p,
                                   SolverReport* report) {
  Eigen::VectorXd next = u;
  SemiImplicitStepper<D>(ops).advance(d, next, p, report);
  return next;
}

template class SemiImplicitStepper<2>;
template class SemiImplicitStepper<3>;
template Eigen::VectorXd semi_implicit_step<2>(const P1Operators<2>&, const Eigen::VectorXd&,
                                               const Eigen::VectorXd&, const StepParameters&, SolverReport*);
template Eigen::VectorXd semi_implicit_step<3>(const P1Operators<3>&, const Eigen::VectorXd&,
                                               const Eigen::VectorXd&, const StepParameters&, SolverReport*);

}  // namespace lsr
