// SPDX-License-Identifier: BSD-3-Clause
/// @file file_formats.h
/// @brief Which file formats lsrecon reads and writes, by extension: one table
/// (adapters/src/file_formats.cpp) for the readers, the writers, the command line and the viewer.
#pragma once

#include <string>

namespace lsr::adapters {

/// @brief The lower-case extension of a path without the dot ("" when it has none).
std::string file_extension(const std::string& path);

/// @brief What lsrecon does with a file format: one table for the readers, the writers, the
/// command line and the viewer.
enum class FileRole {
  point_input,   ///< xyz txt xy pts pcd ply obj off stl conf (registered range scans)
  image_input,   ///< pgm ppm pbm pnm png (2D: dark pixels)
  mesh_output,   ///< ply obj off stl vtk
  curve_output,  ///< svg txt
  volume_output, ///< mesh msh vtu (inside/outside meshes, volume_mesh_files.h)
};

/// @brief The name of each output vertex's distance to the data (ReconstructionResult::
/// distance_to_data): a PLY vertex property, a pcl::PolygonMesh field, an OpenMesh property.
inline constexpr const char* kDistanceProperty = "distance";

/// @brief True if files with extension `ext` (lower case, no dot) play `role`.
bool has_role(const std::string& ext, FileRole role);

/// @brief The extensions of a role for messages: ".a .b .c".
std::string extensions(FileRole role);

}  // namespace lsr::adapters
