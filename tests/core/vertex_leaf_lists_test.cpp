// SPDX-License-Identifier: BSD-3-Clause
/// @file vertex_leaf_lists_test.cpp
/// @brief VertexLeafLists keeps each vertex's leaves in the order a std::vector with push_back
/// and swap-with-last erase would, in its slots and after a list outgrows them.
#include "mesh/vertex_leaf_lists.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

namespace lsr {
namespace {

template <int Slots>
std::vector<Index> listed(const VertexLeafLists<Slots>& lists, Index v) {
  const auto leaves = lists.leaves(v);
  return std::vector<Index>(leaves.begin(), leaves.end());
}

TEST(VertexLeafLists, MatchesVectorsThroughRandomPushesAndErasesAcrossTheSlotLimit) {
  // 4 slots and lists up to about 12 long: every vertex moves out of its slots and some come
  // back down; the chunk of 4096 vertices is crossed too.
  constexpr int kVertices = 5000;
  VertexLeafLists<4> lists;
  std::vector<std::vector<Index>> model(kVertices);
  for (int v = 0; v < kVertices; ++v) lists.add_vertex();
  std::mt19937 rng(7);
  Index next_leaf = 0;
  for (int round = 0; round < 60000; ++round) {
    const Index v = Index(rng() % kVertices);
    auto& m = model[std::size_t(v)];
    if (m.empty() || (m.size() < 12 && rng() % 3 != 0)) {
      lists.push(v, next_leaf);
      m.push_back(next_leaf++);
    } else {
      const Index leaf = m[rng() % m.size()];
      lists.erase(v, leaf);
      *std::find(m.begin(), m.end(), leaf) = m.back();
      m.pop_back();
    }
  }
  std::size_t long_lists = 0;
  for (int v = 0; v < kVertices; ++v) {
    ASSERT_EQ(listed(lists, Index(v)), model[std::size_t(v)]) << "vertex " << v;
    long_lists += model[std::size_t(v)].size() > 4;
  }
  EXPECT_GT(long_lists, 100u);  // the moved lists were exercised
  lists.clear();
  EXPECT_TRUE(lists.empty());
}

}  // namespace
}  // namespace lsr
