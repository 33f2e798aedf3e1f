// SPDX-License-Identifier: BSD-3-Clause
/// @file normal_propagation_test.cpp
/// @brief Senses propagated along the normals' smoothest paths: consistent on a closed sphere
/// whose normals were flipped at random, one tree per separate piece.
#include "start/normal_propagation.h"

#include "geometry/nearest_point_index.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

namespace lsr::detail {
namespace {

// n Fibonacci points of a sphere of radius r at c, and their outward normals.
void sphere(int n, double r, const Vec<3>& c, Points<3>& p, Points<3>& normals) {
  const double golden = kPi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - 2.0 * (i + 0.5) / n, s = std::sqrt(1.0 - z * z);
    const Vec<3> u(s * std::cos(golden * i), s * std::sin(golden * i), z);
    p.push_back(c + r * u);
    normals.push_back(u);
  }
}

constexpr int kNeighbours = 16;

PropagatedSenses propagate(const Points<3>& p, const Points<3>& normals, const std::vector<double>& noise = {}) {
  const NearestPointIndex<3> index(p);
  LargeVector<Index> knn;
  index.query_k(p, kNeighbours, knn);
  return propagate_senses<3>(p, normals, knn, kNeighbours, noise);
}

// How many normals, times their senses, point the other way from the first.
std::size_t inconsistent(const PropagatedSenses& s, const Points<3>& flipped, const Points<3>& outward) {
  std::size_t wrong = 0;
  const double first = s.sense[0] * flipped[0].dot(outward[0]);
  for (std::size_t i = 0; i < outward.size(); ++i) wrong += s.sense[i] * flipped[i].dot(outward[i]) * first < 0.0;
  return wrong;
}

// Every third normal flipped (and one in seven more): after propagation each normal times its
// sense points the same way out of the sphere, outwards for all or inwards for all.
TEST(NormalPropagation, FlippedNormalsOfASphereComeOutConsistent) {
  Points<3> p, outward;
  sphere(3000, 1.0, Vec<3>::Zero(), p, outward);
  Points<3> flipped = outward;
  for (std::size_t i = 0; i < flipped.size(); ++i) {
    if (i % 3 == 0 || i % 7 == 0) flipped[i] = -flipped[i];
  }
  const PropagatedSenses s = propagate(p, flipped);
  ASSERT_EQ(s.parts, 1);
  const double first = s.sense[0] * flipped[0].dot(outward[0]);
  for (std::size_t i = 0; i < p.size(); ++i) ASSERT_GT(s.sense[i] * flipped[i].dot(outward[i]) * first, 0.0) << i;
}

// Two spheres far apart (no point's 16 nearest reach across): two trees, each consistent.
TEST(NormalPropagation, SeparatePiecesAreSeparateTrees) {
  Points<3> p, outward;
  sphere(1000, 1.0, Vec<3>::Zero(), p, outward);
  sphere(1000, 1.0, Vec<3>(5, 0, 0), p, outward);
  Points<3> flipped = outward;
  for (std::size_t i = 0; i < flipped.size(); i += 2) flipped[i] = -flipped[i];
  const PropagatedSenses s = propagate(p, flipped);
  ASSERT_EQ(s.parts, 2);
  for (const std::size_t first : {std::size_t(0), std::size_t(1000)}) {
    const double sign = s.sense[first] * flipped[first].dot(outward[first]);
    for (std::size_t i = first; i < first + 1000; ++i) {
      ASSERT_EQ(s.part[i], s.part[first]);
      ASSERT_GT(s.sense[i] * flipped[i].dot(outward[i]) * sign, 0.0) << i;
    }
  }
}

// Sheets closer than the sampling's spacing (0.065 here) facing each other: two spheres 0.04
// apart, and a shell 0.03 thick (its inner sphere's outward normals point inwards). Across the
// gap the normals are antiparallel, so the plain rule (n_p . n_q) flips one sheet against the
// other; against n_p mirrored in the chord's bisecting plane they agree, as along each sheet.
TEST(NormalPropagation, SheetsFacingAcrossAGapStayConsistent) {
  for (const bool shell : {false, true}) {
    Points<3> p, outward;
    sphere(3000, 1.0, Vec<3>::Zero(), p, outward);
    if (shell) {
      sphere(3000, 0.97, Vec<3>::Zero(), p, outward);
      for (std::size_t i = 3000; i < p.size(); ++i) outward[i] = -outward[i];
    } else {
      sphere(3000, 1.0, Vec<3>(2.04, 0, 0), p, outward);
    }
    Points<3> flipped = outward;
    for (std::size_t i = 0; i < flipped.size(); i += 3) flipped[i] = -flipped[i];
    const PropagatedSenses s = propagate(p, flipped);
    ASSERT_EQ(s.parts, 1) << shell;  // the k-nearest graph joins the sheets
    const double sign = s.sense[0] * flipped[0].dot(outward[0]);
    for (std::size_t i = 0; i < p.size(); ++i) ASSERT_GT(s.sense[i] * flipped[i].dot(outward[i]) * sign, 0.0) << shell << " " << i;
  }
}

// A sphere sampled on a band three spacings either side (radial offsets uniform in +-0.2, the
// spacing of 3000 points being 0.065; deviation 0.2 / sqrt 3), as noise of about twice the
// spacing leaves it: neighbours across the band have chords along the normals, which the mirror
// reads as sheets facing each other, and senses flip between them. Told the noise, the chord's
// offset along the normal within two deviations of the difference of two offsets is taken off,
// and the band is one sheet.
TEST(NormalPropagation, ANoisyBandIsOneSheet) {
  Points<3> p, outward;
  sphere(3000, 1.0, Vec<3>::Zero(), p, outward);
  const double half_width = 0.2;
  std::uint32_t state = 1;
  for (Vec<3>& x : p) {
    state = state * 1664525u + 1013904223u;  // a fixed LCG: the same offsets everywhere
    x *= 1.0 + half_width * (2.0 * double(state >> 8) / double(1u << 24) - 1.0);
  }
  Points<3> flipped = outward;
  for (std::size_t i = 0; i < flipped.size(); i += 3) flipped[i] = -flipped[i];
  EXPECT_GT(inconsistent(propagate(p, flipped), flipped, outward), 0u);
  const std::vector<double> noise(p.size(), half_width / std::sqrt(3.0));
  EXPECT_EQ(inconsistent(propagate(p, flipped, noise), flipped, outward), 0u);
}

}  // namespace
}  // namespace lsr::detail
