// SPDX-License-Identifier: BSD-3-Clause
/// @file mesh_file_vertices.cpp
#include "lsrecon/adapters/mesh_file_vertices.h"

#include "lsrecon/adapters/point_files.h"
#include "lsrecon/core/errors.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <vector>

namespace lsr::adapters {
namespace {

const char* const kHint = "the file is corrupt or truncated; re-export it";

std::vector<std::string> words(const std::string& line) {
  std::istringstream s(line);
  std::vector<std::string> w;
  for (std::string t; s >> t;) w.push_back(t);
  return w;
}

// x y z from w[first], w[first + 1], w[first + 2].
Vec<3> position(const std::vector<std::string>& w, std::size_t first, const std::string& where) {
  if (w.size() < first + 3) throw Error(where + ": expected x y z", kHint);
  Vec<3> p;
  for (int k = 0; k < 3; ++k) {
    const std::string& t = w[first + std::size_t(k)];
    char* end = nullptr;
    p[k] = std::strtod(t.c_str(), &end);
    if (t.empty() || end != t.c_str() + t.size()) throw Error(where + ": '" + printable(t) + "' is not a number", kHint);
  }
  return p;
}

Points<3> read_obj(std::ifstream& in, const std::string& path) {
  Points<3> points;
  std::string line;
  for (long number = 1; std::getline(in, line); ++number) {
    const std::vector<std::string> w = words(line);
    if (!w.empty() && w[0] == "v") points.push_back(position(w, 1, path + ":" + std::to_string(number)));
  }
  return points;
}

Points<3> read_off(std::ifstream& in, const std::string& path) {
  std::string line;
  long number = 0;
  // Significant lines only: no blank lines, no comments.
  auto next = [&]() {
    while (std::getline(in, line)) {
      ++number;
      const std::size_t hash = line.find('#');
      if (hash != std::string::npos) line.resize(hash);
      std::vector<std::string> w = words(line);
      if (!w.empty()) return w;
    }
    throw Error(path + ": truncated after line " + std::to_string(number), kHint);
  };
  std::vector<std::string> w = next();
  const std::string& magic = w[0];
  if (magic.size() < 3 || magic.compare(magic.size() - 3, 3, "OFF") != 0) throw Error(path + ": no OFF header", kHint);
  if (std::find(w.begin(), w.end(), "BINARY") != w.end()) {
    throw Error(path + ": binary OFF is not supported", "convert it to PLY, OBJ or text OFF");
  }
  if (w.size() == 1) w = next();
  else w.erase(w.begin());
  char* end = nullptr;
  const long long count = std::strtoll(w[0].c_str(), &end, 10);
  if (end == w[0].c_str() || *end != '\0' || count < 0) throw Error(path + ": the OFF header has no vertex count", kHint);
  Points<3> points;
  points.reserve(std::size_t(std::min<long long>(count, 1 << 20)));
  for (long long v = 0; v < count; ++v) points.push_back(position(next(), 0, path + ":" + std::to_string(number)));
  return points;
}

Points<3> weld(const Points<3>& corners) {
  Points<3> points;
  std::set<std::array<double, 3>> seen;
  for (const auto& p : corners) {
    if (seen.insert({p.x(), p.y(), p.z()}).second) points.push_back(p);
  }
  return points;
}

Points<3> read_stl(std::ifstream& in, const std::string& path) {
  std::error_code e;
  const double size = double(std::filesystem::file_size(path, e));
  char header[80];
  std::uint32_t triangles = 0;
  const bool has_header = bool(in.read(header, 80)) && bool(in.read(reinterpret_cast<char*>(&triangles), 4));
  // Binary when the size matches the count, whatever the header says ("solid" included).
  if (has_header && size == 84.0 + 50.0 * triangles) {
    Points<3> corners;
    corners.reserve(std::size_t(triangles) * 3);
    char record[50];
    for (std::uint32_t t = 0; t < triangles && in.read(record, 50); ++t) {
      for (int c = 0; c < 3; ++c) {
        float xyz[3];
        std::copy_n(record + 12 + 12 * c, 12, reinterpret_cast<char*>(xyz));
        corners.emplace_back(xyz[0], xyz[1], xyz[2]);
      }
    }
    return weld(corners);
  }
  in.clear();
  in.seekg(0);
  char magic[5] = {};
  if (!in.read(magic, 5) || std::string(magic, 5) != "solid") {
    throw Error(path + ": neither a binary STL (84 + 50 bytes per triangle) nor a text one (solid ...)", kHint);
  }
  in.clear();
  in.seekg(0);
  Points<3> corners;
  std::string line;
  bool in_facet = false;
  for (long number = 1; std::getline(in, line); ++number) {
    const std::vector<std::string> w = words(line);
    if (w.empty()) continue;
    if (w[0] == "vertex") corners.push_back(position(w, 1, path + ":" + std::to_string(number)));
    if (w[0] == "facet") in_facet = true;
    if (w[0] == "endfacet") in_facet = false;
  }
  // A file cut mid-facet is a failed transfer, not a smaller mesh.
  if (in_facet || corners.size() % 3 != 0) {
    throw Error(path + ": the text STL ends inside a facet (" + std::to_string(corners.size()) + " vertices)", kHint);
  }
  return weld(corners);
}

}  // namespace

Points<3> read_mesh_file_vertices(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error("cannot open " + path, "check the path and the file's permissions");
  const std::string ext = file_extension(path);
  if (ext == "obj") return read_obj(in, path);
  if (ext == "off") return read_off(in, path);
  if (ext == "stl") return read_stl(in, path);
  throw Error("not a mesh file: " + path, "use .obj, .off or .stl");
}

}  // namespace lsr::adapters
