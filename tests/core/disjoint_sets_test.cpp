// SPDX-License-Identifier: BSD-3-Clause
/// @file disjoint_sets_test.cpp
/// @brief The one union-find: sets as joined, each rooted at its smallest index whatever the
/// order of the unions (what makes component numbers deterministic).
#include "graph/disjoint_sets.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <utility>
#include <vector>

namespace lsr::detail {
namespace {

TEST(DisjointSets, RootsAreTheSmallestIndexWhateverTheOrder) {
  std::vector<std::pair<Index, Index>> joins = {{5, 3}, {7, 9}, {3, 8}, {9, 1}, {4, 4}};
  for (int order = 0; order < 2; ++order) {
    DisjointSets sets(10);
    for (const auto& [a, b] : joins) sets.unite(a, b);
    const std::vector<Index> expected = {0, 1, 2, 3, 4, 3, 6, 1, 3, 1};
    for (Index v = 0; v < 10; ++v) EXPECT_EQ(sets.find(v), expected[std::size_t(v)]) << v << " order " << order;
    std::reverse(joins.begin(), joins.end());
  }
}

TEST(DisjointSets, UniteSaysWhetherTheSetsWereApartAndAddGrows) {
  DisjointSets sets;
  EXPECT_EQ(sets.add(), 0);
  EXPECT_EQ(sets.add(), 1);
  EXPECT_EQ(sets.add(), 2);
  EXPECT_TRUE(sets.unite(2, 1));
  EXPECT_FALSE(sets.unite(1, 2));
  EXPECT_TRUE(sets.unite(0, 2));
  EXPECT_EQ(sets.find(1), 0);
  sets.clear();
  EXPECT_EQ(sets.size(), 0u);
}

}  // namespace
}  // namespace lsr::detail
