// SPDX-License-Identifier: BSD-3-Clause
/// @file renormalization_test.cpp
#include "evolution/renormalization.h"
#include "lsrecon/testdata/analytic_shapes.h"
#include "mesh/adaptive_refinement.h"

#include <gtest/gtest.h>

namespace lsr {
namespace {

template <int D, class Shape>
void check_renormalization(const Shape& shape, const Points<D>& samples, double h) {
  AdaptiveMeshOptions o;
  o.h_min = h;
  const AdaptiveMesh<D> m = build_adaptive_mesh(NearestPointIndex<D>(samples), o);
  Eigen::VectorXd u(m.mesh.vertices.size());
  Eigen::VectorXd exact(u.size());
  for (Eigen::Index i = 0; i < u.size(); ++i) {
    exact[i] = shape.signed_distance(m.mesh.vertices[i]);
    u[i] = 3.0 * exact[i] * (1.0 + exact[i]);  // same zero set, |grad u| far from 1
  }
  const double band = 5 * h;
  const RenormalizationReport<D> r = renormalize(m.mesh, u, band);
  EXPECT_GT(r.band_vertices, 0);
  // The zero set moved by at most the interpolation error kappa L^2 / 8 (L = sqrt(D) h), so
  // the distances to it are within that of the exact ones.
  const double tolerance = (D - 1) / shape.radius * D * h * h / 8.0 * 1.5;
  for (Eigen::Index i = 0; i < u.size(); ++i) {
    EXPECT_EQ(u[i] < 0.0, exact[i] < 0.0) << i;
    if (std::abs(exact[i]) < band - tolerance) {
      EXPECT_NEAR(u[i], exact[i], tolerance) << i;
    } else if (std::abs(exact[i]) > band + tolerance) {
      EXPECT_EQ(std::abs(u[i]), band) << i;
    }
  }
}

TEST(Renormalization, RestoresTheSignedDistanceOfACircle) {
  const Circle c{Vec<2>(0.5, 0.5), 0.3};
  check_renormalization<2>(c, c.sample(5000), 1.0 / 256);
}

TEST(Renormalization, RestoresTheSignedDistanceOfASphere) {
  const Sphere s{Vec<3>(0.5, 0.5, 0.5), 0.3};
  check_renormalization<3>(s, s.sample(20000), 1.0 / 64);
}

TEST(Renormalization, LeavesAFieldWithoutZeroSetAlone) {
  const Circle c{Vec<2>(0.5, 0.5), 0.3};
  AdaptiveMeshOptions o;
  const AdaptiveMesh<2> m = build_adaptive_mesh(NearestPointIndex<2>(c.sample(100)), o);
  Eigen::VectorXd u = Eigen::VectorXd::Constant(Eigen::Index(m.mesh.vertices.size()), 0.7);
  EXPECT_TRUE(renormalize(m.mesh, u, 0.1).front.facets.empty());
  EXPECT_EQ(u.minCoeff(), 0.7);
}

}  // namespace
}  // namespace lsr
