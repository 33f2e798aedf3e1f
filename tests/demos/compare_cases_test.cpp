// SPDX-License-Identifier: BSD-3-Clause
/// @file compare_cases_test.cpp
/// @brief Clouds of lsrecon-compare that once came out wrong, end to end.
#include "compare_cases.h"

#include "lsrecon/core/level_set_reconstruction.h"
#include "surface/surface_topology.h"

#include <gtest/gtest.h>

namespace lsr {
namespace {

// Clean, 20,000 points, draw 1: past a knife-edged ear tip, which the rim test takes for a
// hole's rim, the front kept a sliver of solid nearest to none of the samples, and the bunny
// came out as two components (core/unsupported_parts.h).
TEST(CompareCases, TheSmoothBunnyOfDraw1IsOnePiece) {
  const demos::CompareCase c = demos::make_case("bunny-smooth", 20000, SamplingVariant{}, 1);
  const ReconstructionResult<3> r = reconstruct<3>(c.points);
  const SurfaceTopology t = analyze_surface(r.surface.vertices, r.surface.facets);
  EXPECT_TRUE(t.watertight && t.edge_manifold && t.vertex_manifold);
  EXPECT_EQ(t.genus, c.genus);
}

}  // namespace
}  // namespace lsr
