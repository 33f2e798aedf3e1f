// SPDX-License-Identifier: BSD-3-Clause
/// @file fitted_surface_test.cpp
/// @brief The fit stage's quadrics: built from the points and their oriented normals, they
/// put points near the surface onto it, to the quadrics' order.
#include "fit/fitted_surface.h"

#include "lsrecon/testdata/analytic_shapes.h"
#include "sampling/data_preparation.h"
#include "sampling/local_sampling.h"
#include "sampling/mesh_resolution_data.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace lsr::detail {
namespace {

TEST(FittedSurface, TheQuadricsOfASpherePutNearbyPointsOnIt) {
  const Vec<3> centre(0.5, 0.5, 0.5);
  const double radius = 0.3;
  const NearestPointIndex<3> data(Sphere{centre, radius}.sample(5000));
  Points<3> normals;
  for (const auto& p : data.points()) normals.push_back((p - centre).normalized());
  const LocalSampling<3> s = estimate_local_sampling(data, 1);
  const QuadricImplicit<3> fit = fit_quadrics(data, normals, s.spacing, 1);
  // Points half a spacing s off the sphere, projected. A quadric through a neighbourhood of
  // radius r misses the sphere's height by its quartic term, r^4 / (8 R^3) at most; with the
  // kFitNeighbours nearest (r = s sqrt(kFitNeighbours / 6)) and R = 14 s here, that is about
  // 0.001 s, and the blend and the two projection steps add as much again: well within 1% of
  // the spacing, where the mesh (the front) resolves s itself.
  const double spacing = median(s.spacing);
  Points<3> off;
  for (std::size_t i = 0; i < data.points().size(); i += 50) off.push_back(centre + (data.points()[i] - centre) * (1.0 + 0.5 * spacing / radius));
  fit.project(off, 1);
  double worst = 0.0;
  for (const auto& p : off) worst = std::max(worst, std::abs((p - centre).norm() - radius));
  EXPECT_LE(worst, 0.01 * spacing);
}

// Two views of a sphere registered a shift delta apart, sampled far finer than the mesh's
// finest size h (delta = 1.5 h, the case of a dense scan under a resolution cap): the fits must
// read the pair as one thick sheet, not as two surfaces. At the poles along the shift the
// sheets lie delta apart; a fit that follows one of them puts the surface delta / 2 from their
// middle, one through both puts it in between: nearer the middle than either sheet means within
// delta / 4 of it.
TEST(FittedSurface, SheetsCloserThanTheMeshResolvesAreFittedAsOne) {
  const Vec<3> centre(0.5, 0.5, 0.5);
  const double radius = 0.3;
  const Points<3> view = Sphere{centre, radius}.sample(20000);
  const double h = 4.0 * median(estimate_local_sampling(NearestPointIndex<3>(view), 1).spacing);
  const Vec<3> shift(1.5 * h, 0.0, 0.0);
  Points<3> points = view, normals;
  for (const auto& p : view) points.push_back(p + shift);
  for (const auto& p : points) normals.push_back((p - centre - (normals.size() < view.size() ? Vec<3>::Zero() : shift)).normalized());
  NearestPointIndex<3> data(points);
  LocalSampling<3> s = estimate_local_sampling(data, 1);
  std::vector<double> scale = local_scales(s);
  const LeftOut<3> out = keep_mesh_resolution(data, s, scale, std::vector<double>(scale.size(), h), 1);
  ASSERT_FALSE(out.kept.empty());
  Points<3> kept_normals;
  for (Index i : out.kept) kept_normals.push_back(normals[std::size_t(i)]);
  for (double& x : scale) x = std::max(x, h);  // as the mesh raises it (data_mesh.h)
  const QuadricImplicit<3> fit = fit_quadrics(data, kept_normals, scale, 1);
  const Vec<3> middle = centre + 0.5 * shift;
  Points<3> poles;
  for (const auto& p : view) {
    const Vec<3> d = (p - centre).normalized();
    if (std::abs(d.x()) > 0.95) poles.push_back(middle + radius * d);
  }
  ASSERT_GT(poles.size(), 100u);
  fit.project(poles, 1);
  double worst = 0.0;
  for (const auto& p : poles) worst = std::max(worst, std::abs((p - middle).norm() - radius));
  EXPECT_LE(worst, 0.25 * shift.x());
}

}  // namespace
}  // namespace lsr::detail
