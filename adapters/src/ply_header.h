// SPDX-License-Identifier: BSD-3-Clause
/// @file ply_header.h
/// @brief The one PLY header parser (internal): used by the point reader and by the size check
/// before OpenMesh reads a PLY mesh.
#pragma once

#include "binary_scalars.h"

#include <istream>
#include <string>
#include <vector>

namespace lsr::adapters::detail {

struct PlyProperty {
  std::string name;
  ScalarType type;        ///< the value's (a list's items')
  ScalarType list_count;  ///< a list's length type; bytes == 0 for a scalar property
  bool is_list() const { return list_count.bytes > 0; }
};

struct PlyElement {
  std::string name;
  double count = 0;
  std::vector<PlyProperty> properties;
  /// @brief Bytes of one row at least: a value is a character and a separator in text, a list
  /// holds at least its length.
  double minimum_row_bytes(bool ascii) const;
};

struct PlyHeader {
  enum class Format { ascii, binary_little_endian, binary_big_endian };
  Format format = Format::ascii;
  std::vector<PlyElement> elements;
  std::streamoff body = 0;  ///< where the first element's data begins
  /// @brief The bytes the declared elements take at least (throws nothing; may exceed the file).
  double minimum_body_bytes() const;
};

/// @brief Parses the header at the start of `in` (from "ply" to "end_header").
/// @throw lsr::Error naming `path` if it is malformed or has unknown types or lines.
PlyHeader parse_ply_header(const std::string& path, std::istream& in);

}  // namespace lsr::adapters::detail
