// SPDX-License-Identifier: BSD-3-Clause
/// @file file_header_checks.cpp
/// Sizes are compared in double: exact for every file size below 2^53 bytes, and a count
/// product cannot overflow.
#include "lsrecon/adapters/file_header_checks.h"

#include "header_lines.h"
#include "ply_header.h"

#include "lsrecon/adapters/point_files.h"
#include "lsrecon/core/errors.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <algorithm>
#include <sstream>
#include <vector>

namespace lsr::adapters {
namespace {

const char* const kCorruptHint = "the file is corrupt or truncated; re-export it";

[[noreturn]] void corrupt(const std::string& path, const std::string& why) {
  throw Error(path + ": " + why, kCorruptHint);
}

double parse_count(const std::string& path, const std::string& token) { return detail::parse_header_count(path, token); }

void require_fits(const std::string& path, double declared, double minimum_bytes, double available, const std::string& what) {
  detail::require_declared_fits(path, declared, minimum_bytes, available, what);
}

// PCL's and OpenMesh's PLY parsers: a vertex element with x, y and z and no list (PCL 1.13
// asserts on one), and elements that fit in the file.
void check_ply(const std::string& path, std::ifstream& in, double size) {
  const detail::PlyHeader h = detail::parse_ply_header(path, in);
  const auto vertex = std::find_if(h.elements.begin(), h.elements.end(), [](const detail::PlyElement& e) { return e.name == "vertex"; });
  int xyz = 0;
  if (vertex != h.elements.end()) {
    for (const auto& p : vertex->properties) {
      if (p.is_list()) corrupt(path, "a list property in the PLY vertex element");
      xyz += p.name == "x" || p.name == "y" || p.name == "z";
    }
  }
  // PCL's conversion of an empty cloud takes the address of its first point.
  if (vertex == h.elements.end() || vertex->count == 0 || xyz != 3) corrupt(path, "no vertex element with x, y and z in the PLY header");
  double total = 0.0;
  for (const auto& e : h.elements) total += e.count;
  require_fits(path, total, h.minimum_body_bytes(), size - double(h.body), "elements");
}

void check_off(const std::string& path, std::ifstream& in, double size) {
  std::string magic;
  in >> magic;
  if (magic.size() < 3 || magic.compare(magic.size() - 3, 3, "OFF") != 0) corrupt(path, "no OFF header");
  std::string rest;
  std::getline(in, rest);
  if (rest.find("BINARY") != std::string::npos) return;  // OpenMesh reads counts as it streams
  std::vector<std::string> counts;
  std::istringstream first(rest);
  for (std::string w; first >> w && w[0] != '#';) counts.push_back(w);
  for (std::string line; counts.size() < 3 && std::getline(in, line);) {
    std::istringstream s(line);
    for (std::string w; s >> w && w[0] != '#';) counts.push_back(w);
  }
  if (counts.size() < 3) corrupt(path, "the OFF header has no vertex and face counts");
  const double vertices = parse_count(path, counts[0]), faces = parse_count(path, counts[1]);
  // "x y z" and "3 a b c", a digit and a separator each.
  require_fits(path, vertices + faces, vertices * 6.0 + faces * 8.0 - 1.0, size - double(in.tellg()), "vertices and faces");
}

void check_stl(const std::string& path, std::ifstream& in, double size) {
  char header[80];
  std::uint32_t triangles = 0;
  if (!in.read(header, 80)) corrupt(path, "shorter than an STL header");
  if (std::string(header, 5) == "solid") return;  // text STL: no count
  if (!in.read(reinterpret_cast<char*>(&triangles), 4)) corrupt(path, "truncated STL header");
  require_fits(path, triangles, 50.0 * triangles, size - 84.0, "triangles");
}

// Netpbm: magic, width, height (and maxval), '#' comments between tokens.
void check_pnm(const std::string& path, std::ifstream& in, double size) {
  std::vector<std::string> tokens;
  const auto next = [&]() {
    std::string t;
    while (in >> t) {
      if (t[0] != '#') return t;
      std::string comment;
      std::getline(in, comment);
    }
    corrupt(path, "truncated image header");
  };
  const std::string magic = next();
  if (magic.size() != 2 || magic[0] != 'P' || magic[1] < '1' || magic[1] > '6') corrupt(path, "not a PBM / PGM / PPM image");
  const double width = parse_count(path, next()), height = parse_count(path, next());
  const bool bitmap = magic[1] == '1' || magic[1] == '4';
  const double maxval = bitmap ? 1.0 : parse_count(path, next());
  in.get();  // the single whitespace before binary data
  if (width == 0.0 || height == 0.0) corrupt(path, "the image is empty (0 pixels)");
  const double channels = (magic[1] == '3' || magic[1] == '6') ? 3.0 : 1.0;
  const double samples = width * height * channels;
  const double available = size - double(in.tellg());
  if (magic[1] <= '3') {
    require_fits(path, width * height, bitmap ? samples : 2.0 * samples - 1.0, available, "pixels");
  } else {
    const double bytes = bitmap ? std::ceil(width / 8.0) * height : samples * (maxval > 255.0 ? 2.0 : 1.0);
    require_fits(path, width * height, bytes, available, "pixels");
  }
}

void check_png(const std::string& path, std::ifstream& in, double size) {
  unsigned char h[24];
  if (!in.read(reinterpret_cast<char*>(h), 24) || h[1] != 'P' || h[2] != 'N' || h[3] != 'G') corrupt(path, "not a PNG image");
  const auto be32 = [&](int at) { return double((std::uint32_t(h[at]) << 24) | (h[at + 1] << 16) | (h[at + 2] << 8) | h[at + 3]); };
  const double width = be32(16), height = be32(20);
  if (width == 0.0 || height == 0.0) corrupt(path, "the image is empty (0 pixels)");
  // Deflate expands at most ~1032 times; a pixel takes at least one bit.
  require_fits(path, width * height, width * height / (8.0 * 1032.0), size, "pixels");
  if (width * height > double(1u << 28)) {
    throw Error(path + ": " + std::to_string(std::uint64_t(width)) + " x " + std::to_string(std::uint64_t(height)) +
                    " pixels is more than this reader accepts (2^28)",
                "downsample the image");
  }
}

}  // namespace

void require_regular_file(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (fs::is_directory(status)) throw Error(path + " is a directory", "pass a file");
  // Opening a FIFO without a writer would block forever; a device may never end.
  if (fs::exists(status) && !fs::is_regular_file(status)) {
    throw Error(path + " is not a regular file (a FIFO, socket or device)", "save the points to a file and pass that");
  }
}

void check_declared_size(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code error;
  require_regular_file(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error("cannot open " + path, "check the path and the file's permissions");
  const double size = double(fs::file_size(path, error));
  if (error) throw Error("cannot read the size of " + path, "check the path and the file's permissions");
  const std::string ext = file_extension(path);
  if (ext == "ply") check_ply(path, in, size);
  else if (ext == "off") check_off(path, in, size);
  else if (ext == "stl") check_stl(path, in, size);
  else if (ext == "pgm" || ext == "ppm" || ext == "pnm" || ext == "pbm") check_pnm(path, in, size);
  else if (ext == "png") check_png(path, in, size);
}

}  // namespace lsr::adapters
