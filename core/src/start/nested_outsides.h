// SPDX-License-Identifier: BSD-3-Clause
/// @file nested_outsides.h
/// @brief The outside nested inside the data: the hole of an annulus or of a hollow ball, a
/// curve or surface inside another. A flood from the walls (outside_flood_fill.h) stops at the
/// outermost sheet, so everything it encloses starts inside, and the front, which moves only
/// where it is, never reaches the inner sheet ("not converged", the inner data ignored).
///
/// Sheets alternate inside and outside (the Jordan parity). The free regions (connected parts of
/// the vertices a gap from the data) are joined where they face the same data points from
/// opposite sides (across a sheet); a region's depth is its distance in that graph from the
/// flood's: 0 the flood, 1 inside the outermost sheet, 2 inside a sheet inside it, and so on.
/// Free regions of even depth are outside. Counting the data bands a path crosses instead
/// miscounts where two sheets' bands touch (a band joining them across a thin region). A
/// region that reached through a hole in a sheet the region beyond it (a hole wider than the
/// tangent discs span) is one region: an inner sheet with such a hole is a sheet in a cavity,
/// and the front closes on it from both sides.
#pragma once

#include "lsrecon/core/simplex_geometry.h"

#include <vector>

namespace lsr::detail {

/// @brief #V flags of the free vertices the flood did not reach that lie in regions of even depth.
/// Deterministic.
/// @param region #V components of the free vertices, a gap from the data (vertex_components of
/// what the flood could cross), -1 elsewhere
/// @param reached #V flags of the flood from the walls (flood_from_walls)
/// @param points, normals the data and their unoriented unit normals
/// @param nearest #V the data point nearest to each vertex
template <int D>
std::vector<char> nested_outsides(const SimplexMesh<D>& mesh, const VertexNeighbours& neighbours,
                                  const std::vector<Index>& region, const std::vector<char>& reached,
                                  const Points<D>& points, const Points<D>& normals, const std::vector<Index>& nearest);

}  // namespace lsr::detail
