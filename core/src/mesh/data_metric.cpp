// SPDX-License-Identifier: BSD-3-Clause
/// @file data_metric.cpp
#include "mesh/data_metric.h"

#include <omp.h>

#include <algorithm>
#include <limits>

namespace lsr {

template <int D>
std::vector<double> other_sheets(const NearestPointIndex<D>& data, const LocalSampling<D>& sampling, const std::vector<double>& point_size,
                                 int threads) {
  const Points<D>& points = data.points();
  const int k = std::min<int>(kOtherSheetNeighbours, int(points.size()));
  LargeVector<Index> nearest;
  data.query_k(points, k, nearest, threads);
  std::vector<double> distance(points.size(), std::numeric_limits<double>::infinity());
#pragma omp parallel for schedule(static) num_threads(threads > 0 ? threads : omp_get_max_threads())
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (int j = 1; j < k; ++j) {
      const Vec<D> e = points[std::size_t(nearest[i * std::size_t(k) + std::size_t(j)])] - points[i];
      const double height = std::abs(e.dot(sampling.normals[i])), r = e.norm();
      if (height > 0.5 * r && height > 2.0 * point_size[i]) {
        distance[i] = r;
        break;
      }
    }
  }
  return distance;
}

template <int D>
MetricField<D> data_metric(const NearestPointIndex<D>& data, const LocalSampling<D>& sampling, const std::vector<double>& point_size,
                           double relative_error, double h_max, const std::vector<double>& other_sheet) {
  return [&data, &sampling, &point_size, relative_error, h_max, &other_sheet](const Vec<D>& x) -> Metric<D> {
    double distance = 0.0;
    const auto p = std::size_t(data.nearest(x, distance));
    // The height field's second derivatives, in the point's frame (rows: tangents, normal),
    // are the Hessian of the distance to the curve or surface through it (unsigned: the sizes
    // need |kappa| only).
    const Eigen::Matrix<double, D, D> frame = tangent_frame<D>(sampling.normals[p]);
    Metric<D> tangential = Metric<D>::Zero();
    const auto& c = sampling.height_fields[p].coefficients;
    if constexpr (D == 2) {
      tangential(0, 0) = c[2];
    } else {
      tangential.template topLeftCorner<2, 2>() << c[3], c[4], c[4], c[5];
    }
    MetricSizes sizes;
    sizes.h_min = point_size[p];
    sizes.h_max = std::max(std::min(h_max, 0.5 * other_sheet[p]), sizes.h_min);
    sizes.error = relative_error * sizes.h_min;
    return level_set_metric<D>(distance, frame.row(D - 1).transpose(), frame.transpose() * tangential * frame, sizes);
  };
}

template MetricField<2> data_metric<2>(const NearestPointIndex<2>&, const LocalSampling<2>&, const std::vector<double>&, double, double,
                                       const std::vector<double>&);
template MetricField<3> data_metric<3>(const NearestPointIndex<3>&, const LocalSampling<3>&, const std::vector<double>&, double, double,
                                       const std::vector<double>&);
template std::vector<double> other_sheets<2>(const NearestPointIndex<2>&, const LocalSampling<2>&, const std::vector<double>&, int);
template std::vector<double> other_sheets<3>(const NearestPointIndex<3>&, const LocalSampling<3>&, const std::vector<double>&, int);

}  // namespace lsr
