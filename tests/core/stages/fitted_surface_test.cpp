// SPDX-License-Identifier: BSD-3-Clause
/// @file fitted_surface_test.cpp
/// @brief The fit stage's quadrics: built from the points and their oriented normals, they
/// put points near the surface onto it, to the quadrics' order.
#include "fit/fitted_surface.h"

#include "lsrecon/testdata/analytic_shapes.h"
#include "sampling/local_sampling.h"

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

}  // namespace
}  // namespace lsr::detail
