// SPDX-License-Identifier: BSD-3-Clause
/// @file tangent_discs.cpp
#include "start/tangent_discs.h"

#include "thread_count.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <memory>

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
                                          int threads, bool rims_only) {
  const int t = detail::thread_count(threads);
  // The points that carry a disc, indexed apart when they are the rims only.
  std::vector<Index> carrier;
  for (std::size_t i = 0; i < data.points().size(); ++i) {
    if (!rims_only || (i < sampling.rim.size() && sampling.rim[i])) carrier.push_back(Index(i));
  }
  std::vector<double> out(point_distance);
  if (carrier.empty()) return out;
  std::unique_ptr<NearestPointIndex<D>> rims;
  if (rims_only) {
    Points<D> p(carrier.size());
    for (std::size_t c = 0; c < carrier.size(); ++c) p[c] = data.points()[std::size_t(carrier[c])];
    rims = std::make_unique<NearestPointIndex<D>>(std::move(p));
  }
  const NearestPointIndex<D>& index = rims ? *rims : data;
  const Points<D>& points = index.points();
  std::vector<Frame<D>> frames(points.size());
  std::vector<Shape<D>> shapes(points.size());
#pragma omp parallel for schedule(static) num_threads(t)
  for (std::ptrdiff_t c = 0; c < std::ptrdiff_t(points.size()); ++c) {
    const std::size_t i = std::size_t(carrier[std::size_t(c)]);
    frames[c] = tangent_frame(sampling.normals[i]);
    shapes[c] = disc_shape(sampling.height_fields[i], radius);
  }
  // The queries within their cap; with rims only, those with a rim point near enough: a disc
  // reaches less than 2 radii from its point (half-axes <= radius, the height field's rise over
  // them less), so farther rims cannot come closer than the points. In chunks, so that the
  // transient lists stay small (a copy of every vertex added 5% to the peak at 200k points).
  std::vector<Index> which;
  Points<D> near;
  constexpr std::size_t kChunk = std::size_t(1) << 16;
  Points<D> chunk;
  std::vector<Index> chunk_which, found;
  std::vector<double> bound, dist;
  for (std::size_t first = 0; first < queries.size(); first += kChunk) {
    chunk.clear();
    chunk_which.clear();
    bound.clear();
    for (std::size_t q = first; q < std::min(queries.size(), first + kChunk); ++q) {
      if (!(point_distance[q] > 0.0 && point_distance[q] <= cap[q])) continue;
      chunk_which.push_back(Index(q));
      chunk.push_back(queries[q]);
      bound.push_back(point_distance[q] + 2.0 * radius);
    }
    if (rims) index.query_within(chunk, bound, dist, found, t);
    for (std::size_t k = 0; k < chunk.size(); ++k) {
      if (rims && found[k] < 0) continue;
      which.push_back(chunk_which[k]);
      near.push_back(chunk[k]);
    }
  }
  const int discs = std::min<int>(kDiscNeighbours, int(points.size()));
  LargeVector<Index> nearest;
  index.query_k(near, discs, nearest, t);
#pragma omp parallel for schedule(static) num_threads(t)
  for (std::ptrdiff_t k = 0; k < std::ptrdiff_t(which.size()); ++k) {
    const std::size_t q = std::size_t(which[std::size_t(k)]);
    double best = out[q];
    for (int j = 0; j < discs; ++j) {
      const Index c = nearest[std::size_t(k) * discs + j];
      const std::size_t i = std::size_t(carrier[std::size_t(c)]);
      best = std::min(best, disc_distance(sampling.height_fields[i], shapes[c], Vec<D>(frames[c] * (queries[q] - points[c]))));
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
                                                      const std::vector<double>&, const std::vector<double>&, int, bool);
template std::vector<double> tangent_disc_distance<3>(const NearestPointIndex<3>&, const LocalSampling<3>&, double,
                                                      const Points<3>&,
                                                      const std::vector<double>&, const std::vector<double>&, int, bool);

}  // namespace lsr
