// SPDX-License-Identifier: BSD-3-Clause
/// @file disjoint_sets.h
/// @brief Union-find over 0..n-1 (path halving; the smaller index is the root, so roots, and
/// anything numbered by them, do not depend on the order of the unions).
#pragma once

#include "lsrecon/core/types.h"

#include <algorithm>
#include <numeric>
#include <vector>

namespace lsr::detail {

class DisjointSets {
 public:
  explicit DisjointSets(std::size_t n = 0) : parent_(n) { std::iota(parent_.begin(), parent_.end(), Index(0)); }
  /// @brief A new singleton set; its index.
  Index add() {
    parent_.push_back(Index(parent_.size()));
    return parent_.back();
  }
  void clear() { parent_.clear(); }
  std::size_t size() const { return parent_.size(); }
  /// @brief The root of x's set: its smallest index.
  Index find(Index x) {
    while (parent_[std::size_t(x)] != x) {
      parent_[std::size_t(x)] = parent_[std::size_t(parent_[std::size_t(x)])];
      x = parent_[std::size_t(x)];
    }
    return x;
  }
  /// @brief Joins the sets of a and b; whether they were apart.
  bool unite(Index a, Index b) {
    a = find(a);
    b = find(b);
    if (a == b) return false;
    parent_[std::size_t(std::max(a, b))] = std::min(a, b);
    return true;
  }

 private:
  std::vector<Index> parent_;
};

}  // namespace lsr::detail
