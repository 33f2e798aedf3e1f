// SPDX-License-Identifier: BSD-3-Clause
/// @file point_files.h
/// @brief Reading point clouds from files: PCD and PLY (PCL IO), .xyz / .txt (x y [z] per
/// line), OBJ / OFF / STL vertices (OpenMesh IO).
#pragma once

#include "lsrecon/adapters/file_formats.h"
#include "lsrecon/core/types.h"

#include <string>

namespace lsr::adapters {

/// @brief Points read from a file.
struct PointFile {
  Points<3> points;                ///< z = 0 for two-column text files
  std::size_t skipped = 0;         ///< NaN / infinite points left out
  bool planar_text = false;        ///< a text file with two columns: 2D data
};

/// @brief 2 when every point has the same z (closed curves in that plane), else 3: the one rule
/// of the command line and the PCL class.
int detect_dimension(const Points<3>& points);

/// @brief Reads the points of a file, choosing the reader by extension.
/// @throw lsr::Error for a missing, unreadable or corrupt file or an unknown extension; the
/// message names the file, the line where relevant, and the accepted formats.
PointFile read_point_file(const std::string& path);

}  // namespace lsr::adapters
