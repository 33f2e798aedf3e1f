// SPDX-License-Identifier: BSD-3-Clause
/// @file data_metric_test.cpp
/// @brief The metric the data ask for, on a sampled circle: across, the point's size growing
/// with the distance; along, sqrt(8 error / kappa) from its height field's curvature, down to
/// the size across at kAnisotropicReach sizes from the data (none in 2D).
#include "lsrecon/testdata/analytic_shapes.h"
#include "mesh/data_metric.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace lsr {
namespace {

TEST(DataMetric, SizesOfASampledCircle) {
  const Circle c{Vec<2>(0.5, 0.5), 0.3};
  const NearestPointIndex<2> data(c.sample(4000));
  const LocalSampling<2> sampling = estimate_local_sampling(data, 1, HeightFieldsAt::all);
  const double h = 1.0 / 1024, relative_error = 0.25, h_max = 1.0 / 8;
  const std::vector<double> size(data.points().size(), h);
  const MetricField<2> metric = data_metric<2>(data, sampling, size, relative_error, h_max);
  for (double d : {0.0, 0.002, -0.004, 0.01}) {
    for (double t : {0.1, 1.3, 4.0}) {
      const Vec<2> n(std::cos(t), std::sin(t));
      const Vec<2> x = c.center + (c.radius + d) * n;
      Vec<2> sizes;
      Metric<2> directions;
      metric_sizes<2>(metric(x), sizes, directions);
      // Across: the distance to the nearest point (not the curve: between two points it is up
      // to half a spacing). The height field of 16 neighbours over a circle: its curvature is
      // 1/R to (kappa r)^2 ~ 1e-4; its normal is the nearest point's, within half a spacing
      // (2e-4 rad) of the direction n.
      const double distance = data.distance(x);
      const double across = h + 0.5 * distance;
      const double anisotropy = std::max(0.0, 1.0 - distance / (kAnisotropicReach<2> * h));  // isotropic past the reach
      const double along = across + anisotropy * (std::clamp(std::sqrt(8.0 * relative_error * h * c.radius), across, h_max) - across);
      EXPECT_NEAR(sizes[0], across, 1e-3 * across) << d << " " << t;
      EXPECT_NEAR(sizes[1], along, 1e-2 * along) << d << " " << t;
      if (along > 1.01 * across) {
        EXPECT_NEAR(std::abs(directions.col(0).dot(n)), 1.0, 1e-3);
      }
    }
  }
}

}  // namespace
}  // namespace lsr
