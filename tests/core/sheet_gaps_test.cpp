// SPDX-License-Identifier: BSD-3-Clause
/// @file sheet_gaps_test.cpp
/// @brief A gap between two facing sheets is found; the inside of a thin slab, a hole in one
/// sheet and a sheet's own noise band are not gaps.
#include "fit/sheet_gaps.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace lsr {
namespace {

// 4000 random points of the square [0.2, 0.8]^2 at height z (spacing sqrt(0.36 / 4000) =
// 0.0095), without the disc of radius `hole` at (0.5, 0.5), each with normal (0, 0, nz).
void add_sheet(double z, double nz, double hole, unsigned seed, Points<3>& p, Points<3>& n) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.2, 0.8);
  for (int i = 0; i < 4000;) {
    const Vec<3> x(u(rng), u(rng), z);
    if (std::hypot(x.x() - 0.5, x.y() - 0.5) <= hole) continue;
    p.push_back(x);
    n.push_back(Vec<3>(0.0, 0.0, nz));
    ++i;
  }
}

constexpr double kSpacing = 0.0095;

// Queries on a 7 x 7 grid of the square's middle at height z.
Points<3> grid_at(double z) {
  Points<3> q;
  for (int i = 0; i < 7; ++i) {
    for (int j = 0; j < 7; ++j) q.push_back(Vec<3>(0.35 + 0.05 * i, 0.35 + 0.05 * j, z));
  }
  return q;
}

std::vector<char> gaps(const Points<3>& p, const Points<3>& n, const Points<3>& q) {
  const NearestPointIndex<3> data(p);
  std::vector<double> d;
  data.query(q, d);
  return between_facing_sheets(data, n, q, d, std::vector<double>(q.size(), kSpacing));
}

TEST(SheetGaps, FindTheMiddleOfAGapBetweenFacingSheets) {
  // Sheets 4 spacings apart, facing each other (the lower one's outside is up). A query in the
  // middle misses only if one sheet has no point within 30 degrees of the normal through it
  // (a disc of radius 0.011: 4.2 points expected, none with probability 1.5%) and none of the
  // near pairs within 37 degrees each makes up for it: expected misses well below 1 of 49.
  Points<3> p, n;
  add_sheet(0.48, 1.0, 0.0, 1, p, n);
  add_sheet(0.52, -1.0, 0.0, 2, p, n);
  const std::vector<char> in_gap = gaps(p, n, grid_at(0.5));
  EXPECT_GE(std::count(in_gap.begin(), in_gap.end(), 1), 47);
}

TEST(SheetGaps, TheInsideOfAThinSlabIsNoGap) {
  // The same sheets as the two sides of one slab: their outward normals point away from the
  // query, which faces none of them.
  Points<3> p, n;
  add_sheet(0.48, -1.0, 0.0, 1, p, n);
  add_sheet(0.52, 1.0, 0.0, 2, p, n);
  const std::vector<char> in_gap = gaps(p, n, grid_at(0.5));
  EXPECT_EQ(std::count(in_gap.begin(), in_gap.end(), 1), 0);
}

TEST(SheetGaps, AHoleInOneSheetIsNoGap) {
  // Across a hole of radius 0.05 the rim points lie on all sides of its middle, but at most
  // 0.005 below it over at least 0.05 sideways: within 6 degrees of their tangent planes.
  Points<3> p, n;
  add_sheet(0.5, 1.0, 0.05, 1, p, n);
  const Points<3> q = {Vec<3>(0.5, 0.5, 0.5), Vec<3>(0.5, 0.5, 0.505), Vec<3>(0.51, 0.49, 0.503)};
  const std::vector<char> in_gap = gaps(p, n, q);
  EXPECT_EQ(std::count(in_gap.begin(), in_gap.end(), 1), 0);
}

TEST(SheetGaps, ASheetsNoiseBandIsNoGap) {
  // Noise of a third of a spacing scatters points above and below a query in the sheet, and
  // those face it; a query nearer than a spacing to the data is in the band, not in a gap.
  Points<3> p, n;
  add_sheet(0.5, 1.0, 0.0, 1, p, n);
  std::mt19937_64 rng(3);
  std::normal_distribution<double> noise(0.0, kSpacing / 3);
  for (Vec<3>& x : p) x.z() += noise(rng);
  Points<3> q;
  for (std::size_t i = 0; i < p.size(); i += 40) q.push_back(p[i] + Vec<3>(0.0, 0.0, 0.3 * kSpacing));
  const std::vector<char> in_gap = gaps(p, n, q);
  EXPECT_EQ(std::count(in_gap.begin(), in_gap.end(), 1), 0);
}

}  // namespace
}  // namespace lsr
