// SPDX-License-Identifier: BSD-3-Clause
/// @file resolution_hierarchy_test.cpp
/// @brief Levels of detail: each level closed with the right topology, each finer than the one
/// before, from cold and from warm starts.
#include "lsrecon/core/resolution_hierarchy.h"

#include "lsrecon/core/errors.h"
#include "lsrecon/testdata/analytic_shapes.h"
#include "lsrecon/testdata/shape_corpus.h"
#include "surface/surface_topology.h"

#include <gtest/gtest.h>

namespace lsr {
namespace {

TEST(ResolutionHierarchy, ThreeLevelsOfARandomTorusAreClosedAndFinerEachTime) {
  const Points<3> points = sample_test_shape(make_test_shape("torus"), 4000).points;
  for (bool warm : {false, true}) {
    const std::vector<ReconstructionResult<3>> levels = reconstruct_levels<3>(points, 3, {}, warm);
    ASSERT_EQ(levels.size(), 3u);
    for (std::size_t k = 0; k < levels.size(); ++k) {
      const auto& r = levels[k];
      EXPECT_EQ(r.status, ReconstructionStatus::converged) << k;
      const SurfaceTopology t = analyze_surface(r.surface.vertices, r.surface.facets);
      EXPECT_TRUE(t.watertight) << k;
      EXPECT_EQ(t.genus, std::vector<int>{1}) << k << (warm ? " warm" : " cold");
      if (k > 0) {
        // Twice the resolution: about 4 times the surface triangles, at least twice.
        EXPECT_GT(r.surface.facets.size(), 2 * levels[k - 1].surface.facets.size()) << k;
        EXPECT_LT(r.h_min, levels[k - 1].h_min) << k;
      }
    }
  }
  EXPECT_THROW(reconstruct_levels<3>(points, 0), InvalidInput);
  EXPECT_THROW(reconstruct_levels<3>(points, 9), InvalidInput);
}

TEST(ResolutionHierarchy, LengthsInTheInputsUnitsAreRefused) {
  ReconstructionOptions o;
  o.lengths = LengthUnit::input;
  EXPECT_THROW(reconstruct_levels<3>(Sphere{Vec<3>(0, 0, 0), 1.0}.sample(500), 2, o), InvalidInput);
}

TEST(ResolutionHierarchy, OneLevelIsThePlainReconstruction) {
  const Points<2> points = sample_star(3000, Vec<2>(0, 0), 1.0);
  const auto one = reconstruct_levels<2>(points, 1);
  const auto plain = reconstruct<2>(points);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0].surface.vertices, plain.surface.vertices);
}

}  // namespace
}  // namespace lsr
