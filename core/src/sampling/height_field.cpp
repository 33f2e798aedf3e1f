// SPDX-License-Identifier: BSD-3-Clause
/// @file height_field.cpp
/// @brief The tangent frame of a normal and the quadric height fields over it (local_sampling.h).
#include "sampling/local_sampling.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace lsr {

template <int D>
Eigen::Matrix<double, D, D> tangent_frame(const Vec<D>& normal) {
  Eigen::Matrix<double, D, D> frame;
  frame.row(D - 1) = normal.transpose();
  if constexpr (D == 2) {
    frame.row(0) << -normal[1], normal[0];
  } else {
    const Vec<3> t = normal.unitOrthogonal();
    frame.row(0) = t.transpose();
    frame.row(1) = normal.cross(t).transpose();
  }
  return frame;
}

template <int D>
auto HeightField<D>::monomials(const Eigen::Matrix<double, D - 1, 1>& x) -> Eigen::Matrix<double, kTerms, 1> {
  Eigen::Matrix<double, kTerms, 1> m;
  if constexpr (D == 2) {
    m << 1.0, x[0], 0.5 * x[0] * x[0];
  } else {
    m << 1.0, x[0], x[1], 0.5 * x[0] * x[0], x[0] * x[1], 0.5 * x[1] * x[1];
  }
  return m;
}

template <int D>
double HeightField<D>::height(const Eigen::Matrix<double, D - 1, 1>& x) const {
  return Eigen::Map<const Eigen::Matrix<double, kTerms, 1>>(coefficients.data()).dot(monomials(x));
}

template <int D>
Eigen::Matrix<double, D - 1, 1> HeightField<D>::slope(const Eigen::Matrix<double, D - 1, 1>& x) const {
  const auto& c = coefficients;
  Eigen::Matrix<double, D - 1, 1> g;
  if constexpr (D == 2) {
    g << c[1] + c[2] * x[0];
  } else {
    g << c[1] + c[3] * x[0] + c[4] * x[1], c[2] + c[4] * x[0] + c[5] * x[1];
  }
  return g;
}

template <int D>
double HeightField<D>::largest_curvature() const {
  const auto& c = coefficients;
  if constexpr (D == 2) {
    return std::abs(c[2]);
  } else {
    const Eigen::Matrix2d hessian = (Eigen::Matrix2d() << c[3], c[4], c[4], c[5]).finished();
    return Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(hessian).eigenvalues().cwiseAbs().maxCoeff();
  }
}

template struct HeightField<2>;
template struct HeightField<3>;
template Eigen::Matrix<double, 2, 2> tangent_frame<2>(const Vec<2>&);
template Eigen::Matrix<double, 3, 3> tangent_frame<3>(const Vec<3>&);

}  // namespace lsr
