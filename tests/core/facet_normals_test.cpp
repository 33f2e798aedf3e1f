// SPDX-License-Identifier: BSD-3-Clause
/// @file facet_normals_test.cpp
/// @brief Vertex normals from facets on a flat grid, whose every facet's normal is +z.
#include "surface/facet_normals.h"

#include <gtest/gtest.h>

namespace lsr {
namespace {

// n x n vertices at integer (i, j, 0), each square split along its (1, 1) diagonal.
LevelSetMesh<3> flat_grid(int n) {
  LevelSetMesh<3> s;
  const auto id = [n](int i, int j) { return Index(i * n + j); };
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) s.vertices.push_back(Vec<3>(i, j, 0.0));
  }
  for (int i = 0; i + 1 < n; ++i) {
    for (int j = 0; j + 1 < n; ++j) {
      s.facets.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      s.facets.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  }
  return s;
}

TEST(FacetNormals, AreaNormalsAreOrientedAndScaledByTheMeasure) {
  const Points<3> x{Vec<3>(0, 0, 0), Vec<3>(2, 0, 0), Vec<3>(0, 3, 0)};
  EXPECT_EQ(facet_area_normal<3>(x, {0, 1, 2}), Vec<3>(0, 0, 6));   // twice the area 3
  EXPECT_EQ(facet_area_normal<3>(x, {0, 2, 1}), Vec<3>(0, 0, -6));  // the other way round
  const Points<2> y{Vec<2>(1, 1), Vec<2>(1, 4)};
  EXPECT_EQ(facet_area_normal<2>(y, {0, 1}), Vec<2>(3, 0));  // a segment going up: its right
}

TEST(FacetNormals, ReplaceFlaggedNormalsAndThoseAgainstTheFacetsOnly) {
  const LevelSetMesh<3> grid = flat_grid(3);
  const Vec<3> tilted(0.6, 0.0, 0.8);
  Points<3> normals(grid.vertices.size(), tilted);
  normals[1] = Vec<3>(0.0, 0.6, -0.8);  // against its facets: the fit's of another sheet
  normals[5] = Vec<3>(1.0, 0.0, 0.0);   // perpendicular to them: not against, kept
  std::vector<char> flagged(grid.vertices.size(), 0);
  flagged[2] = 1;
  set_facet_normals(grid, flagged, normals);
  for (std::size_t v = 0; v < normals.size(); ++v) {
    const Vec<3> expected = v == 1 || v == 2 ? Vec<3>(0, 0, 1) : v == 5 ? Vec<3>(1, 0, 0) : tilted;
    EXPECT_EQ(normals[v], expected) << v;
  }
  Points<3> unflagged(grid.vertices.size(), tilted);
  set_facet_normals(grid, {}, unflagged);  // no flags: only those against their facets
  EXPECT_EQ(unflagged, Points<3>(grid.vertices.size(), tilted));
}

}  // namespace
}  // namespace lsr
