// SPDX-License-Identifier: BSD-3-Clause
/// @file level_set_extraction.h
/// @brief The zero level set of a P1 nodal field: marching triangles (2D, closed polylines)
/// and marching tetrahedra (3D, a triangle surface).
///
/// Output vertices are keyed by the mesh edge they lie on, so the result is welded and, on a
/// conforming mesh, closed and manifold by construction. They are numbered by their edges
/// (a < b) in the order of a, then b; facets follow the simplices. Runs in parallel, with the
/// same result on any number of threads. A nodal value of exactly 0 counts as
/// positive, so the level set never passes through a mesh vertex. Facets are oriented with
/// their normals towards u > 0 (outwards when u < 0 inside).
#pragma once

#include "lsrecon/core/simplex_geometry.h"

#include <array>
#include <vector>

namespace lsr {

/// @brief The extracted zero set: segments (D = 2) or triangles (D = 3).
template <int D>
struct LevelSetMesh {
  Points<D> vertices;                       ///< #V points on mesh edges
  std::vector<std::array<Index, D>> facets;  ///< #F oriented segments / triangles
  /// #V: the mesh edge (a < b) each vertex lies on and its parameter t in (0, 1), so that
  /// vertex = (1 - t) x_a + t x_b. Handy for normals, attributes and tests.
  std::vector<EdgePoint> sources;
};

/// @brief The position of an edge point, computed as the extraction computes it.
template <int D>
Vec<D> edge_point_position(const SimplexMesh<D>& mesh, const EdgePoint& e) {
  return (1.0 - e.t) * mesh.vertices[e.a] + e.t * mesh.vertices[e.b];
}

/// @brief The diagonal along which marching tetrahedra cuts the quad (q0, q1, q2, q3) into two
/// triangles: true for q0-q2 (the shorter one), false for q1-q3. The volume split
/// (level_set_volume_mesh.h) follows the same rule so that its interface is the surface.
template <int D>
bool split_quad_along_02(const Vec<D>& q0, const Vec<D>& q1, const Vec<D>& q2, const Vec<D>& q3) {
  return (q0 - q2).squaredNorm() <= (q1 - q3).squaredNorm();
}

/// @brief Extracts {u = 0}. u holds one value per mesh vertex.
/// @param edge_margin output vertices stay this fraction of their edge (clamped to
/// [1e-9, 0.25]) away from its ends: a mesh vertex just off the level set otherwise makes
/// output vertices closer than any weld tolerance (seen at 200k points).
/// @param threads 0 for all cores
/// @throw InvalidInput if u has the wrong size or a non-finite value.
template <int D>
LevelSetMesh<D> extract_zero_level_set(const SimplexMesh<D>& mesh, const std::vector<double>& u,
                                       double edge_margin = 1e-9, int threads = 0);

/// @brief Orders the segments of a 2D zero set into closed loops, each a list of vertex
/// indices in order (the last joins the first). The negative side is on the left: outer
/// boundaries of u < 0 run counter-clockwise.
/// @throw InvalidInput if a vertex does not have exactly one incoming and one outgoing segment.
std::vector<std::vector<Index>> closed_loops(const LevelSetMesh<2>& curves);

}  // namespace lsr
