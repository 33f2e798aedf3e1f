// SPDX-License-Identifier: BSD-3-Clause
/// @file vertex_leaf_lists.h
/// @brief The leaves around each vertex of a bisection forest, for its conforming closure: up to
/// `Slots` per vertex in fixed slots, in chunks that never move; a longer list moves to a
/// vector of its own.
///
/// A std::vector per vertex cost the serial bisection an allocation per new vertex, a
/// reallocation for each list that outgrew its reservation and a free per vertex at the end.
#pragma once

#include "lsrecon/core/types.h"

#include <algorithm>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace lsr {

template <int Slots>
class VertexLeafLists {
  static_assert(Slots > 0 && Slots < 255, "the count byte also marks a moved list");

 public:
  /// A vertex's leaves, in the order std::vector's push_back and swap-with-last erase give.
  struct Leaves {
    const Index* first;
    const Index* last;
    const Index* begin() const { return first; }
    const Index* end() const { return last; }
  };

  /// Appends an empty list (for the next vertex).
  void add_vertex() {
    if (count_.size() % kChunk == 0) chunks_.emplace_back(kChunk * Slots);
    count_.push_back(0);
  }
  bool empty() const { return count_.empty(); }

  Leaves leaves(Index v) const {
    if (count_[std::size_t(v)] == kMoved) {
      const std::vector<Index>& list = moved_.at(v);
      return {list.data(), list.data() + list.size()};
    }
    const Index* first = slots(v);
    return {first, first + count_[std::size_t(v)]};
  }

  void push(Index v, Index leaf) {
    std::uint8_t& count = count_[std::size_t(v)];
    if (count == kMoved) {
      moved_[v].push_back(leaf);
    } else if (count == Slots) {
      std::vector<Index>& list = moved_[v];
      list.assign(slots(v), slots(v) + Slots);
      list.push_back(leaf);
      count = kMoved;
    } else {
      slots(v)[count++] = leaf;
    }
  }

  /// Removes `leaf`, which v's list holds: the last leaf takes its place.
  void erase(Index v, Index leaf) {
    std::uint8_t& count = count_[std::size_t(v)];
    if (count == kMoved) {
      std::vector<Index>& list = moved_[v];
      *std::find(list.begin(), list.end(), leaf) = list.back();
      list.pop_back();
    } else {
      Index* first = slots(v);
      Index* last = first + count - 1;
      *std::find(first, last, leaf) = *last;
      --count;
    }
  }

  /// Frees everything.
  void clear() {
    chunks_ = {};
    count_ = {};
    moved_ = {};
  }

 private:
  static constexpr std::size_t kChunk = 4096;  ///< vertices per chunk
  static constexpr std::uint8_t kMoved = 255;  ///< count of a list moved to `moved_`

  Index* slots(Index v) { return chunks_[std::size_t(v) / kChunk].data() + std::size_t(v) % kChunk * Slots; }
  const Index* slots(Index v) const {
    return chunks_[std::size_t(v) / kChunk].data() + std::size_t(v) % kChunk * Slots;
  }

  std::vector<std::vector<Index>> chunks_;
  std::vector<std::uint8_t> count_;
  std::unordered_map<Index, std::vector<Index>> moved_;
};

}  // namespace lsr
