// SPDX-License-Identifier: BSD-3-Clause
/// @file unsupported_fairing.h
/// @brief Fairs the parts of a surface that no sample lies near: the back of a single view, an
/// unseen underside, a cavity seen only at grazing angles. Nothing places the surface there but
/// the front's curvature and the switches between the fit and the front, whose zero sets come
/// out as terraces and folds an edge or a few high. One implicit step of the bilaplacian
/// flow on the surface's edge graph, (I + t L^2) x = x0 at those vertices, the others fixed,
/// damps a wave of w edges by 1 / (1 + t l^2), l = 4 (1 - cos(2 pi / w)) on a regular grid: at
/// t = 4, waves of 2 and 4 edges (terraces, folds) by 257x and 65x, of 8 edges 6.5x, of 32 by
/// 2.4% and of 64 by 0.15%, so the shape the supported part around sets is kept (t is
/// calibrated: docs/calibration.md).
/// Derivation: docs/how-it-works.md (Unsupported surface).
#pragma once

#include "lsrecon/core/level_set_extraction.h"

#include <cstddef>
#include <vector>

namespace lsr {

/// @brief A surface's edges as adjacency lists: v's neighbours are next[first[v] .. first[v + 1]).
struct EdgeGraph {
  std::vector<std::size_t> first;
  std::vector<Index> next;
};

/// @brief The edges of `surface`'s facets, each once (0.4 s at 570k vertices: built only where
/// something is to be faired, and shared by the growth and the fairing).
template <int D>
EdgeGraph edge_graph(const LevelSetMesh<D>& surface);

/// @brief Adds to `flags` every vertex `allowed` that a path of edges through allowed vertices
/// joins to a flagged one (the flagged set grown by hysteresis).
void grow_over_edges(const EdgeGraph& edges, std::vector<char>& flags, const std::vector<char>& allowed);

/// @brief Replaces the positions x0 of the vertices of `surface` flagged `free` by the solution
/// x of (I + step L^2) x = x0 there, L = degree - adjacency of the surface's edges, the other
/// vertices fixed (their positions enter the right-hand side). The matrix is symmetric
/// positive definite whatever the flags, so every free vertex has its solution.
/// @param edges edge_graph(surface)
/// @param free #V of surface.vertices
/// @param step t, in squared edges
/// @return the number of vertices moved
template <int D>
std::size_t fair_unsupported(LevelSetMesh<D>& surface, const EdgeGraph& edges, const std::vector<char>& free, double step);

}  // namespace lsr
