// SPDX-License-Identifier: BSD-3-Clause
/// @file file_header_checks.cpp
/// Sizes are compared in double: exact for every file size below 2^53 bytes, and a count
/// product cannot overflow.
#include "lsrecon/adapters/file_header_checks.h"

#include "lsrecon/adapters/point_files.h"
#include "lsrecon/core/errors.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <vector>

namespace lsr::adapters {
namespace {

const char* const kCorruptHint = "the file is corrupt or truncated; re-export it";

[[noreturn]] void corrupt(const std::string& path, const std::string& why) {
  throw Error(path + ": " + why, kCorruptHint);
}

// A count from a header: a non-negative integer, nothing else.
double parse_count(const std::string& path, const std::string& token) {
  char* end = nullptr;
  const unsigned long long v = std::strtoull(token.c_str(), &end, 10);
  if (token.empty() || token[0] == '-' || end == token.c_str() || *end != '\0') {
    corrupt(path, "'" + token + "' in the header is not a count");
  }
  return double(v);
}

void require_fits(const std::string& path, double declared, double minimum_bytes, double available, const std::string& what) {
  if (minimum_bytes > available) {
    std::ostringstream s;
    s << path << ": the header declares " << declared << ' ' << what << ", which need at least " << minimum_bytes
      << " bytes, but the file has " << available;
    throw Error(s.str(), kCorruptHint);
  }
}

// Header lines up to and including the one starting with `last` (split in words; blank lines,
// and '#' comments if `hash_comments`, left out); `offset` is then where the data begins.
// False if the file ends (or 64 KiB pass) first.
bool read_header(std::ifstream& in, const std::string& last, bool hash_comments, std::vector<std::vector<std::string>>& lines,
                 double& offset) {
  std::string line;
  while (std::getline(in, line)) {
    if (in.tellg() > 65536) return false;
    std::istringstream s(line);
    std::vector<std::string> words;
    for (std::string w; s >> w;) words.push_back(w);
    if (!words.empty() && !(hash_comments && words[0][0] == '#')) lines.push_back(words);
    if (!words.empty() && words[0] == last) {
      offset = double(in.tellg());
      return true;
    }
  }
  return false;
}

void check_pcd(const std::string& path, std::ifstream& in, double size) {
  std::vector<std::vector<std::string>> lines;
  double offset = 0.0;
  if (!read_header(in, "DATA", true, lines, offset)) corrupt(path, "no PCD header (it ends with a DATA line)");
  static const std::set<std::string> kKeys = {"VERSION", "FIELDS", "SIZE", "TYPE", "COUNT", "WIDTH", "HEIGHT",
                                              "VIEWPOINT", "POINTS", "DATA"};
  std::map<std::string, std::vector<std::string>> key;
  for (const auto& l : lines) {
    if (!kKeys.count(l[0]) || key.count(l[0])) corrupt(path, "unknown or repeated PCD header line '" + l[0] + "'");
    key[l[0]] = std::vector<std::string>(l.begin() + 1, l.end());
  }
  const auto& sizes = key["SIZE"];
  const auto& fields = key["FIELDS"];
  std::vector<std::string> counts = key["COUNT"];
  if (counts.empty()) counts.assign(fields.size(), "1");
  if (fields.empty() || sizes.size() != fields.size() || counts.size() != fields.size() || key["DATA"].size() != 1) {
    corrupt(path, "malformed PCD header (FIELDS, SIZE, COUNT and DATA disagree)");
  }
  const auto& types = key["TYPE"];
  if (types.size() != fields.size()) corrupt(path, "malformed PCD header (FIELDS and TYPE disagree)");
  double values = 0.0, bytes = 0.0;
  for (std::size_t f = 0; f < fields.size(); ++f) {
    const double size = parse_count(path, sizes[f]), count = parse_count(path, counts[f]);
    // PCL copies SIZE bytes per value whatever TYPE says: only the sizes a type can have.
    const bool valid = types[f] == "F" ? (size == 4 || size == 8)
                                       : (types[f] == "I" || types[f] == "U") && (size == 1 || size == 2 || size == 4 || size == 8);
    const bool coordinate = fields[f] == "x" || fields[f] == "y" || fields[f] == "z";
    if (!valid || count < 1 || (coordinate && (types[f] != "F" || count != 1))) {
      corrupt(path, "the PCD field '" + fields[f] + "' has TYPE " + types[f] + ", SIZE " + sizes[f] + ", COUNT " + counts[f]);
    }
    values += count;
    bytes += size * count;
  }
  if (key["WIDTH"].size() != 1 || key["HEIGHT"].size() != 1) corrupt(path, "malformed PCD header (WIDTH, HEIGHT)");
  const double points = parse_count(path, key["WIDTH"][0]) * parse_count(path, key["HEIGHT"][0]);
  if (key["POINTS"].size() == 1 && parse_count(path, key["POINTS"][0]) != points) {
    corrupt(path, "the PCD header's POINTS differs from WIDTH x HEIGHT");
  }
  const std::string& data = key["DATA"][0];
  const double available = size - offset;
  if (data == "ascii") {
    // Every value takes a digit and a separator.
    require_fits(path, points, points * values * 2.0 - 1.0, available, "points");
  } else if (data == "binary") {
    require_fits(path, points, points * bytes, available, "points");
  } else if (data == "binary_compressed") {
    std::uint32_t header[2] = {0, 0};  // compressed and uncompressed sizes
    in.seekg(std::streamoff(offset));
    if (!in.read(reinterpret_cast<char*>(header), sizeof(header))) corrupt(path, "truncated compressed PCD data");
    require_fits(path, points, 8.0 + header[0], available, "compressed bytes");
    // LZF expands at most ~90 times (264 bytes from a 3-byte back-reference).
    if (double(header[1]) != points * bytes || double(header[1]) > 100.0 * header[0] + 64.0) {
      corrupt(path, "the compressed PCD data does not match the declared points");
    }
  } else {
    corrupt(path, "unknown PCD DATA type '" + data + "'");
  }
}

double ply_type_size(const std::string& path, const std::string& type) {
  static const std::map<std::string, double> sizes = {
      {"char", 1}, {"int8", 1}, {"uchar", 1}, {"uint8", 1}, {"short", 2}, {"int16", 2}, {"ushort", 2}, {"uint16", 2},
      {"int", 4},  {"int32", 4}, {"uint", 4}, {"uint32", 4}, {"float", 4}, {"float32", 4}, {"double", 8}, {"float64", 8}};
  const auto it = sizes.find(type);
  if (it == sizes.end()) corrupt(path, "unknown PLY property type '" + type + "'");
  return it->second;
}

void check_ply(const std::string& path, std::ifstream& in, double size) {
  std::vector<std::vector<std::string>> lines;
  double offset = 0.0;
  if (!read_header(in, "end_header", false, lines, offset) || lines.empty() || lines[0][0] != "ply") {
    corrupt(path, "no PLY header (ply ... end_header)");
  }
  bool ascii = false;
  double minimum = 0.0, count = 0.0, element_bytes = 0.0, total = 0.0;
  std::string element;
  double vertices = 0.0;
  int xyz = 0;
  const auto close_element = [&] { minimum += count * element_bytes; };
  // Every line is checked: PCL 1.13's PLY parser asserts (aborts) on some it does not expect,
  // e.g. a list property of the vertex element.
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const auto& l = lines[i];
    if (l[0] == "format") {
      if (l.size() != 3 || (l[1] != "ascii" && l[1] != "binary_little_endian" && l[1] != "binary_big_endian")) {
        corrupt(path, "malformed PLY format line");
      }
      ascii = l[1] == "ascii";
    } else if (l[0] == "element") {
      if (l.size() != 3) corrupt(path, "malformed PLY element line");
      close_element();
      element = l[1];
      count = parse_count(path, l[2]);
      if (element == "vertex") vertices += count;
      total += count;
      element_bytes = 0.0;
    } else if (l[0] == "property") {
      if (element.empty()) corrupt(path, "a PLY property before any element");
      // A value is a digit and a separator in text; a list holds at least its length.
      if (l.size() == 5 && l[1] == "list" && element != "vertex") {
        ply_type_size(path, l[3]);
        element_bytes += ascii ? 2.0 : ply_type_size(path, l[2]);
      } else if (l.size() == 3 && l[1] != "list") {
        element_bytes += ascii ? 2.0 : ply_type_size(path, l[1]);
        xyz += element == "vertex" && (l[2] == "x" || l[2] == "y" || l[2] == "z");
      } else {
        corrupt(path, "malformed PLY property line (or a list in the vertex element)");
      }
    } else if (l[0] != "comment" && l[0] != "obj_info" && l[0] != "end_header") {
      corrupt(path, "unknown PLY header line '" + l[0] + "'");
    }
  }
  close_element();
  // PCL's conversion of an empty cloud takes the address of its first point.
  if (vertices == 0.0 || xyz != 3) corrupt(path, "no vertex element with x, y and z in the PLY header");
  require_fits(path, total, minimum - (ascii ? 1.0 : 0.0), size - offset, "elements");
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

void check_declared_size(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code error;
  if (fs::is_directory(path, error)) throw Error(path + " is a directory", "pass a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error("cannot open " + path, "check the path and the file's permissions");
  const double size = double(fs::file_size(path, error));
  if (error) throw Error("cannot read the size of " + path, "check the path and the file's permissions");
  const std::string ext = file_extension(path);
  if (ext == "pcd") check_pcd(path, in, size);
  else if (ext == "ply") check_ply(path, in, size);
  else if (ext == "off") check_off(path, in, size);
  else if (ext == "stl") check_stl(path, in, size);
  else if (ext == "pgm" || ext == "ppm" || ext == "pnm" || ext == "pbm") check_pnm(path, in, size);
  else if (ext == "png") check_png(path, in, size);
}

}  // namespace lsr::adapters
