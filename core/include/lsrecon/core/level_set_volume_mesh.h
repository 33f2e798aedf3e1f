// SPDX-License-Identifier: BSD-3-Clause
/// @file level_set_volume_mesh.h
/// @brief Meshes of the inside and the outside of a level set, for simulation (paper section
/// 6.4.1, figure 6): the simplices of the box mesh that {u = 0} crosses are split along it, as
/// Mmg's level-set discretisation does, into simplices of the inside (u < 0) and the outside.
///
/// The interface is the extracted surface itself, vertex for vertex: its vertices are the
/// surface's (at their final positions, e.g. projected onto a fit) and its facets the surface's
/// facets, so the inside mesh's boundary is exactly the reconstructed surface. A cut simplex
/// becomes a corner simplex and a prism (3D: 1 + 3 tetrahedra, or 2 prisms); prism faces in mesh
/// faces are cut along the diagonal through their smallest vertex id, as on the other side of
/// the face (Dompierre et al. 1999), so the result is conforming; the interface quad follows the
/// surface's diagonal, and a prism whose three diagonals turn in a cycle gets a centre vertex.
/// Surface vertices whose final position would flatten a simplex (below 1e-9 of the mean measure)
/// stay short of it; box-mesh vertices next to slivers or tiny corners then move towards their
/// neighbours' centroid where that improves the worst simplex around them.
#pragma once

#include "lsrecon/core/level_set_extraction.h"
#include "lsrecon/core/simplex_geometry.h"

#include <array>
#include <vector>

namespace lsr {

inline constexpr int kInsideRegion = 1;   ///< u < 0
inline constexpr int kOutsideRegion = 2;  ///< u >= 0, up to the box walls

/// @brief A labelled simplicial mesh of the box.
template <int D>
struct VolumeMesh {
  /// The box mesh's vertices, then the interface's (surface vertex i is vertex
  /// interface_offset + i), then the centres of prisms split around one.
  Points<D> vertices;
  std::vector<std::array<Index, D + 1>> simplices;  ///< positively oriented
  std::vector<int> regions;                         ///< per simplex: kInsideRegion or kOutsideRegion
  std::vector<std::array<Index, D>> interface;      ///< the surface's facets, normals towards the outside
  std::vector<std::array<Index, D>> walls;          ///< the box's boundary facets, normals outwards
  Index interface_offset = 0;
  /// Interface vertices moved back towards where the cut put them, because their final position
  /// (e.g. on a fit) would have flattened a thin simplex or turned it inside out; the surface
  /// must take their positions from here to stay the inside's boundary.
  std::size_t pulled_back = 0;
};

/// @brief Splits `mesh`, a mesh of the unit box [0,1]^D, along the zero level set of `values`.
/// @param surface extract_zero_level_set(mesh, values, ...) for the same values; its vertex
/// positions may have moved since (projection onto a fit), and the volume mesh takes them,
/// except where that would invert a simplex (VolumeMesh::pulled_back).
/// @throw InvalidInput if the surface does not belong to these values.
template <int D>
VolumeMesh<D> split_along_level_set(const SimplexMesh<D>& mesh, const std::vector<double>& values,
                                    const LevelSetMesh<D>& surface);

/// @brief What a simulation user checks before using a mesh.
struct VolumeMeshQuality {
  std::size_t inverted = 0;        ///< simplices of measure <= 0
  double min_relative_measure = 0.0;  ///< smallest simplex measure over the mean (1e-9 sought)
  double min_angle_degrees = 0.0;  ///< smallest dihedral angle (3D) or angle (2D)
  double median_angle_degrees = 0.0;
  double small_angle_fraction = 0.0;  ///< of the simplices, those with an angle below 5 degrees
  double inside_measure = 0.0;     ///< volume (area in 2D) of the inside region
  double outside_measure = 0.0;
  std::size_t inside_simplices = 0, outside_simplices = 0;
};

template <int D>
VolumeMeshQuality volume_mesh_quality(const VolumeMesh<D>& mesh);

}  // namespace lsr
