// SPDX-License-Identifier: BSD-3-Clause
/// @file level_set_volume_mesh_test.cpp
/// @brief The inside/outside split of a graded box mesh along analytic level sets: conforming,
/// positively oriented, regions adding up to the box, the inside's boundary equal to the
/// extracted surface facet for facet, and the inside's measure within the interpolation error.
#include "core/mesh_checks.h"
#include "lsrecon/core/level_set_reconstruction.h"
#include "lsrecon/core/level_set_volume_mesh.h"
#include "lsrecon/testdata/analytic_shapes.h"
#include "lsrecon/testdata/shape_corpus.h"
#include "mesh/adaptive_refinement.h"
#include "surface/surface_topology.h"
#include "volume/sliver_removal.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <limits>
#include <map>

namespace lsr {
namespace {

template <int D>
using Facet = std::array<Index, D>;

// A facet up to rotation (orientation kept): smallest index first.
template <int D>
Facet<D> canonical(Facet<D> f) {
  if constexpr (D == 2) {
    return f;
  } else {
    while (f[0] > f[1] || f[0] > f[2]) std::rotate(f.begin(), f.begin() + 1, f.end());
    return f;
  }
}

// The facets of a positively oriented simplex, each oriented outwards.
template <int D>
std::vector<Facet<D>> outward_facets(const std::array<Index, D + 1>& s) {
  if constexpr (D == 2) {
    return {{s[0], s[1]}, {s[1], s[2]}, {s[2], s[0]}};
  } else {
    return {{s[1], s[2], s[3]}, {s[0], s[3], s[2]}, {s[0], s[1], s[3]}, {s[0], s[2], s[1]}};
  }
}

template <int D>
Facet<D> unoriented(Facet<D> f) {
  std::sort(f.begin(), f.end());
  return f;
}

template <int D>
struct Split {
  VolumeMesh<D> volume;
  LevelSetMesh<D> surface;
};

template <int D>
Split<D> split(const Points<D>& samples, double h_min, const std::function<double(const Vec<D>&)>& sdf) {
  const testing::SampledField<D> f = testing::sampled_field<D>(samples, h_min, sdf);
  Split<D> out;
  out.surface = extract_zero_level_set(f.adaptive.mesh, f.values, 0.01);
  out.volume = split_along_level_set(f.adaptive.mesh, f.values, out.surface);
  return out;
}

// Every face shared by two simplices, or one of the box walls; the inside's boundary is the
// interface, facet for facet with the same orientation.
template <int D>
void expect_conforming_with_the_surface_as_boundary(const VolumeMesh<D>& v) {
  std::map<Facet<D>, int> uses;                // unoriented face -> simplices using it
  std::map<Facet<D>, int> inside_boundary;     // oriented (canonical) -> count
  for (std::size_t s = 0; s < v.simplices.size(); ++s) {
    for (const auto& f : outward_facets<D>(v.simplices[s])) {
      ++uses[unoriented<D>(f)];
      if (v.regions[s] == kInsideRegion) {
        Facet<D> back = f;
        std::swap(back[0], back[1]);
        auto it = inside_boundary.find(canonical<D>(back));
        if (it != inside_boundary.end()) {
          inside_boundary.erase(it);  // shared by two inside simplices
        } else {
          ++inside_boundary[canonical<D>(f)];
        }
      }
    }
  }
  // The faces used once are exactly the box walls (found from the unit box's coordinates),
  // each oriented as its simplex faces it (outwards); every other face is used twice.
  std::map<Facet<D>, int> outward;
  for (const auto& s : v.simplices) {
    for (const auto& f : outward_facets<D>(s)) ++outward[canonical<D>(f)];
  }
  std::size_t once = 0;
  for (const auto& [face, count] : uses) {
    ASSERT_LE(count, 2);
    once += count == 1 ? 1 : 0;
  }
  ASSERT_EQ(v.walls.size(), once);
  for (const auto& f : v.walls) {
    EXPECT_EQ(outward.count(canonical<D>(f)), 1u);
    EXPECT_EQ(uses[unoriented<D>(f)], 1);
  }
  ASSERT_EQ(inside_boundary.size(), v.interface.size());
  for (const auto& f : v.interface) EXPECT_EQ(inside_boundary.count(canonical<D>(f)), 1u);
}

// The area of the zero set times the interpolation error bound: how far the P1 inside can be
// from the exact one (interpolation along an edge of length sqrt(D) h of a function with
// curvature kappa misplaces the zero by at most kappa L^2 / (8 (1 - kappa L))).
double interpolation_bound(int dim, double h, double kappa) {
  const double L = std::sqrt(double(dim)) * h;
  return kappa * L * L / (8.0 * (1.0 - kappa * L));
}

TEST(LevelSetVolumeMesh, TorusInsideAndOutsideConformAndShareTheSurface) {
  const Torus torus{Vec<3>(0.5, 0.5, 0.5), 0.25, 0.1};
  const double h = 1.0 / 64;
  const Split<3> r = split<3>(torus.sample(4000), h, [&](const Vec<3>& p) { return torus.signed_distance(p); });
  const VolumeMesh<3>& v = r.volume;
  ASSERT_EQ(v.simplices.size(), v.regions.size());
  expect_conforming_with_the_surface_as_boundary<3>(v);
  const VolumeMeshQuality q = volume_mesh_quality(v);
  EXPECT_EQ(q.inverted, 0u);
  EXPECT_GT(q.min_angle_degrees, 0.0);
  EXPECT_GE(q.min_relative_measure, kFlatMeasure);
  // The unit box, up to the rounding of a sum of #simplices terms.
  const double rounding = double(v.simplices.size()) * std::numeric_limits<double>::epsilon();
  EXPECT_NEAR(q.inside_measure + q.outside_measure, 1.0, rounding);
  // The inside's volume is the volume the surface encloses, exactly (same facets).
  const SurfaceTopology t = analyze_surface(r.surface.vertices, r.surface.facets);
  EXPECT_NEAR(q.inside_measure, t.signed_volume, rounding);
  const double exact = 2 * kPi * kPi * torus.major_radius * torus.minor_radius * torus.minor_radius;
  const double area = 4 * kPi * kPi * torus.major_radius * torus.minor_radius;
  EXPECT_NEAR(q.inside_measure, exact, area * interpolation_bound(3, h, 1.0 / torus.minor_radius));
  std::printf("torus: %zu inside + %zu outside tetrahedra, dihedral min %.2f median %.1f degrees\n",
              q.inside_simplices, q.outside_simplices, q.min_angle_degrees, q.median_angle_degrees);
}

TEST(LevelSetVolumeMesh, TwoCirclesGiveTwoInsidePiecesAndAConformingOutside) {
  const Circle a{Vec<2>(0.3, 0.5), 0.15}, b{Vec<2>(0.7, 0.5), 0.15};
  const double h = 1.0 / 256;
  Points<2> samples = a.sample(400);
  for (const auto& p : b.sample(400)) samples.push_back(p);
  const Split<2> r = split<2>(samples, h, [&](const Vec<2>& p) { return std::min(a.signed_distance(p), b.signed_distance(p)); });
  expect_conforming_with_the_surface_as_boundary<2>(r.volume);
  const VolumeMeshQuality q = volume_mesh_quality(r.volume);
  EXPECT_EQ(q.inverted, 0u);
  EXPECT_GE(q.min_relative_measure, kFlatMeasure);
  EXPECT_NEAR(q.inside_measure + q.outside_measure, 1.0, double(r.volume.simplices.size()) * 1.2e-16);
  const double exact = 2 * kPi * 0.15 * 0.15, length = 2 * 2 * kPi * 0.15;
  EXPECT_NEAR(q.inside_measure, exact, length * interpolation_bound(2, h, 1.0 / 0.15));
  std::printf("two circles: %zu inside + %zu outside triangles, angle min %.2f median %.1f degrees\n",
              q.inside_simplices, q.outside_simplices, q.min_angle_degrees, q.median_angle_degrees);
}

// Through the whole pipeline on a random torus: the fit moves the surface after the cut, the
// split keeps every simplex positive, and the output surface is still the inside's boundary.
TEST(LevelSetVolumeMesh, ReconstructionReturnsMeshesSharingItsSurface) {
  ReconstructionOptions o;
  o.output.volume_mesh = true;
  const Points<3> points = sample_test_shape(make_test_shape("torus"), 3000).points;
  const ReconstructionResult<3> r = reconstruct<3>(points, o);
  ASSERT_EQ(r.status, ReconstructionStatus::converged);
  const VolumeMesh<3>& v = r.volume;
  expect_conforming_with_the_surface_as_boundary<3>(v);
  ASSERT_EQ(v.vertices.size() >= std::size_t(v.interface_offset) + r.surface.vertices.size(), true);
  for (std::size_t i = 0; i < r.surface.vertices.size(); ++i) {
    ASSERT_EQ(v.vertices[std::size_t(v.interface_offset) + i], r.surface.vertices[i]) << i;
  }
  for (std::size_t f = 0; f < r.surface.facets.size(); ++f) {
    for (int k = 0; k < 3; ++k) ASSERT_EQ(v.interface[f][k], r.surface.facets[f][k] + v.interface_offset);
  }
  const VolumeMeshQuality q = volume_mesh_quality(v);
  EXPECT_EQ(q.inverted, 0u);
  EXPECT_GE(q.min_relative_measure, kFlatMeasure);  // the fit may not flatten a simplex either
  const SurfaceTopology t = analyze_surface(r.surface.vertices, r.surface.facets);
  EXPECT_NEAR(q.inside_measure, t.signed_volume, double(v.simplices.size()) * 1e-16 * q.inside_measure);
  std::printf("random torus: %zu + %zu tetrahedra, dihedral min %.2f median %.1f, %.1f%% below 5 degrees, smallest %.1e of the mean, %zu pulled back\n",
              q.inside_simplices, q.outside_simplices, q.min_angle_degrees, q.median_angle_degrees,
              100 * q.small_angle_fraction, q.min_relative_measure, v.pulled_back);
}

TEST(LevelSetVolumeMesh, ASurfaceFromOtherValuesIsRefused) {
  const Sphere sphere{Vec<3>(0.5, 0.5, 0.5), 0.3};
  AdaptiveMeshOptions o;
  o.h_min = 1.0 / 16;
  const AdaptiveMesh<3> m = build_adaptive_mesh(NearestPointIndex<3>(sphere.sample(500)), o);
  std::vector<double> u(m.mesh.vertices.size()), w(m.mesh.vertices.size());
  for (std::size_t i = 0; i < u.size(); ++i) {
    u[i] = sphere.signed_distance(m.mesh.vertices[i]);
    w[i] = u[i] + 0.1;
  }
  EXPECT_THROW(split_along_level_set(m.mesh, w, extract_zero_level_set(m.mesh, u)), InvalidInput);
}

}  // namespace
}  // namespace lsr
