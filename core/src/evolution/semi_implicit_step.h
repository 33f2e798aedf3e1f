// SPDX-License-Identifier: BSD-3-Clause
/// @file semi_implicit_step.h
/// @brief One time step of du/dt = |grad u| (beta kappa(u) + alpha d) (eq. 1 with a curvature
/// weight beta), semi-implicit as eq. (9)/(16): curvature implicit, |grad u| frozen at t_n.
///
/// Multiplying (I - dt beta D M) u' = u + dt alpha D d by Lambda D^-1 and using
/// Lambda M = -G^T W G gives the symmetric positive definite system
///     (Lambda D^-1 + dt beta G^T W G) u' = Lambda D^-1 u + dt alpha Lambda d,
/// solved matrix-free by Jacobi-preconditioned CG warm-started from u. Vertices on the walls of
/// the box are advanced by the data term only and eliminated: the paper's natural Neumann rows
/// there are anti-diffusive (docs/design.md section 9). The paper's unsymmetric form with GMRES is
/// kept as a reference path, with the same wall rows.
#pragma once

#include "evolution/conjugate_gradient.h"
#include "evolution/p1_operators.h"
#include "lsrecon/core/reconstruction_options.h"  // LinearSolver

namespace lsr {

/// @brief Parameters of one step, in unit-box units.
struct StepParameters {
  double time_step = 0.0;         ///< dt > 0
  double alpha = 2.0;             ///< weight of the attraction alpha d(x)
  double curvature_weight = 1.0;  ///< beta >= 0, weight of the curvature
  /// #V: beta per vertex, replacing curvature_weight when not empty. Applied inside the
  /// divergence in the symmetric form (div(beta grad u / |grad u|)), which differs from
  /// beta kappa by grad beta . n: small where beta follows a slowly varying sampling scale.
  Eigen::VectorXd curvature_weights;
  /// #V flags, or nullptr: vertices advanced by the data term only, like the walls (a front
  /// pinned on the data, where d = 0, is held still, and curvature no longer shrinks it).
  const std::vector<char>* held = nullptr;
  double min_gradient = 1e-2;     ///< eps_a: |grad u| is bounded below by it
  double solver_tolerance = 1e-8; ///< relative residual of the linear solve
  int max_solver_iterations = 2000;
  LinearSolver solver = LinearSolver::conjugate_gradient;
};

/// @brief Steps u in place on one mesh, keeping its vectors from one step to the next (see
/// SymmetricCurvatureOperator: fresh vectors are page-faulted in at each step). Gives the same u, to the bit, as semi_implicit_step().
template <int D>
class SemiImplicitStepper {
 public:
  explicit SemiImplicitStepper(const P1Operators<D>& ops) : ops_(ops), curvature_(ops) {}
  /// @brief u at t_n (#V) becomes u at t_{n+1}; distance d (#V).
  void advance(const Eigen::VectorXd& distance, Eigen::VectorXd& u, const StepParameters& p,
               SolverReport* report = nullptr);
  /// @brief Frees the kept vectors (the next step allocates them again): the caller's memory
  /// peak between steps, e.g. a renormalisation, then does not carry them.
  void release();

 private:
  void advance_cg(const Eigen::VectorXd& d, Eigen::VectorXd& u, const StepParameters& p, SolverReport* report);
  // (v, out) -> out = (Lambda D^-1 + c G^T W G) v; out must not be v.
  void apply(const Eigen::VectorXd& v, Eigen::VectorXd& out, double c) const;

  const P1Operators<D>& ops_;
  SymmetricCurvatureOperator<D> curvature_;
  ConjugateGradientWorkspace cg_;
  Eigen::VectorXd a_, interior_, lambda_over_a_, residual_, inverse_diagonal_, delta_, masked_;
};

/// @brief u at t_{n+1} from u at t_n (both #V), distance d (#V).
template <int D>
Eigen::VectorXd semi_implicit_step(const P1Operators<D>& ops, const Eigen::VectorXd& distance,
                                   const Eigen::VectorXd& u, const StepParameters& p,
                                   SolverReport* report = nullptr);

}  // namespace lsr
