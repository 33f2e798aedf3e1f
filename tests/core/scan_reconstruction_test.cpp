// SPDX-License-Identifier: BSD-3-Clause
/// @file scan_reconstruction_test.cpp
/// @brief Simulated line scans (testdata/simulated_scan.h) reconstruct with the right topology:
/// dense lines with wide gaps between them, range noise and misregistered views, from all sides
/// and from above only (the underside unseen, closed by the front).
#include "checks/exact_self_intersections.h"
#include "lsrecon/core/level_set_reconstruction.h"
#include "lsrecon/testdata/simulated_scan.h"
#include "surface/surface_topology.h"

#include <gtest/gtest.h>

#include <cstdint>

namespace lsr {
namespace {

// 6 views of 40 lines x 400 samples each (10:1 along / across), optionally from above only.
ScannerSettings test_scanner(bool from_above) {
  ScannerSettings s;
  s.lines = 40;
  s.samples_per_line = 400;
  s.from_above = from_above;
  return s;
}

SurfaceTopology scan_topology(const std::string& shape, const ScannerSettings& settings, std::uint64_t seed = 2011) {
  const SampledShape scan = simulate_scan(make_test_shape(shape), settings, seed);
  const ReconstructionResult<3> r = reconstruct<3>(scan.points);
  EXPECT_EQ(testing::cgal_self_intersections(r.surface.vertices, r.surface.facets), 0u) << shape;  // embedded
  return analyze_surface(r.surface.vertices, r.surface.facets);
}

// 6 views of 40 lines x 400 samples (10:1 along / across), range noise 0.1%, views off by
// 0.002 rad and 0.2% of the diagonal: before the scan-line rule the torus came out of genus
// 263, the sphere in 5 parts (60 x 600 lines).
TEST(ScanReconstruction, AScannedTorusAndTwoSpheresKeepTheirTopology) {
  const ScannerSettings s = test_scanner(false);
  const SurfaceTopology torus = scan_topology("torus", s);
  EXPECT_TRUE(torus.watertight);
  EXPECT_EQ(torus.genus, std::vector<int>{1});
  const SurfaceTopology spheres = scan_topology("two-spheres", s);
  EXPECT_TRUE(spheres.watertight);
  EXPECT_EQ(spheres.genus, (std::vector<int>{0, 0}));
}

// The triple torus's middle hole is a slit 0.2 wide between two tubes, 3.6 spacings of the
// 60 x 600 scan (the scale is the gap between its lines). The front stalls short in the slit
// and its pins hold a membrane across it; the fit opens it, since the normals of both walls
// face the slit (before: genus 2).
TEST(ScanReconstruction, ASlitBetweenFacingWallsIsOpened) {
  const SurfaceTopology t = scan_topology("triple-torus", ScannerSettings());
  EXPECT_TRUE(t.watertight);
  EXPECT_EQ(t.genus, std::vector<int>{3});
}

TEST(ScanReconstruction, AnUndersideNoViewSawIsClosed) {
  const ScannerSettings s = test_scanner(true);
  const SurfaceTopology bunny = scan_topology("bunny", s);
  EXPECT_TRUE(bunny.watertight);
  EXPECT_EQ(bunny.genus, std::vector<int>{0});
}

// From above, the flood enters the sphere and the cup through their unseen undersides and wraps
// their walls from both sides: before the open sides were closed (open_side_closure.h) the
// sphere came out of genus 3 and the thin-walled cup of genus 4.
TEST(ScanReconstruction, AnOpenUndersideClosesWithoutTunnels) {
  const ScannerSettings s = test_scanner(true);
  for (const char* shape : {"sphere", "cup"}) {
    const SurfaceTopology t = scan_topology(shape, s);
    EXPECT_TRUE(t.watertight) << shape;
    EXPECT_EQ(t.genus, std::vector<int>{0}) << shape;
  }
}

// Two spheres from above: the discs spanning their undersides kept the flood out, so nothing was
// closed, and the front tunnelled between the scan lines from inside until the spheres merged
// (one component here; genus 9 at 60 x 600 lines). The open sides are now found on a flood the
// discs do not stop (start_fields.cpp).
TEST(ScanReconstruction, UndersidesTheDiscsSpanAreClosedToo) {
  const ScannerSettings s = test_scanner(true);
  const SurfaceTopology spheres = scan_topology("two-spheres", s);
  EXPECT_TRUE(spheres.watertight);
  EXPECT_EQ(spheres.genus, (std::vector<int>{0, 0}));
}

// From above, a ring's inner wall below its equator is seen at grazing angles and reached by
// the flood from both sides along paths of nearly equal length (through the hole and through
// the unseen underside), so its side is a guess; the band held behind such walls left handles
// in the torus's hole (genus 3 at this seed) and a web in a linked ring's (genus 2 and 1).
TEST(ScanReconstruction, AGrazingInnerWallSeenFromAboveLeavesTheHoleOpen) {
  ScannerSettings s;
  s.from_above = true;
  const SurfaceTopology torus = scan_topology("torus", s, 2);
  EXPECT_TRUE(torus.watertight);
  EXPECT_EQ(torus.genus, std::vector<int>{1});
  const SurfaceTopology rings = scan_topology("linked-rings", s, 2);
  EXPECT_TRUE(rings.watertight);
  EXPECT_EQ(rings.genus, (std::vector<int>{1, 1}));
}

}  // namespace
}  // namespace lsr
