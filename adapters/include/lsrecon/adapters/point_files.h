// SPDX-License-Identifier: BSD-3-Clause
/// @file point_files.h
/// @brief Reading point clouds from files: PCD and PLY (PCL IO), .xyz / .txt (x y [z] per
/// line), OBJ / OFF / STL vertices (OpenMesh IO), range scans registered by a Stanford .conf;
/// writing them as lsrecon reads them back.
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
  std::size_t other_rows = 0;      ///< points (finite or not) in the file's other parts (FileShare)
};

/// @brief Part `part` of `parts` of a file's points (lsrecon-mpi: each rank reads its own): of
/// its n rows, [part n / parts, (part + 1) n / parts). A binary PLY file's part is read alone
/// (a seek to its first row); the other formats are read whole and cut.
struct FileShare {
  std::size_t part = 0, parts = 1;
};

/// @brief 2 when every point has the same z (closed curves in that plane), else 3: the one rule
/// of the command line and the PCL class.
int detect_dimension(const Points<3>& points);

/// @brief Reads the points of a file, choosing the reader by extension.
/// @throw lsr::Error for a missing, unreadable or corrupt file or an unknown extension; the
/// message names the file, the line where relevant, and the accepted formats.
PointFile read_point_file(const std::string& path, FileShare share = {});

/// @brief Points as lsrecon reads them back, written atomically: PATH.ply as binary doubles in
/// the host's byte order (exact; 10M points read in about 1 s against 10 s as text), any
/// other name as text, "x y z" per line with 17 digits (2D input: z = 0).
void write_points(const std::string& path, const Points<3>& points);

}  // namespace lsr::adapters
