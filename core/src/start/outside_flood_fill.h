// SPDX-License-Identifier: BSD-3-Clause
/// @file outside_flood_fill.h
/// @brief Connected components of vertex subsets, and the "tagging" start of Zhao, Osher and Fedkiw (2001): the mesh vertices that can be
/// reached from the walls of the box without coming closer to the data than the local sampling
/// gap. Its boundary is a closed front hugging the data from outside at that distance, with the
/// topology the data allows at that scale (tunnels wider than the gap are open, sampling holes
/// narrower than it are sealed).
#pragma once

#include "lsrecon/core/simplex_geometry.h"

#include <vector>

namespace lsr {

/// @brief Connected components of a subset of the vertices through the mesh edges joining two
/// members: per vertex, the lowest vertex index of its component, or -1 for non-members.
/// Union-find over the edges of the simplices: linear in the mesh, no adjacency lists.
/// @param member #V flags
template <int D>
std::vector<Index> vertex_components(const SimplexMesh<D>& mesh, const std::vector<char>& member);

/// @brief True on the boundary of the box [0,1]^D (or outside it).
template <int D>
bool on_wall(const Vec<D>& x);

/// @brief Marks (1) the vertices connected to a wall vertex of the box [0,1]^D through mesh
/// edges whose two ends are both passable. Wall vertices that are not passable are not reached.
/// @param passable #V flags
template <int D>
std::vector<char> flood_from_walls(const SimplexMesh<D>& mesh, const std::vector<char>& passable);

/// @brief The same flood from the passable vertices' components (vertex_components), for a
/// caller that needs them too.
template <int D>
std::vector<char> flood_from_walls(const SimplexMesh<D>& mesh, const std::vector<Index>& component);

}  // namespace lsr
