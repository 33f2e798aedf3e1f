// SPDX-License-Identifier: BSD-3-Clause
/// @file cavity_sealing.h
/// @brief Takes back from a wall flood (outside_flood_fill.h) the cavities it entered through an
/// opening narrower than the widest hole spanned: the inside of an object whose open end a
/// sampling hole took (a thin tube's tip), which tangent discs cannot cap, as they continue the
/// tube instead of closing it.
///
/// A flood that stays a gap from the data slips through any opening wider than twice the gap;
/// if it reaches the inside, the front hugs the data from both sides (a double shell, crusted
/// by the fit). A cavity is told from the outside by its core: vertices farther than `radius`
/// from the data (fat) that the flood reached but that no path of fat vertices joins to the
/// walls. The outside is the union of the data-free balls centred on the wall-connected fat
/// vertices (a ball of radius >= `radius` rolling over the data); what the flood reached beyond
/// that union falls into connected parts, and a part holding a fat vertex is a cavity. Narrow
/// outside places (the gap between close sheets, a crease, a through-hole narrower than
/// `radius`) hold no fat vertex and stay flooded.
#pragma once

#include "lsrecon/core/simplex_geometry.h"

#include <Eigen/Core>

#include <vector>

namespace lsr {

/// @brief What seal_cavities gave back.
struct SealedCavities {
  int count = 0;
  /// #V flags, empty when count is 0: the given-back vertices next to the flood, across the
  /// openings, where the start now closes them
  std::vector<char> mouth;
};

/// @brief Unmarks in `reached` the cavities described above. Linear in the mesh when there is
/// none (two passes); otherwise a priority flood of the balls' reach over the reached vertices.
/// Deterministic.
/// @param clearance #V distance from each vertex to the data (or to what spans its holes)
/// @param radius the narrowest opening that is not sealed (in the mesh's units); <= 0: none
/// @param reached #V flags of a flood from the walls (flood_from_walls)
template <int D>
SealedCavities seal_cavities(const SimplexMesh<D>& mesh, const VertexNeighbours& neighbours,
                             const Eigen::VectorXd& clearance, double radius, std::vector<char>& reached);

}  // namespace lsr
