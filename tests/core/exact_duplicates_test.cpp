// SPDX-License-Identifier: BSD-3-Clause
/// @file exact_duplicates_test.cpp
/// @brief Equal coordinates merge into their first copy; a set without copies is unchanged; a
/// cloud given twice reconstructs exactly as once.
#include "sampling/exact_duplicates.h"

#include "lsrecon/core/level_set_reconstruction.h"
#include "lsrecon/testdata/analytic_shapes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace lsr {
namespace {

TEST(ExactDuplicates, CopiesMergeIntoTheirFirstAppearance) {
  const Points<3> p = {Vec<3>(1, 2, 3), Vec<3>(0, 0, 0), Vec<3>(1, 2, 3), Vec<3>(-0.0, 0.0, -0.0), Vec<3>(1, 2, 3.0000001),
                       Vec<3>(0, 0, 0)};
  const DistinctPoints<3> d = merge_exact_duplicates(p);
  // 0.0 and -0.0 compare equal and merge; a point 1e-7 away is another point.
  ASSERT_EQ(d.points.size(), 3u);
  EXPECT_EQ(d.duplicates(), 3u);
  EXPECT_EQ(d.first, (std::vector<std::size_t>{0, 1, 4}));
  EXPECT_EQ(d.index_of, (std::vector<std::size_t>{0, 1, 0, 1, 2, 1}));
  for (std::size_t i = 0; i < p.size(); ++i) EXPECT_EQ(d.points[d.index_of[i]], p[i]) << i;
}

TEST(ExactDuplicates, ASetWithoutCopiesComesBackInItsOrder) {
  const Points<2> p = Circle{Vec<2>(0, 0), 1.0}.sample(5000);
  const DistinctPoints<2> d = merge_exact_duplicates(p);
  EXPECT_EQ(d.points, p);
  EXPECT_EQ(d.duplicates(), 0u);
}

TEST(ExactDuplicates, ACloudGivenTwiceReconstructsExactlyAsOnce) {
  const Points<3> once = Sphere{Vec<3>(0.5, 0, 0), 1.0}.sample(2000);
  Points<3> twice = once;
  twice.insert(twice.end(), once.begin(), once.end());
  ReconstructionOptions o;
  o.limits.threads = 2;
  const ReconstructionResult<3> a = reconstruct<3>(once, o), b = reconstruct<3>(twice, o);
  EXPECT_EQ(b.duplicate_points, once.size());
  EXPECT_EQ(b.outlier_points, a.outlier_points);
  ASSERT_EQ(a.surface.vertices.size(), b.surface.vertices.size());
  for (std::size_t v = 0; v < a.surface.vertices.size(); ++v) ASSERT_EQ(a.surface.vertices[v], b.surface.vertices[v]) << v;
  EXPECT_EQ(a.surface.facets, b.surface.facets);
  // Every copy carries its original's normal.
  ASSERT_EQ(b.point_normals.size(), twice.size());
  for (std::size_t i = 0; i < once.size(); ++i) {
    EXPECT_EQ(b.point_normals[i], a.point_normals[i]) << i;
    EXPECT_EQ(b.point_normals[once.size() + i], a.point_normals[i]) << i;
  }
}

// A scanner's flood of (0,0,0) with the four corners of a tetrahedron: 4 distinct points span
// space, so a closed surface, not "1 distinct point".
TEST(ExactDuplicates, FourDistinctPointsAmongThousandsOfCopiesGiveASurface) {
  Points<3> p(2000, Vec<3>::Zero());
  for (const Vec<3>& q : {Vec<3>(1, 0, 0), Vec<3>(0, 1, 0), Vec<3>(0, 0, 1)}) p.push_back(q);
  const ReconstructionResult<3> r = reconstruct<3>(p);
  EXPECT_EQ(r.duplicate_points, 1999u);
  EXPECT_FALSE(r.surface.facets.empty());
}

}  // namespace
}  // namespace lsr
