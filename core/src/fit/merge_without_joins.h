// SPDX-License-Identifier: BSD-3-Clause
/// @file merge_without_joins.h
/// @brief Moves a P1 function's sign pattern towards another's one vertex at a time, where
/// that joins nothing: the new zero set may cut parts and handles apart or remove them, never
/// join two parts, open a handle or create a part (after the simple points of digital topology,
/// Han, Xu and Prince 2003, on a simplicial mesh).
///
/// For a P1 function on a triangulated D-manifold, {f < 0} deformation-retracts onto the
/// subcomplex spanned by the negative vertices, {f >= 0} onto that of the others. When vertex
/// v changes sign, its side loses v and the other side gains it, glued along the other side's
/// vertices in v's link (a (D-1)-sphere: the facets of v's simplices opposite v). If those form
/// one connected piece, the gaining side keeps its topology, and the losing side either keeps
/// its own (it also forms one piece in the link: v is "simple"), loses v as a whole part (none),
/// or is cut where v was (several pieces: a handle cut or a part split). If they form several
/// pieces, the flip would join them: a new handle, or two parts merged; if none, a new part.
#pragma once

#include "lsrecon/core/simplex_geometry.h"

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace lsr {

/// @brief Turns the narrow parts of {values < 0} and {values >= 0} to the other sign by
/// negating their values: bubbles and specks below the sampling gap, which no data can
/// support (and which the extraction would turn into tiny closed surfaces). `values` must be a signed distance
/// near its zero set; a part is narrow if all its vertices lie nearer to the zero set than
/// their `width` and its bounding box's diagonal is shorter than the largest width in it.
/// Only the vertices nearer than their width are visited.
/// @param neighbours the mesh's edge graph
/// @param width #V lengths
/// @param values #V values, changed in place
/// @return the number of vertices that changed sign
/// @note A part that touches the box walls is never narrow: it is the outside.
template <int D>
std::size_t absorb_small_parts(const SimplexMesh<D>& mesh, const VertexNeighbours& neighbours,
                               const Eigen::VectorXd& width, std::vector<double>& values);

/// @brief Turns to the negative side the parts of {values >= 0} that reach no box wall but
/// whose vertices reached one in {reference >= 0}: voids that a merge (which may cut parts)
/// cut off the outside, where the reference had none. A closed void is a surface no sample
/// lies on unless the reference found it; parts already enclosed in the reference stay.
/// @param reference #V values (walls non-negative)
/// @param values #V values (walls non-negative), changed in place
/// @return the number of vertices that changed sign
template <int D>
std::size_t fill_cut_off_voids(const SimplexMesh<D>& mesh, const Eigen::VectorXd& reference,
                               std::vector<double>& values);

/// @brief How many connected pieces the negative and the non-negative vertices of v's link form.
struct LinkPieces {
  int negative = 0;
  int non_negative = 0;
  /// Changing v's sign keeps the topology of both {f < 0} and {f >= 0}.
  bool simple() const { return negative == 1 && non_negative == 1; }
};

/// @brief The pieces of the link of vertex v, through the link's edges.
/// @param star the simplices that contain v
/// @param negative #V flags: f < 0
template <int D>
LinkPieces link_pieces(const SimplexMesh<D>& mesh, const std::vector<Index>& star, Index v,
                       const std::vector<char>& negative);

/// @brief Gives each vertex the sign of `values` where that joins nothing in {reference < 0}
/// or {reference >= 0}: vertices whose sign differs flip one at a time, most confident (largest
/// |values|) first, each when the vertices of the other sign in its link form one piece; a flip
/// makes its neighbours worth another look. Vertices that never may flip take the reference's
/// value. Deterministic.
/// @param reference #V values whose parts and handles may be cut or removed, not joined or added
/// @param values #V wanted values; on return every vertex has the sign the merge gave it
/// @param may_join #V flags, or empty: vertices where a join is allowed too (still never a new part)
/// @return the number of vertices that kept the reference's sign against `values`
/// @note Vertices on the box walls never flip: their links are not spheres.
template <int D>
std::size_t merge_without_joins(const SimplexMesh<D>& mesh, const Eigen::VectorXd& reference,
                                std::vector<double>& values, const std::vector<char>& may_join = {});

}  // namespace lsr
