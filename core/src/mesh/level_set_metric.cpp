// SPDX-License-Identifier: BSD-3-Clause
#include "mesh/level_set_metric.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace lsr {
namespace {

// Columns: an orthonormal basis of the plane (line) orthogonal to the unit vector n.
template <int D>
Eigen::Matrix<double, D, D - 1> tangent_basis(const Vec<D>& n) {
  Eigen::Matrix<double, D, D - 1> t;
  if constexpr (D == 2) {
    t.col(0) = Vec<2>(-n.y(), n.x());
  } else {
    Eigen::Index axis = 0;
    n.cwiseAbs().minCoeff(&axis);  // the axis least aligned with n
    const Vec<3> a = n.cross(Vec<3>::Unit(axis)).normalized();
    t.col(0) = a;
    t.col(1) = n.cross(a);
  }
  return t;
}

}  // namespace

template <int D>
Metric<D> level_set_metric(double u, const Vec<D>& g, const Metric<D>& hessian, const MetricSizes& s) {
  const double length = g.norm();
  if (!(length > 0.0)) return Metric<D>::Identity() / (s.h_max * s.h_max);
  const Vec<D> n = g / length;
  const double distance = std::abs(u) / length;
  const double across = std::min(s.h_max, s.h_min + s.growth * distance);
  const double anisotropy = std::max(0.0, 1.0 - distance / s.anisotropic_reach);
  Metric<D> m = n * n.transpose() / (across * across);
  // The level set's shape operator in a tangent basis: its eigenvalues are the principal
  // curvatures, its eigenvectors the principal directions.
  const Eigen::Matrix<double, D, D - 1> t = tangent_basis<D>(n);
  const Eigen::Matrix<double, D - 1, D - 1> shape = t.transpose() * (0.5 * (hessian + hessian.transpose())) * t / length;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, D - 1, D - 1>> principal(shape);
  for (int i = 0; i < D - 1; ++i) {
    const double kappa = std::abs(principal.eigenvalues()[i]);
    const double along = across + anisotropy * ((kappa > 0.0 ? std::clamp(std::sqrt(8.0 * s.error / kappa), across, s.h_max) : s.h_max) - across);
    const Vec<D> direction = t * principal.eigenvectors().col(i);
    m += direction * direction.transpose() / (along * along);
  }
  return m;
}

template <int D>
std::vector<Metric<D>> level_set_metrics(const P1Operators<D>& ops, const Eigen::VectorXd& u, const MetricSizes& sizes) {
  const Eigen::Index nv = u.size();
  const Eigen::VectorXd g = ops.gradient_times(u);
  std::vector<Metric<D>> hessian(std::size_t(nv), Metric<D>::Zero());
  Eigen::VectorXd component(nv);
  for (int k = 0; k < D; ++k) {
    for (Eigen::Index i = 0; i < nv; ++i) component[i] = g[D * i + k];
    const Eigen::VectorXd row = ops.gradient_times(component);  // d/dx_j of dg/dx_k
    for (Eigen::Index i = 0; i < nv; ++i) hessian[std::size_t(i)].row(k) = row.template segment<D>(D * i).transpose();
  }
  std::vector<Metric<D>> m(static_cast<std::size_t>(nv));
  for (Eigen::Index i = 0; i < nv; ++i) {
    m[std::size_t(i)] = level_set_metric<D>(u[i], g.template segment<D>(D * i), hessian[std::size_t(i)], sizes);
  }
  return m;
}

template <int D>
void metric_sizes(const Metric<D>& m, Vec<D>& sizes, Metric<D>& directions) {
  const Eigen::SelfAdjointEigenSolver<Metric<D>> e(m);
  for (int i = 0; i < D; ++i) {  // the largest eigenvalue is the smallest size
    sizes[i] = 1.0 / std::sqrt(e.eigenvalues()[D - 1 - i]);
    directions.col(i) = e.eigenvectors().col(D - 1 - i);
  }
}

template Metric<2> level_set_metric<2>(double, const Vec<2>&, const Metric<2>&, const MetricSizes&);
template Metric<3> level_set_metric<3>(double, const Vec<3>&, const Metric<3>&, const MetricSizes&);
template std::vector<Metric<2>> level_set_metrics<2>(const P1Operators<2>&, const Eigen::VectorXd&, const MetricSizes&);
template std::vector<Metric<3>> level_set_metrics<3>(const P1Operators<3>&, const Eigen::VectorXd&, const MetricSizes&);
template void metric_sizes<2>(const Metric<2>&, Vec<2>&, Metric<2>&);
template void metric_sizes<3>(const Metric<3>&, Vec<3>&, Metric<3>&);

}  // namespace lsr
