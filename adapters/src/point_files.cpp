// SPDX-License-Identifier: BSD-3-Clause
/// @file point_files.cpp
#include "lsrecon/adapters/point_files.h"

#include "binary_scalars.h"
#include "point_file_readers.h"

#include "lsrecon/adapters/file_header_checks.h"
#include "lsrecon/adapters/mesh_file_vertices.h"
#include "lsrecon/core/errors.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>
#include <vector>

namespace lsr::adapters {

namespace {

// Whitespace-separated fields; a line that is one comma- or semicolon-separated field is CSV.
std::vector<std::string> split_fields(const std::string& line) {
  std::vector<std::string> fields;
  std::istringstream s(line);
  for (std::string t; s >> t;) fields.push_back(t);
  if (fields.size() == 1 && fields[0].find_first_of(",;") != std::string::npos) {
    std::string csv = fields[0];
    std::replace_if(csv.begin(), csv.end(), [](char c) { return c == ',' || c == ';'; }, ' ');
    return split_fields(csv);
  }
  return fields;
}

PointFile read_text(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error("cannot open " + path, "check the path and the file's permissions");
  PointFile out;
  const char* const format = "a point file has 'x y' or 'x y z' (or x,y,z) per line, '.' as the decimal point (# starts a comment)";
  std::string line;
  int columns = 0;
  bool first = true;
  for (long number = 1; std::getline(in, line); ++number) {
    const std::size_t start = line.find_first_not_of(" \t\r");
    if (start == std::string::npos || line[start] == '#') continue;
    const std::vector<std::string> fields = split_fields(line);
    double v[3] = {0, 0, 0};
    int n = 0;
    // A first line of names is a column header ("x,y,z").
    const bool header = first && std::all_of(fields.begin(), fields.end(), [](const std::string& t) { return std::isalpha(static_cast<unsigned char>(t[0])) != 0; });
    first = false;
    if (header) continue;
    for (; n < 3 && n < int(fields.size()); ++n) {
      if (!detail::parse_number(fields[n], v[n])) {
        throw Error(path + ":" + std::to_string(number) + ": '" + printable(fields[n]) + "' is not a number", format);
      }
    }
    if (n < 2) throw Error(path + ":" + std::to_string(number) + ": expected 2 or 3 numbers", format);
    if (columns == 0) columns = n;
    // 2D and 3D lines mixed: a z column lost on some lines is data lost, not a plane.
    if (n != columns) {
      throw Error(path + ":" + std::to_string(number) + ": " + std::to_string(n) + " coordinates where the first point has " +
                      std::to_string(columns), format);
    }
    const Vec<3> p(v[0], v[1], v[2]);
    if (p.allFinite()) {
      out.points.push_back(p);
    } else {
      ++out.skipped;
    }
  }
  // Said here, not as "no finite points" below: the file is what to change.
  if (out.points.empty() && out.skipped == 0) {
    throw Error(path + " holds no points: it is empty or only comments and a header line", format);
  }
  out.planar_text = columns == 2;
  return out;
}

}  // namespace

int detect_dimension(const Points<3>& points) {
  const bool planar = std::all_of(points.begin(), points.end(), [&](const Vec<3>& p) { return p.z() == points[0].z(); });
  return planar && !points.empty() ? 2 : 3;
}

PointFile read_point_file(const std::string& path, FileShare share) {
  if (share.parts > 1 && file_extension(path) != "ply") {
    // Read whole and cut: the non-finite points count in the first part.
    PointFile all = read_point_file(path);
    const std::size_t n = all.points.size(), first = share.part * n / share.parts, end = (share.part + 1) * n / share.parts;
    PointFile out;
    out.points.assign(all.points.begin() + long(first), all.points.begin() + long(end));
    out.skipped = share.part == 0 ? all.skipped : 0;
    out.other_rows = n + all.skipped - out.points.size() - out.skipped;
    out.planar_text = all.planar_text;
    return out;
  }
  require_regular_file(path);
  const std::string ext = file_extension(path);
  if (!has_role(ext, FileRole::point_input)) {
    throw Error("unknown input format '" + printable(ext) + "' (" + path + ")",
                "use " + extensions(FileRole::point_input) + " (or an image for 2D: " + extensions(FileRole::image_input) + ")");
  }
  if (ext == "pcd") return detail::read_pcd_points(path);
  if (ext == "ply") return detail::read_ply_points(path, share);
  if (ext == "conf") return detail::read_registered_scans(path);
  check_declared_size(path);
  if (ext == "obj" || ext == "off" || ext == "stl") {
    PointFile out;
    out.points = read_mesh_file_vertices(path);
    return out;
  }
  return read_text(path);
}

}  // namespace lsr::adapters
