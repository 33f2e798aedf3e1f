// SPDX-License-Identifier: BSD-3-Clause
/// @file point_file_readers.h
/// @brief lsrecon's own readers of PCD and PLY points (internal): every header and body is
/// parsed here, checked against the file's size before anything is allocated, with coordinates
/// of any numeric type. PCL 1.13's readers go on parsing header keywords after DATA, trust SIZE
/// over TYPE and read double coordinates as zeros, so untrusted files never reach them.
#pragma once

#include "lsrecon/adapters/point_files.h"

#include <string>

namespace lsr::adapters::detail {

/// @brief The x, y, z of a PCD file (DATA ascii, binary or binary_compressed; fields of TYPE F,
/// I or U and any SIZE that type has).
/// @throw lsr::Error if the file is malformed, truncated, or declares more than it holds.
PointFile read_pcd_points(const std::string& path);

/// @brief The x, y, z of the vertex element of a PLY file (ascii, binary_little_endian or
/// binary_big_endian; any property type; elements before the vertices are skipped).
/// @throw lsr::Error as read_pcd_points.
PointFile read_ply_points(const std::string& path, FileShare share = {});

/// @brief The points of the range scans a Stanford .conf file lists, each mapped by its
/// registration (registered_scans.cpp).
/// @throw lsr::Error for a malformed line, a scan that cannot be read, or no scan at all.
PointFile read_registered_scans(const std::string& path);

}  // namespace lsr::adapters::detail
