// SPDX-License-Identifier: BSD-3-Clause
/// @file unsupported_parts.h
/// @brief Removes the closed parts of a level set that no sample is nearest to. Every part of a
/// reconstruction must explain some data; a solid or a void whose boundary is the nearest
/// surface to fewer than D + 1 samples (which span no volume) is a guess of the solver, not
/// something the data showed.
#pragma once

#include "lsrecon/core/level_set_extraction.h"
#include "lsrecon/core/simplex_geometry.h"

#include <cstddef>
#include <vector>

namespace lsr {

/// @brief Turns to the other sign each part of {values < 0}, and of {values >= 0} that reaches
/// no box wall, whose boundary in `surface` is nearest to fewer than D + 1 of `points`. A
/// sample counts for both parts on either side of the surface vertex nearest to it. Costs
/// nothing beyond a component labelling when there is one part only (the common case); then
/// a kd-tree over the surface's vertices.
/// @param surface the zero set of `values` on `mesh` (extract_zero_level_set)
/// @param points the data, in the mesh's coordinates
/// @param values #V values (box walls non-negative), changed in place
/// @param threads 0 for all cores
/// @return the number of vertices that changed sign: if not zero, extract `values` again
template <int D>
std::size_t drop_unsupported_parts(const SimplexMesh<D>& mesh, const LevelSetMesh<D>& surface,
                                   const Points<D>& points, std::vector<double>& values, int threads = 0);

/// @brief The same on a surface without its mesh (tiles welded, tiles/tiled_solve.h): drops
/// each connected piece of `surface` (through shared vertices) nearest to fewer than D + 1 of
/// `points`, a solid's or a void's whole boundary when it is one piece. The vertices keep their
/// order; `sources` must be empty.
/// @return the number of pieces dropped
template <int D>
std::size_t drop_unsupported_pieces(LevelSetMesh<D>& surface, const Points<D>& points, int threads = 0);

}  // namespace lsr
