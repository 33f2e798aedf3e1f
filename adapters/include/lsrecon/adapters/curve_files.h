// SPDX-License-Identifier: BSD-3-Clause
/// @file curve_files.h
/// @brief 2D curves: SVG (closed paths, y up) and a plain polyline text format ("# loop k"
/// then "x y" per vertex), written atomically; the text format read back (a start curve).
#pragma once

#include "lsrecon/core/types.h"

#include <string>
#include <vector>

namespace lsr::adapters {

/// @brief Closed curves: the vertices of each loop in order (the last joins the first).
struct Curves {
  Points<2> vertices;
  std::vector<std::vector<Index>> loops;
};

/// @brief Reads the text format write_polylines writes (a "# loop" line starts each loop).
/// @throw lsr::Error naming the file and line for what is not a number or a loop of fewer than
/// 3 vertices.
Curves read_polylines(const std::string& path);

/// @brief "# loop k" then "x y" per vertex, written atomically.
void write_polylines(const std::string& path, const Points<2>& vertices, const std::vector<std::vector<Index>>& loops);

/// @brief The curves over the data points as an SVG picture (y up).
/// @param start if given, drawn dashed in grey (where the front started)
void write_svg(const std::string& path, const Points<2>& vertices, const std::vector<std::vector<Index>>& loops,
               const Points<2>& data, const Curves* start = nullptr);

}  // namespace lsr::adapters
