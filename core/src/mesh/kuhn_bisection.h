// SPDX-License-Identifier: BSD-3-Clause
/// @file kuhn_bisection.h
/// @brief Conforming bisection refinement of a Kuhn triangulation of the unit box [0,1]^D
/// (newest-vertex bisection in 2D, Maubach's bisection in 3D; one algorithm for both).
///
/// The background mesh splits each cube of an n^D grid into D! Kuhn simplices
/// (x0, x0 + e_p1, x0 + e_p1 + e_p2, ...), all tagged D. A tagged simplex (x0, ..., xD) with
/// tag g is bisected at the midpoint z of its refinement edge (x0, xg) into
///   (x0, ..., x_{g-1}, z, x_{g+1}, ..., xD) and (x1, ..., xg, z, x_{g+1}, ..., xD),
/// both tagged g - 1 (or D when g = 1) [Maubach 1995; Stevenson 2008]. The Kuhn grid meets
/// Stevenson's matching condition, so the recursive closure below terminates and every mesh
/// it produces is conforming; shapes fall in finitely many similarity classes. New vertices
/// are edge midpoints: no geometric predicate can fail.
///
/// The forest keeps every simplex ever created, so a point is located by descending from its
/// Kuhn root (see point_location.h).
#pragma once

#include "lsrecon/core/large_array_allocator.h"
#include "lsrecon/core/types.h"
#include "mesh/vertex_leaf_lists.h"

#include <array>
#include <cstdint>
#include <vector>

namespace lsr {

/// @brief One node of the bisection forest.
template <int D>
struct ForestSimplex {
  std::array<Index, D + 1> v{};  ///< vertices in Maubach order: refinement edge (v[0], v[tag])
  Index first_child = -1;        ///< children are first_child and first_child + 1; -1: a leaf
  Index parent = -1;             ///< -1 for a Kuhn root
  std::uint8_t tag = D;
  std::uint8_t level = 0;  ///< bisections since its Kuhn root
};

/// @brief The bisection forest over a Kuhn triangulation of [0,1]^D.
template <int D>
class KuhnBisectionForest {
 public:
  static constexpr int kRootsPerCell = D == 2 ? 2 : 6;  ///< D!

  /// @brief The Kuhn triangulation of a grid of cells_per_axis^D cubes.
  /// @throw InvalidInput if cells_per_axis < 1 or the grid would exceed 2^30 vertices.
  explicit KuhnBisectionForest(int cells_per_axis);

  int cells_per_axis() const { return cells_; }
  const Points<D>& vertices() const { return vertices_; }
  const LargeVector<ForestSimplex<D>>& simplices() const { return simplices_; }
  bool is_leaf(Index s) const { return simplices_[s].first_child < 0; }
  Index leaf_count() const { return leaf_count_; }

  /// @brief The root simplex of a grid cell, with roots listed per cell in the order of
  /// permutations(): root = cell_linear_index * D! + permutation index.
  Index root(Index cell_linear_index, int permutation) const {
    return cell_linear_index * kRootsPerCell + permutation;
  }
  /// @brief The D! axis orders of the Kuhn simplices, in std::next_permutation order.
  static const std::array<std::array<int, D>, kRootsPerCell>& permutations();

  /// @brief Size of a simplex: its longest edge / sqrt(D). For a Kuhn simplex this is the side
  /// of its cube; the D - 1 intermediate bisection levels lie between two cube sides. The
  /// simplices of one level are congruent [Maubach 1995]: the size of the first one of its
  /// level, read without its vertices. On a power-of-two grid (the adaptive mesh's) every
  /// coordinate is dyadic and that size is each one's to the bit; on others, to a few 2^-53.
  double size(Index s) const { return level_size_[simplices_[s].level]; }

  /// @brief Bisects leaf s, after bisecting whatever neighbours the conforming closure needs
  /// (the mesh of leaves is conforming before and after).
  void refine(Index s);

  /// @brief Room for this many nodes in all (never shrinks): refine() then appends without
  /// moving the forest.
  void reserve(std::size_t nodes) { simplices_.reserve(nodes); }

  /// @brief Frees the vertex-to-leaf lists refine() needs; refine() must not be called after.
  void finish_refinement();

 private:
  void refine(Index s, int depth);
  double measured_size(Index s) const;
  bool has_refinement_edge(Index s, Index a, Index b) const;
  bool contains(Index s, Index vertex) const;
  void bisect(Index s, Index midpoint);

  int cells_ = 0;
  Points<D> vertices_;
  LargeVector<ForestSimplex<D>> simplices_;
  /// 48 slots in 3D (docs/calibration.md); longer lists move out.
  VertexLeafLists<D == 2 ? 16 : 48> leaves_at_vertex_;
  std::vector<double> level_size_;  ///< size() per level
  std::vector<Index> patch_;  ///< the leaves around the edge refine() bisects
  Index leaf_count_ = 0;
};

}  // namespace lsr
