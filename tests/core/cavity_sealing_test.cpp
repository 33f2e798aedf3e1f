// SPDX-License-Identifier: BSD-3-Clause
/// @file cavity_sealing_test.cpp
/// @brief A wall flood given back the cavities it entered through openings narrower than the
/// radius, and only those: exact distances to curves on a uniform 2D Kuhn mesh.
#include "mesh/adaptive_refinement.h"
#include "mesh/kuhn_bisection.h"
#include "start/cavity_sealing.h"
#include "start/outside_flood_fill.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>

namespace lsr {
namespace {

constexpr double kGap = 0.02;     // the flood stays this far from the data
constexpr double kRadius = 0.06;  // openings narrower than this (half-width) are sealed
const Vec<2> kCentre(0.5, 0.5);
constexpr double kRing = 0.25;

double segment_distance(const Vec<2>& p, const Vec<2>& a, const Vec<2>& b) {
  const double t = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
  return (p - a - t * (b - a)).norm();
}

// Distance to the ring of radius kRing with an opening of half-width `opening` around angle 0.
double open_ring_distance(const Vec<2>& p, double opening) {
  const double half_angle = std::asin(opening / kRing);
  const Vec<2> x = p - kCentre;
  if (std::abs(std::atan2(x.y(), x.x())) >= half_angle) return std::abs(x.norm() - kRing);
  const Vec<2> end(kRing * std::cos(half_angle), kRing * std::sin(half_angle));
  return std::min((x - end).norm(), (x - Vec<2>(end.x(), -end.y())).norm());
}

struct Flood {
  SimplexMesh<2> mesh;
  std::vector<char> reached;
  int sealed = 0;
};

Flood flood_and_seal(const std::function<double(const Vec<2>&)>& distance) {
  Flood f;
  f.mesh = leaf_mesh(KuhnBisectionForest<2>(128)).mesh;
  const VertexNeighbours neighbours = vertex_neighbours(f.mesh, 1);
  Eigen::VectorXd clearance(Eigen::Index(f.mesh.vertices.size()));
  std::vector<char> passable(f.mesh.vertices.size());
  for (std::size_t v = 0; v < passable.size(); ++v) {
    clearance[Eigen::Index(v)] = distance(f.mesh.vertices[v]);
    passable[v] = clearance[Eigen::Index(v)] > kGap;
  }
  f.reached = flood_from_walls(f.mesh, passable);
  const SealedCavities sealed = seal_cavities(f.mesh, neighbours, clearance, kRadius, f.reached);
  f.sealed = sealed.count;
  // The mouth: given back, next to the flood, and at the opening.
  EXPECT_EQ(sealed.mouth.empty(), sealed.count == 0);
  for (std::size_t v = 0; v < sealed.mouth.size(); ++v) {
    if (!sealed.mouth[v]) continue;
    EXPECT_FALSE(f.reached[v]);
    EXPECT_LT((f.mesh.vertices[v] - kCentre - Vec<2>(kRing, 0.0)).norm(), kRadius) << f.mesh.vertices[v].transpose();
  }
  return f;
}

bool reached_at(const Flood& f, const Vec<2>& x) {
  for (std::size_t v = 0; v < f.mesh.vertices.size(); ++v) {
    if ((f.mesh.vertices[v] - x).norm() < 1e-9) return f.reached[v];
  }
  ADD_FAILURE() << "no vertex at " << x.transpose();
  return false;
}

TEST(CavitySealing, GivesBackARingEnteredThroughANarrowOpening) {
  // Half-width 0.04: wider than the gap (the flood enters), narrower than the radius.
  const Flood f = flood_and_seal([](const Vec<2>& p) { return open_ring_distance(p, 0.04); });
  EXPECT_EQ(f.sealed, 1);
  EXPECT_FALSE(reached_at(f, kCentre));
  for (std::size_t v = 0; v < f.mesh.vertices.size(); ++v) {
    const double r = (f.mesh.vertices[v] - kCentre).norm();
    // Inside, short of the opening's mouth (within an opening's width of it), nothing is left.
    if (r < kRing - 0.1) {
      EXPECT_FALSE(f.reached[v]) << f.mesh.vertices[v].transpose();
    }
    // The outside stays: everything a gap beyond the ring is reached.
    if (r > kRing + kGap + 0.01) {
      EXPECT_TRUE(f.reached[v]) << f.mesh.vertices[v].transpose();
    }
  }
}

TEST(CavitySealing, LeavesARingWhoseOpeningIsWiderThanTheRadius) {
  const Flood f = flood_and_seal([](const Vec<2>& p) { return open_ring_distance(p, 0.12); });
  EXPECT_EQ(f.sealed, 0);
  EXPECT_TRUE(reached_at(f, kCentre));
}

TEST(CavitySealing, LeavesAClosedRingAndANarrowDeadEndSlotAlone) {
  // The flood does not enter the closed ring; the slot (half-width 0.04, closed at x = 0.8)
  // is entered, but it holds no vertex farther than the radius from its walls: outside.
  const Vec<2> a(0.1, 0.06), b(0.8, 0.06), c(0.8, 0.14), d(0.1, 0.14);
  const Flood f = flood_and_seal([&](const Vec<2>& p) {
    const double slot = std::min({segment_distance(p, a, b), segment_distance(p, b, c), segment_distance(p, c, d)});
    return std::min(slot, open_ring_distance(p, 0.0));
  });
  EXPECT_EQ(f.sealed, 0);
  EXPECT_FALSE(reached_at(f, kCentre));
  EXPECT_TRUE(reached_at(f, Vec<2>(0.75, 0.09375)));  // near the slot's far end, on a vertex
}

}  // namespace
}  // namespace lsr
