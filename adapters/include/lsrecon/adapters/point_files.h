// SPDX-License-Identifier: BSD-3-Clause
/// @file point_files.h
/// @brief Reading point clouds from files: PCD and PLY (PCL IO), .xyz / .txt (x y [z] per
/// line), OBJ / OFF / STL vertices (OpenMesh IO).
#pragma once

#include "lsrecon/core/types.h"

#include <string>

namespace lsr::adapters {

/// @brief Points read from a file.
struct PointFile {
  Points<3> points;                ///< z = 0 for two-column text files
  std::size_t skipped = 0;         ///< NaN / infinite points left out
  bool planar_text = false;        ///< a text file with two columns: 2D data
};

/// @brief The lower-case extension of a path without the dot ("" when it has none).
std::string file_extension(const std::string& path);

/// @brief 2 when every point has the same z (closed curves in that plane), else 3: the one rule
/// of the command line and the PCL class.
int detect_dimension(const Points<3>& points);

/// @brief What lsrecon does with a file format: one table for the readers, the writers, the
/// command line and the viewer.
enum class FileRole {
  point_input,   ///< xyz txt xy pts pcd ply obj off stl
  image_input,   ///< pgm ppm pbm pnm png (2D: dark pixels)
  mesh_output,   ///< ply obj off stl vtk
  curve_output,  ///< svg txt
  volume_output, ///< mesh msh vtu (inside/outside meshes, volume_mesh_files.h)
};

/// @brief True if files with extension `ext` (lower case, no dot) play `role`.
bool has_role(const std::string& ext, FileRole role);

/// @brief The extensions of a role for messages: ".a .b .c".
std::string extensions(FileRole role);

/// @brief Reads the points of a file, choosing the reader by extension.
/// @throw lsr::Error for a missing, unreadable or corrupt file or an unknown extension; the
/// message names the file, the line where relevant, and the accepted formats.
PointFile read_point_file(const std::string& path);

}  // namespace lsr::adapters
