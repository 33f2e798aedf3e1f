// SPDX-License-Identifier: BSD-3-Clause
/// @file data_metric.cpp
#include "mesh/data_metric.h"

#include <algorithm>

namespace lsr {

template <int D>
MetricField<D> data_metric(const NearestPointIndex<D>& data, const LocalSampling<D>& sampling, const std::vector<double>& point_size,
                           double relative_error, double h_max) {
  return [&data, &sampling, &point_size, relative_error, h_max](const Vec<D>& x) -> Metric<D> {
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
    sizes.h_max = std::max(h_max, sizes.h_min);
    sizes.error = relative_error * sizes.h_min;
    sizes.anisotropic_reach = kAnisotropicReach<D> * sizes.h_min;
    return level_set_metric<D>(distance, frame.row(D - 1).transpose(), frame.transpose() * tangential * frame, sizes);
  };
}

template MetricField<2> data_metric<2>(const NearestPointIndex<2>&, const LocalSampling<2>&, const std::vector<double>&, double, double);
template MetricField<3> data_metric<3>(const NearestPointIndex<3>&, const LocalSampling<3>&, const std::vector<double>&, double, double);

}  // namespace lsr
