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

template <int D>
void pca(const Points<D>& p, const Index* nearest, int k, double& thickness, Vec<D>& normal, double* elongation) {
  Vec<D> mean = Vec<D>::Zero();
  for (int j = 0; j < k; ++j) mean += p[nearest[j]];
  mean /= double(k);
  Eigen::Matrix<double, D, D> cov = Eigen::Matrix<double, D, D>::Zero();
  for (int j = 0; j < k; ++j) {
    const Vec<D> e = p[nearest[j]] - mean;
    cov += e * e.transpose() / double(k);
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, D, D>> eig(cov);
  thickness = std::sqrt(std::max(0.0, eig.eigenvalues()[0]));
  normal = eig.eigenvectors().col(0);
  // The second largest spread over the largest: near 0 when the neighbours lie along a line.
  if (elongation) *elongation = eig.eigenvalues()[D - 1] > 0.0 ? eig.eigenvalues()[D - 2] / eig.eigenvalues()[D - 1] : 1.0;
}

template <int D>
HeightField<D> fit_height_field(const Points<D>& p, const Index* nearest, int k, const Vec<D>& origin, const Vec<D>& normal,
                                double radius) {
  constexpr int kTerms = HeightField<D>::kTerms;
  HeightField<D> f;
  const Eigen::Matrix<double, D, D> frame = tangent_frame(normal);
  // Normal equations (a 6x6 solve per point, cheap next to the k-NN query), in units of the
  // neighbourhood's radius so that they stay well conditioned.
  if (!(radius > 0.0)) return f;
  Eigen::Matrix<double, kTerms, kTerms> ata = Eigen::Matrix<double, kTerms, kTerms>::Zero();
  Eigen::Matrix<double, kTerms, 1> ath = Eigen::Matrix<double, kTerms, 1>::Zero();
  for (int j = 0; j < k; ++j) {
    const Vec<D> y = frame * (p[nearest[j]] - origin) / radius;
    const Eigen::Matrix<double, kTerms, 1> row = HeightField<D>::monomials(y.template head<D - 1>());
    ata += row * row.transpose();
    ath += row * y[D - 1];
  }
  Eigen::Matrix<double, kTerms, 1> c = ata.ldlt().solve(ath);
  if (!c.allFinite()) return f;
  // Back to lengths: the constant scales by r, the slopes not, the second derivatives by 1/r.
  c[0] *= radius;
  c.template tail<kTerms - D>() /= radius;
  for (int t = 0; t < kTerms; ++t) f.coefficients[std::size_t(t)] = c[t];
  return f;
}

template struct HeightField<2>;
template struct HeightField<3>;
template Eigen::Matrix<double, 2, 2> tangent_frame<2>(const Vec<2>&);
template Eigen::Matrix<double, 3, 3> tangent_frame<3>(const Vec<3>&);
template void pca<2>(const Points<2>&, const Index*, int, double&, Vec<2>&, double*);
template void pca<3>(const Points<3>&, const Index*, int, double&, Vec<3>&, double*);
template HeightField<2> fit_height_field<2>(const Points<2>&, const Index*, int, const Vec<2>&, const Vec<2>&, double);
template HeightField<3> fit_height_field<3>(const Points<3>&, const Index*, int, const Vec<3>&, const Vec<3>&, double);

}  // namespace lsr
