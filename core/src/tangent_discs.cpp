// SPDX-License-Identifier: BSD-3-Clause
/// @file tangent_discs.cpp
#include "lsrecon/core/tangent_discs.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

#include <omp.h>

namespace lsr {
namespace {

template <int D>
using Frame = Eigen::Matrix<double, D, D, Eigen::DontAlign>;
template <int D>
using Shape = Eigen::Matrix<double, D - 1, D - 1, Eigen::DontAlign>;

// Distance from y (in the disc's frame) to the height field over the disc {|S x| <= 1}: the
// vertical gap over the slope inside, the gap to the rim outside (first order in both).
template <int D>
double disc_distance(const HeightField<D>& f, const Shape<D>& shape, const Vec<D>& y) {
  const Eigen::Matrix<double, D - 1, 1> x = y.template head<D - 1>();
  const double extent = (shape * x).norm();
  if (extent <= 1.0) {
    return std::abs(y[D - 1] - f.height(x)) / std::sqrt(1.0 + f.slope(x).squaredNorm());
  }
  const Eigen::Matrix<double, D - 1, 1> rim = x / extent;
  return std::hypot((x - rim).norm(), y[D - 1] - f.height(rim));
}

}  // namespace

template <int D>
std::vector<double> tangent_disc_distance(const NearestPointIndex<D>& data, const LocalSampling<D>& sampling,
                                          double radius, const Points<D>& queries,
                                          const std::vector<double>& point_distance, const std::vector<double>& cap,
                                          int threads) {
  const Points<D>& points = data.points();
  const int t = threads > 0 ? threads : omp_get_max_threads();
  std::vector<Frame<D>> frames(points.size());
  std::vector<Shape<D>> shapes(points.size());
#pragma omp parallel for schedule(static) num_threads(t)
  for (std::ptrdiff_t i = 0; i < std::ptrdiff_t(points.size()); ++i) {
    frames[i] = tangent_frame(sampling.normals[i]);
    shapes[i] = disc_shape(sampling.height_fields[i], radius);
  }
  std::vector<double> out(point_distance);
  std::vector<Index> which;
  Points<D> near;
  for (std::size_t q = 0; q < queries.size(); ++q) {
    if (point_distance[q] > 0.0 && point_distance[q] <= cap[q]) {
      which.push_back(Index(q));
      near.push_back(queries[q]);
    }
  }
  std::vector<Index> nearest;
  data.query_k(near, kDiscNeighbours, nearest, t);
#pragma omp parallel for schedule(static) num_threads(t)
  for (std::ptrdiff_t k = 0; k < std::ptrdiff_t(which.size()); ++k) {
    const std::size_t q = std::size_t(which[std::size_t(k)]);
    double best = out[q];
    for (int j = 0; j < kDiscNeighbours; ++j) {
      const Index p = nearest[std::size_t(k) * kDiscNeighbours + j];
      best = std::min(best, disc_distance(sampling.height_fields[p], shapes[p], Vec<D>(frames[p] * (queries[q] - points[p]))));
    }
    out[q] = best;
  }
  return out;
}

template <int D>
Eigen::Matrix<double, D - 1, D - 1> disc_shape(const HeightField<D>& f, double radius) {
  const auto& c = f.coefficients;
  auto extent = [radius](double curvature) { return 1.0 / std::min(radius, 1.0 / std::abs(curvature)); };
  if constexpr (D == 2) {
    return Eigen::Matrix<double, 1, 1>(extent(c[2]));
  } else {
    const Eigen::Matrix2d a = (Eigen::Matrix2d() << c[3], c[4], c[4], c[5]).finished();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(a);
    const Eigen::Vector2d inverse(extent(eig.eigenvalues()[0]), extent(eig.eigenvalues()[1]));
    return eig.eigenvectors() * inverse.asDiagonal() * eig.eigenvectors().transpose();
  }
}

template Eigen::Matrix<double, 1, 1> disc_shape<2>(const HeightField<2>&, double);
template Eigen::Matrix<double, 2, 2> disc_shape<3>(const HeightField<3>&, double);
template std::vector<double> tangent_disc_distance<2>(const NearestPointIndex<2>&, const LocalSampling<2>&, double,
                                                      const Points<2>&,
                                                      const std::vector<double>&, const std::vector<double>&, int);
template std::vector<double> tangent_disc_distance<3>(const NearestPointIndex<3>&, const LocalSampling<3>&, double,
                                                      const Points<3>&,
                                                      const std::vector<double>&, const std::vector<double>&, int);

}  // namespace lsr
