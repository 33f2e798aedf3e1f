// SPDX-License-Identifier: BSD-3-Clause
/// @file conjugate_gradient.h
/// @brief Matrix-free preconditioned conjugate gradients.
///
/// Eigen's ConjugateGradient needs an assembled matrix or a MatrixReplacement wrapper plus a
/// custom preconditioner class; the operator here (G^T W G, a 2-ring stencil in 3D) is far
/// cheaper to apply than to assemble, so the 30-line algorithm is written out. Its status
/// mirrors Eigen's: converged, iterations, error.
#pragma once

#include <Eigen/Core>

#include <cmath>

namespace lsr {

/// @brief How a conjugate-gradient solve ended.
struct SolverReport {
  bool converged = false;
  int iterations = 0;
  double error = 0.0;  ///< final ||b - A x|| / ||b||
};

/// @brief CG's vectors, kept by a caller that solves many systems of one size.
struct ConjugateGradientWorkspace {
  Eigen::VectorXd r, z, p, ap;
};

/// @brief Solves A x = b for symmetric positive definite A, starting from x.
/// @param apply (v, out) -> out = A v
/// @param inverse_diagonal Jacobi preconditioner, 1 / diag(A)
/// @param x the start; a zero start saves one product
/// @param tolerance stop when ||b - A x|| <= tolerance * reference_norm (||b|| if <= 0)
template <class ApplyA>
SolverReport conjugate_gradient(const ApplyA& apply, const Eigen::VectorXd& inverse_diagonal,
                                const Eigen::VectorXd& b, Eigen::VectorXd& x, double tolerance,
                                int max_iterations, ConjugateGradientWorkspace& w,
                                double reference_norm = 0.0) {
  SolverReport report;
  const double scale = reference_norm > 0.0 ? reference_norm : b.norm();
  Eigen::VectorXd &r = w.r, &z = w.z, &p = w.p, &ap = w.ap;
  r = b;
  if (!x.isZero(0.0)) {
    apply(x, ap);
    r -= ap;
  }
  if (scale == 0.0 || r.norm() <= tolerance * scale) {
    report.converged = true;
    report.error = scale == 0.0 ? 0.0 : r.norm() / scale;
    return report;
  }
  z = inverse_diagonal.cwiseProduct(r);
  p = z;
  double rz = r.dot(z);
  for (report.iterations = 1; report.iterations <= max_iterations; ++report.iterations) {
    apply(p, ap);
    const double step = rz / p.dot(ap);
    x += step * p;
    r -= step * ap;
    report.error = r.norm() / scale;
    if (report.error <= tolerance) {
      report.converged = true;
      return report;
    }
    z = inverse_diagonal.cwiseProduct(r);
    const double rz_next = r.dot(z);
    p = z + (rz_next / rz) * p;
    rz = rz_next;
  }
  report.iterations = max_iterations;
  return report;
}

}  // namespace lsr
