// SPDX-License-Identifier: BSD-3-Clause
/// @file simplex_geometry.h
/// @brief A simplicial mesh (triangles in 2D, tetrahedra in 3D) and the per-simplex geometry
/// the P1 operators need: measures, barycentric-coordinate gradients and vertex balls.
#pragma once

#include "lsrecon/core/large_array_allocator.h"
#include "lsrecon/core/types.h"

#include <array>
#include <vector>

namespace lsr {

/// @brief Vertices and simplices. Simplices list D + 1 vertex indices, positively oriented
/// (det[x1 - x0, ..., xD - x0] > 0) when produced by lsrecon.
template <int D>
struct SimplexMesh {
  Points<D> vertices;                            ///< #V points of R^D
  LargeVector<std::array<Index, D + 1>> simplices;  ///< #S simplices (on huge pages once large)
};

/// @brief det[x1 - x0, ..., xD - x0] / D!: the measure of simplex s, negative when it is
/// negatively oriented.
template <int D>
double signed_measure(const SimplexMesh<D>& mesh, Index s);

/// @brief CSR vertex adjacency: the vertices sharing an edge with vertex i are
/// neighbours[offsets[i] .. offsets[i + 1]), in ascending order.
struct VertexNeighbours {
  LargeVector<Index> offsets;
  LargeVector<Index> neighbours;
};

/// @brief The edge graph of a mesh.
/// @param threads threads for sorting the rows, 0 for all cores
template <int D>
VertexNeighbours vertex_neighbours(const SimplexMesh<D>& mesh, int threads = 0);

/// @brief Geometry of a fixed mesh, computed once: what eq. (10)-(14) of the paper sum over.
template <int D>
struct SimplexGeometry {
  LargeVector<double> measure;  ///< #S: |K|
  /// #S: gradient of the barycentric coordinate of the j-th vertex of K (constant on K).
  std::vector<std::array<Vec<D>, D + 1>> gradients;
  /// CSR adjacency of the balls B_i: the simplices containing vertex i are
  /// ball_simplices[ball_offsets[i] .. ball_offsets[i + 1]).
  LargeVector<Index> ball_offsets;
  LargeVector<Index> ball_simplices;
  std::vector<double> ball_measure;  ///< #V: |B_i| = sum of |K| over B_i
};

/// @brief Computes measures, balls and, with_gradients, the gradients (96 bytes per
/// tetrahedron, a third of the pipeline's peak at 200k points: without them, consumers compute
/// each simplex's gradients when they need them, barycentric_gradients()).
/// @throw InvalidInput if a simplex is degenerate (zero measure).
template <int D>
SimplexGeometry<D> compute_simplex_geometry(const SimplexMesh<D>& mesh, bool with_gradients = true);

/// @brief The edge graph of a mesh from the balls of its geometry (the same graph as
/// vertex_neighbours(mesh), without listing the balls again).
template <int D>
VertexNeighbours vertex_neighbours(const SimplexMesh<D>& mesh, const SimplexGeometry<D>& geometry, int threads = 0);

/// @brief The gradients of the barycentric coordinates of simplex s (one per vertex).
template <int D>
std::array<Vec<D>, D + 1> barycentric_gradients(const SimplexMesh<D>& mesh, Index s);

}  // namespace lsr
