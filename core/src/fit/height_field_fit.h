// SPDX-License-Identifier: BSD-3-Clause
/// @file height_field_fit.h
/// @brief Weighted least squares of a polynomial height field z(t) over tangent coordinates t,
/// and the choice between a quadric and a cubic by Schwarz's criterion (BIC): the cubic terms
/// are kept only where they explain more of the data than noise would.
#pragma once

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include <algorithm>
#include <cmath>

namespace lsr {

/// Coefficients of a quadric height field in D dimensions, and of a cubic one (3D).
template <int D>
constexpr int kQuadricTerms = D == 2 ? 3 : 6;
constexpr int kCubicTerms = 10;

/// @brief The monomials of the height field c0 + g.t + t^T H t / 2 (D == 2: t scalar), then
/// for P = 10 (3D) the cubic terms t0^3 / 6, t0^2 t1 / 2, t0 t1^2 / 2, t1^3 / 6.
template <int D, int P>
Eigen::Matrix<double, P, 1> height_monomials(const Eigen::Matrix<double, D - 1, 1>& t) {
  static_assert(P == kQuadricTerms<D> || (D == 3 && P == kCubicTerms));
  if constexpr (D == 2) {
    return Eigen::Vector3d(1.0, t[0], 0.5 * t[0] * t[0]);
  } else {
    const double a = t[0], b = t[1];
    Eigen::Matrix<double, 10, 1> m;
    m << 1.0, a, b, 0.5 * a * a, a * b, 0.5 * b * b, a * a * a / 6.0, 0.5 * a * a * b, 0.5 * a * b * b, b * b * b / 6.0;
    return m.template head<P>();
  }
}

/// @brief The weighted normal equations of P height-field terms, with sum w^2 m m^T (for the
/// cubic): how much of the residual noise alone removes depends on it.
template <int D, int P>
struct HeightFieldEquations {
  Eigen::Matrix<double, P, P> ata = Eigen::Matrix<double, P, P>::Zero();
  Eigen::Matrix<double, P, P> ata2 = Eigen::Matrix<double, P, P>::Zero();
  Eigen::Matrix<double, P, 1> atz = Eigen::Matrix<double, P, 1>::Zero();
  double sum_w = 0.0, sum_w2 = 0.0;

  /// A point of height z at tangent coordinates with monomials m, weight w.
  void add(double w, const Eigen::Matrix<double, P, 1>& m, double z) {
    ata += w * m * m.transpose();
    if constexpr (P == kCubicTerms) ata2 += (w * w) * m * m.transpose();
    atz += (w * z) * m;
    sum_w += w;
    sum_w2 += w * w;
  }
  /// A light ridge on every term but c0, scaled to the fit's radius: sparse or colinear
  /// neighbourhoods stay solvable and fall back towards the tangent plane.
  void regularize(double reach) {
    const double scale = ata(0, 0) > 0.0 ? ata(0, 0) : 1.0;
    for (int c = 1; c < P; ++c) ata(c, c) += 1e-6 * scale * std::pow(reach, 2 * degree(c));
    if (ata(0, 0) <= 0.0) ata(0, 0) = 1.0;
  }
  Eigen::Matrix<double, P, 1> solve() const { return ata.ldlt().solve(atz); }

 private:
  static int degree(int c) { return c == 0 ? 0 : c < D ? 1 : c < kQuadricTerms<D> ? 2 : 3; }
};

/// @brief The quadric or the cubic fit of a 3D height field, whichever Schwarz's criterion picks.
struct CubicSelection {
  Eigen::Matrix<double, 6, 1> quadric;  ///< the chosen fit's constant, slope and curvature terms
  Eigen::Vector4d cubic = Eigen::Vector4d::Zero();  ///< its cubic terms (zero if the quadric won)
  bool cubic_kept = false;
  double removed = 0.0;   ///< the weighted residual the cubic terms remove
  double by_noise = 0.0;  ///< what they remove, in the mean, from noise of unit deviation
  double points = 0.0;    ///< the fit's effective number of points, (sum w)^2 / sum w^2
};

/// @brief Keeps the cubic terms if they remove more of the weighted residual than noise of
/// deviation sigma would by ln(n) per unit of its mean (Schwarz's criterion, n = points):
/// noise alone removes sigma^2 (tr(A3^-1 B3) - tr(A2^-1 B2)) in the mean, A = sum w m m^T,
/// B = sum w^2 m m^T over the cubic's (3) and the quadric's (2) terms; 4 sigma^2 with equal
/// weights. Residuals from the normal equations: sum w z^2 - x . A^T z.
inline CubicSelection select_cubic(const HeightFieldEquations<3, kCubicTerms>& e, double sigma) {
  const auto cubic_solver = e.ata.ldlt();
  const Eigen::Matrix<double, kCubicTerms, 1> x = cubic_solver.solve(e.atz);
  const Eigen::Matrix<double, 6, 6> a2 = e.ata.topLeftCorner<6, 6>();
  const Eigen::Matrix<double, 6, 6> b2 = e.ata2.topLeftCorner<6, 6>();
  const auto quadric_solver = a2.ldlt();
  const Eigen::Matrix<double, 6, 1> q = quadric_solver.solve(e.atz.head<6>());
  CubicSelection s;
  s.removed = x.dot(e.atz) - q.dot(e.atz.head<6>());
  s.by_noise = cubic_solver.solve(e.ata2).trace() - quadric_solver.solve(b2).trace();
  s.points = e.sum_w * e.sum_w / std::max(e.sum_w2, 1e-300);
  s.cubic_kept = s.removed > std::log(std::max(s.points, 1.0)) * sigma * sigma * s.by_noise;
  s.quadric = s.cubic_kept ? Eigen::Matrix<double, 6, 1>(x.head<6>()) : q;
  if (s.cubic_kept) s.cubic = x.tail<4>();
  return s;
}

}  // namespace lsr
