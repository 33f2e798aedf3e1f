// SPDX-License-Identifier: BSD-3-Clause
/// @file curve_refinement_test.cpp
/// @brief Long segments of a closed curve split and projected onto the fit: a polygon's chords
/// on a circle become a polygon as fine as asked, on the circle to the fit's accuracy; a fine
/// polygon is left alone.
#include "checks/exact_self_intersections.h"
#include "fit/curve_refinement.h"
#include "lsrecon/testdata/analytic_shapes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace lsr::detail {
namespace {

// The regular n-gon inscribed in the circle, as a closed curve (facets in order).
LevelSetMesh<2> polygon(const Circle& c, int n) {
  LevelSetMesh<2> p;
  for (int k = 0; k < n; ++k) {
    const double t = 2.0 * kPi * k / n;
    p.vertices.push_back(c.center + c.radius * Vec<2>(std::cos(t), std::sin(t)));
    p.sources.push_back({0, 1, 0.5});
    p.facets.push_back({Index(k), Index((k + 1) % n)});
  }
  return p;
}

TEST(CurveRefinement, LongChordsBecomeFineAndLieOnTheFit) {
  const Circle c{Vec<2>(0.5, 0.5), 0.3};
  const Points<2> samples = c.sample(4000);
  Points<2> normals;
  for (const auto& p : samples) normals.push_back((p - c.center).normalized());
  const double spacing = 2.0 * kPi * c.radius / 4000;
  const NearestPointIndex<2> index(samples);  // the fit refers to it
  const QuadricImplicit<2> fit(index, normals, std::vector<double>(samples.size(), spacing));
  const double length = 0.01;
  LevelSetMesh<2> curve = polygon(c, 24);  // sides 0.078
  Points<2> curve_normals(curve.vertices.size(), Vec<2>::Zero());
  Points<2> polygon_points = curve.vertices;  // subdivided alongside
  refine_long_segments(curve, curve_normals, fit, [&](std::size_t) { return length; }, polygon_points, 1);
  EXPECT_EQ(polygon_points.size(), curve.vertices.size());
  EXPECT_EQ(testing::cgal_self_intersections(polygon_points, curve.facets), 0u);
  // ceil(0.078 / 0.01) = 8 parts a side.
  EXPECT_EQ(curve.vertices.size(), 24u * 8u);
  EXPECT_EQ(curve.facets.size(), curve.vertices.size());
  EXPECT_EQ(curve.sources.size(), curve.vertices.size());
  EXPECT_EQ(curve_normals.size(), curve.vertices.size());
  std::vector<int> starts(curve.vertices.size(), 0), ends(curve.vertices.size(), 0);
  for (const auto& f : curve.facets) {
    EXPECT_LE((curve.vertices[std::size_t(f[1])] - curve.vertices[std::size_t(f[0])]).norm(), 1.01 * length);
    ++starts[std::size_t(f[0])];
    ++ends[std::size_t(f[1])];
  }
  for (std::size_t v = 0; v < curve.vertices.size(); ++v) {
    EXPECT_EQ(starts[v], 1);  // still one closed loop's worth of links
    EXPECT_EQ(ends[v], 1);
    // The fit of a circle's samples: within the next term of its height field, far below the
    // chords' sagitta (kappa L^2 / 8 = 2.5e-3 for the polygon's sides).
    EXPECT_NEAR((curve.vertices[v] - c.center).norm(), c.radius, 1e-6) << v;
  }
  // As fine as asked already: unchanged.
  LevelSetMesh<2> fine = polygon(c, 400);  // sides 4.7e-3
  Points<2> fine_normals(fine.vertices.size(), Vec<2>::Zero());
  Points<2> fine_points = fine.vertices;
  refine_long_segments(fine, fine_normals, fit, [&](std::size_t) { return length; }, fine_points, 1);
  EXPECT_EQ(fine.vertices.size(), 400u);
}

}  // namespace
}  // namespace lsr::detail
