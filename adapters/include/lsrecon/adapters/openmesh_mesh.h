// SPDX-License-Identifier: BSD-3-Clause
/// @file openmesh_mesh.h
/// @brief Core surfaces <-> OpenMesh triangle meshes, OpenMesh file IO (PLY, OBJ, OFF, STL)
/// written atomically, and quadric decimation.
#pragma once

// OpenMesh wants its IO header first. Its PropertyT::push_back appends a default-constructed
// VectorT, uninitialised by design (the mesh fills it next); GCC 12 reports that from every
// file that adds vertices, so the warning is silenced for OpenMesh's code only.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

#include "lsrecon/adapters/file_formats.h"
#include "lsrecon/core/level_set_extraction.h"

#include <optional>
#include <string>
#include <vector>

namespace lsr::adapters {

/// @brief Double-precision points and normals: a float mesh lost the geometry of a scan at
/// 1e6 m (georeferenced coordinates) to 0.06 m steps.
struct DoubleTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};

/// @brief The triangle mesh of the adapters; vertex normals are present when to_openmesh was
/// given some (has_vertex_normals()).
using TriMesh = OpenMesh::TriMesh_ArrayKernelT<DoubleTraits>;

/// @brief The surface with its per-vertex normals (none when normals is empty); face
/// orientation is kept.
/// @throw lsr::Error if OpenMesh refuses a face (a non-manifold surface).
TriMesh to_openmesh(const LevelSetMesh<3>& surface, const Points<3>& normals);

/// @brief Attaches `distance` (#vertices) as the vertex property kDistanceProperty: it survives
/// decimate() (the vertices kept do not move) and is written to PLY.
void set_distance_to_data(TriMesh& mesh, const std::vector<double>& distance);

/// @brief The vertex property kDistanceProperty, if the mesh has it.
std::optional<OpenMesh::VPropHandleT<double>> distance_to_data(const TriMesh& mesh);

/// @brief Vertices and triangles of an OpenMesh mesh.
LevelSetMesh<3> from_openmesh(const TriMesh& mesh);

/// @brief Reads a triangle mesh: PLY, OBJ, OFF, STL (OpenMesh, after the header checks of
/// file_header_checks.h) or VTK (PCL), i.e. every format write_mesh_file writes.
/// @throw lsr::Error for a missing, unreadable or corrupt file or another extension.
TriMesh read_mesh_file(const std::string& path);

/// @brief Writes PLY (binary, double), OBJ, OFF or STL by the file's extension, with vertex
/// normals where the format holds them (and, in PLY, the distance to the data if attached), 17 significant digits in text, atomically (an existing
/// file survives a failure). STL holds floats only.
/// @throw lsr::Error naming the path and the supported extensions.
void write_mesh_file(const TriMesh& mesh, const std::string& path);

/// @brief Quadric-error decimation to at most target_faces faces, never flipping normals;
/// returns the face count reached. Vertex normals are recomputed.
std::size_t decimate(TriMesh& mesh, std::size_t target_faces);

/// @brief Tangential and normal Laplace smoothing (OpenMesh's Jacobi smoother, C1), `iterations`
/// rounds; keeps the connectivity. Vertex normals are recomputed.
void smooth(TriMesh& mesh, unsigned iterations);

}  // namespace lsr::adapters
