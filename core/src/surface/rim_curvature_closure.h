// SPDX-License-Identifier: BSD-3-Clause
/// @file rim_curvature_closure.h
/// @brief Rounds the unseen parts of a surface to the curvature of the seen surface around
/// them. The front closes an unseen underside by its curvature alone: a minimal surface, flat
/// across a tube's or a sphere's underside where the object goes on curving. Each unseen part becomes a
/// surface of constant mean curvature H on the uniform Laplacian of the surface's edges,
///   x_v - mean of x_w over v's neighbours w = (m_v / 2) H n_v,
/// m_v the mean squared length of v's edges, n_v its normal: points on a sphere of radius R
/// satisfy its normal part exactly with H = 1 / R (each neighbour lies |x_v - x_w|^2 / (2 R)
/// below v's tangent plane), a cylinder of radius r with H = 1 / (2 r) on neighbourhoods spread
/// alike in every direction. H is the one that balances the part closed tangent to the seen
/// surface at its rim (the conormal's integral over the rim against the vector area), so a
/// tube's strip and a sphere's cap get their own curvature back, and a flat bottom between
/// walls that come level at the rim (a vessel's) stays flat; never below 0 (a hollow's lid is not
/// drawn in). Derivation and measurements: docs/how-it-works.md (Unsupported surface).
#pragma once

#include "lsrecon/core/level_set_extraction.h"
#include "surface/unsupported_fairing.h"

#include <cstddef>
#include <vector>

namespace lsr {

/// @brief What round_to_rim_curvature did.
struct RimClosure {
  std::size_t rounded = 0;  ///< free vertices moved to the rim's curvature
  std::size_t kept = 0;     ///< free vertices of parts left as they were (no such surface spans them)
  int iterations = 0;       ///< fixed-point iterations
};

/// @brief Moves the vertices flagged `free` so that each part they form (over the surface's
/// edges) has its rim's mean curvature, the other vertices fixed: fixed-point iterations of
/// the linear system above, normals and edge lengths from the previous iterate, one sparse
/// factorisation. Of the two such surfaces through a rim the iterations from the flattened
/// part find the nearer. A part whose vertices would move farther than its in-radius (the
/// longest path over its edges to its rim) is left as it was: no surface of that curvature
/// spans it within reach (a rim far from planar), and the iterations would inflate it. A part
/// with no rim (a whole component unseen) is left as it was too.
/// @param edges edge_graph(surface)
/// @param free #V flags
/// @param normals #V unit outward normals, used at the rim (fixed vertices) only
template <int D>
RimClosure round_to_rim_curvature(LevelSetMesh<D>& surface, const EdgeGraph& edges, const std::vector<char>& free,
                                  const Points<D>& normals);

}  // namespace lsr
