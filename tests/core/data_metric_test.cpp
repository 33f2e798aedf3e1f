// SPDX-License-Identifier: BSD-3-Clause
/// @file data_metric_test.cpp
/// @brief The metric the data ask for, on a sampled circle: across, the point's size growing
/// with the distance; along, sqrt(8 error / kappa) from its height field's curvature.
#include "lsrecon/testdata/analytic_shapes.h"
#include "mesh/data_metric.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace lsr {
namespace {

TEST(DataMetric, SizesOfASampledCircle) {
  const Circle c{Vec<2>(0.5, 0.5), 0.3};
  const NearestPointIndex<2> data(c.sample(4000));
  const LocalSampling<2> sampling = estimate_local_sampling(data, 1, HeightFieldsAt::all);
  const double h = 1.0 / 1024, relative_error = 0.25, h_max = 1.0 / 8;
  const std::vector<double> size(data.points().size(), h);
  const std::vector<double> other_sheet = other_sheets<2>(data, sampling, size, 1);
  const MetricField<2> metric = data_metric<2>(data, sampling, size, relative_error, h_max, other_sheet);
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
      const double across = h + 0.5 * data.distance(x);
      const double along = std::clamp(std::sqrt(8.0 * relative_error * h * c.radius), across, h_max);
      EXPECT_NEAR(sizes[0], across, 1e-3 * across) << d << " " << t;
      EXPECT_NEAR(sizes[1], along, 1e-2 * along) << d << " " << t;
      if (along > 1.01 * across) {
        EXPECT_NEAR(std::abs(directions.col(0).dot(n)), 1.0, 1e-3);
      }
    }
  }
  // One circle: no other sheet (its own points within 64 neighbours rise 4e-4 over a tangent,
  // far below half their distance).
  for (double d : other_sheet) EXPECT_EQ(d, std::numeric_limits<double>::infinity());
}

// Two parallel lines g apart: each point sees the other line at g (to half a spacing), and
// the sizes along them are at most g / 2 however flat they are.
TEST(DataMetric, SizesAlongAreHalfTheGapToAFacingSheet) {
  const double g = 0.005, spacing = 0.6 / 2000;
  Points<2> points;
  for (int i = 0; i < 2000; ++i) {
    points.emplace_back(0.2 + spacing * i, 0.5);
    points.emplace_back(0.2 + spacing * (i + 0.5), 0.5 + g);
  }
  const NearestPointIndex<2> data(points);
  const LocalSampling<2> sampling = estimate_local_sampling(data, 1, HeightFieldsAt::all);
  const double h = 1.0 / 1024;
  const std::vector<double> size(data.points().size(), h);
  const std::vector<double> other_sheet = other_sheets<2>(data, sampling, size, 1);
  for (double d : other_sheet) EXPECT_NEAR(d, std::hypot(g, 0.5 * spacing), 1e-12);
  const MetricField<2> metric = data_metric<2>(data, sampling, size, 0.25, 1.0 / 8, other_sheet);
  for (double x : {0.3, 0.5, 0.7}) {
    Vec<2> sizes;
    Metric<2> directions;
    metric_sizes<2>(metric(Vec<2>(x, 0.5 + 0.3 * g)), sizes, directions);
    EXPECT_NEAR(sizes[1], 0.5 * std::hypot(g, 0.5 * spacing), 1e-9) << x;
    EXPECT_NEAR(std::abs(directions.col(1).x()), 1.0, 1e-6) << x;
  }
}

}  // namespace
}  // namespace lsr
