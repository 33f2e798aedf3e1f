// SPDX-License-Identifier: BSD-3-Clause
/// @file tangent_discs.cpp
#include "lsrecon/core/tangent_discs.h"

#include <algorithm>
#include <cmath>

#include <omp.h>

namespace lsr {
namespace {

template <int D>
using Frame = Eigen::Matrix<double, D, D, Eigen::DontAlign>;

// Distance from y (in the disc's frame) to the height field over the disc of radius r: the
// vertical gap over the slope inside, the gap to the rim outside (first order in both).
template <int D>
double disc_distance(const HeightField<D>& f, double r, const Vec<D>& y) {
  const Eigen::Matrix<double, D - 1, 1> x = y.template head<D - 1>();
  const double across = x.norm();
  if (across <= r) {
    return std::abs(y[D - 1] - f.height(x)) / std::sqrt(1.0 + f.slope(x).squaredNorm());
  }
  const Eigen::Matrix<double, D - 1, 1> rim = x * (r / across);
  return std::hypot(across - r, y[D - 1] - f.height(rim));
}

}  // namespace

template <int D>
std::vector<double> tangent_disc_distance(const NearestPointIndex<D>& data, const LocalSampling<D>& sampling,
                                          const std::vector<double>& radius, const Points<D>& queries,
                                          const std::vector<double>& point_distance, const std::vector<double>& cap,
                                          int threads) {
  const Points<D>& points = data.points();
  const int t = threads > 0 ? threads : omp_get_max_threads();
  std::vector<Frame<D>> frames(points.size());
#pragma omp parallel for schedule(static) num_threads(t)
  for (std::ptrdiff_t i = 0; i < std::ptrdiff_t(points.size()); ++i) frames[i] = tangent_frame(sampling.normals[i]);
  std::vector<double> out(point_distance);
  const double largest = radius.empty() ? 0.0 : *std::max_element(radius.begin(), radius.end());
#pragma omp parallel num_threads(t)
  {
    std::vector<Index> found;
#pragma omp for schedule(dynamic, 256)
    for (std::ptrdiff_t q = 0; q < std::ptrdiff_t(queries.size()); ++q) {
      const double bound = std::min(point_distance[q], cap[q]);
      if (!(bound > 0.0)) continue;
      // A disc point closer than the bound lies within bound of q, its centre within a radius more.
      data.within(queries[q], bound + largest, found);
      std::sort(found.begin(), found.end());  // the minimum is exact, but keep the reads in order
      double best = out[q];
      for (const Index p : found) {
        const Vec<D> y = frames[p] * (queries[q] - points[p]);
        best = std::min(best, disc_distance(sampling.height_fields[p], radius[p], y));
      }
      out[q] = best;
    }
  }
  return out;
}

std::vector<double> disc_radii(double largest, const std::vector<double>& curvature) {
  std::vector<double> r(curvature.size(), largest);
  for (std::size_t i = 0; i < r.size(); ++i) {
    if (curvature[i] > 0.0) r[i] = std::min(largest, 1.0 / curvature[i]);
  }
  return r;
}

template std::vector<double> tangent_disc_distance<2>(const NearestPointIndex<2>&, const LocalSampling<2>&,
                                                      const std::vector<double>&, const Points<2>&,
                                                      const std::vector<double>&, const std::vector<double>&, int);
template std::vector<double> tangent_disc_distance<3>(const NearestPointIndex<3>&, const LocalSampling<3>&,
                                                      const std::vector<double>&, const Points<3>&,
                                                      const std::vector<double>&, const std::vector<double>&, int);

}  // namespace lsr
