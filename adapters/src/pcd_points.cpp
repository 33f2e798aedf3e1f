// SPDX-License-Identifier: BSD-3-Clause
/// @file pcd_points.cpp
/// @brief PCD v0.7 (and the v0.5 subset without COUNT): the header ends at DATA, whatever
/// follows is the body. binary_compressed bodies are LZF (PCL's bounds-checked
/// pcl::lzfDecompress) holding each field's values for all points in turn.
#include "binary_scalars.h"
#include "header_lines.h"
#include "point_file_readers.h"

#include "lsrecon/core/errors.h"

#include <pcl/io/lzf.h>

#include <array>
#include <cstdint>
#include <fstream>
#include <map>
#include <vector>

namespace lsr::adapters::detail {
namespace {

const char* const kCorruptHint = "the file is corrupt or truncated; re-export it";

[[noreturn]] void corrupt(const std::string& path, const std::string& why) { throw Error(path + ": " + why, kCorruptHint); }

struct Field {
  std::string name;
  ScalarType type;
  double count = 1;
  std::size_t offset = 0;  ///< bytes from the start of a point (binary) or of the field's block (compressed)
};

struct PcdHeader {
  std::vector<Field> fields;
  double points = 0;
  double values = 0;      ///< per point, all fields and counts
  std::size_t bytes = 0;  ///< per point
  std::string data;
  std::streamoff body = 0;
};

PcdHeader parse_header(const std::string& path, std::ifstream& in) {
  std::vector<std::vector<std::string>> lines;
  PcdHeader h;
  if (!read_header_lines(in, "DATA", true, lines, h.body)) corrupt(path, "no PCD header (it ends with a DATA line)");
  static const char* const kKeys[] = {"VERSION", "FIELDS", "SIZE", "TYPE", "COUNT", "WIDTH", "HEIGHT", "VIEWPOINT", "POINTS", "DATA"};
  std::map<std::string, std::vector<std::string>> key;
  for (const auto& l : lines) {
    if (std::find(std::begin(kKeys), std::end(kKeys), l[0]) == std::end(kKeys) || key.count(l[0])) {
      corrupt(path, "unknown or repeated PCD header line '" + printable(l[0]) + "'");
    }
    key[l[0]] = std::vector<std::string>(l.begin() + 1, l.end());
  }
  const auto& names = key["FIELDS"];
  const auto& sizes = key["SIZE"];
  const auto& types = key["TYPE"];
  std::vector<std::string> counts = key["COUNT"];
  if (counts.empty()) counts.assign(names.size(), "1");
  if (names.empty() || sizes.size() != names.size() || types.size() != names.size() || counts.size() != names.size() ||
      key["DATA"].size() != 1) {
    corrupt(path, "malformed PCD header (FIELDS, SIZE, TYPE, COUNT and DATA disagree)");
  }
  for (std::size_t f = 0; f < names.size(); ++f) {
    Field field;
    field.name = names[f];
    field.type.bytes = int(std::min(parse_header_count(path, sizes[f]), 9.0));
    field.type.kind = types[f] == "F" ? ScalarType::floating : types[f] == "I" ? ScalarType::signed_integer : ScalarType::unsigned_integer;
    field.count = parse_header_count(path, counts[f]);
    const bool known = types[f] == "F" ? (field.type.bytes == 4 || field.type.bytes == 8) : (types[f] == "I" || types[f] == "U") && field.type.valid();
    const bool coordinate = field.name == "x" || field.name == "y" || field.name == "z";
    if (!known || field.count < 1 || field.count > 1e6 || (coordinate && field.count != 1)) {
      corrupt(path, "the PCD field '" + printable(names[f]) + "' has TYPE " + printable(types[f]) + ", SIZE " +
                        printable(sizes[f]) + ", COUNT " + printable(counts[f]));
    }
    field.offset = h.bytes;
    h.bytes += std::size_t(field.type.bytes) * std::size_t(field.count);
    h.values += field.count;
    h.fields.push_back(field);
  }
  if (key["WIDTH"].size() > 1 || key["HEIGHT"].size() > 1 || key["POINTS"].size() > 1 ||
      (key["WIDTH"].empty() && key["POINTS"].empty())) {
    corrupt(path, "malformed PCD header (WIDTH, HEIGHT, POINTS)");
  }
  const double height = key["HEIGHT"].empty() ? 1.0 : parse_header_count(path, key["HEIGHT"][0]);
  h.points = key["WIDTH"].empty() ? parse_header_count(path, key["POINTS"][0]) : parse_header_count(path, key["WIDTH"][0]) * height;
  if (!key["POINTS"].empty() && parse_header_count(path, key["POINTS"][0]) != h.points) {
    corrupt(path, "the PCD header's POINTS differs from WIDTH x HEIGHT");
  }
  h.data = key["DATA"][0];
  return h;
}

// Where x, y and z are among the fields.
std::array<const Field*, 3> coordinate_fields(const std::string& path, const PcdHeader& h) {
  std::array<const Field*, 3> xyz = {nullptr, nullptr, nullptr};
  for (const Field& f : h.fields) {
    for (int k = 0; k < 3; ++k) {
      if (f.name == std::string(1, char('x' + k))) {
        if (xyz[std::size_t(k)]) corrupt(path, "the PCD field '" + printable(f.name) + "' appears twice");
        xyz[std::size_t(k)] = &f;
      }
    }
  }
  if (!xyz[0] || !xyz[1] || !xyz[2]) corrupt(path, "no x, y and z fields in the PCD header");
  return xyz;
}

void require_fits(const std::string& path, const PcdHeader& h, double needed, double available, const char* what) {
  require_declared_fits(path, h.points, needed, available, what);
}

void add_point(PointFile& out, double x, double y, double z) {
  const Vec<3> p(x, y, z);
  if (p.allFinite()) {
    out.points.push_back(p);
  } else {
    ++out.skipped;
  }
}

PointFile read_ascii(const std::string& path, std::ifstream& in, const PcdHeader& h, double available) {
  // Every value takes a character and a separator.
  require_fits(path, h, h.points * h.values * 2.0 - 1.0, available, "points");
  const auto xyz = coordinate_fields(path, h);
  std::array<std::size_t, 3> column{};  // the value index of x, y, z within a point
  std::size_t v = 0;
  for (const Field& f : h.fields) {
    for (int k = 0; k < 3; ++k) {
      if (&f == xyz[std::size_t(k)]) column[std::size_t(k)] = v;
    }
    v += std::size_t(f.count);
  }
  PointFile out;
  out.points.reserve(std::size_t(h.points));
  std::vector<double> values(std::size_t(h.values));
  std::string token;
  for (double i = 0; i < h.points; ++i) {
    for (double& value : values) {
      if (!(in >> token)) corrupt(path, "the PCD data ends after " + std::to_string(std::uint64_t(i)) + " of its points");
      if (!parse_number(token, value)) corrupt(path, "'" + printable(token) + "' in the PCD data is not a number");
    }
    add_point(out, as_declared(values[column[0]], xyz[0]->type), as_declared(values[column[1]], xyz[1]->type),
              as_declared(values[column[2]], xyz[2]->type));
  }
  if (in >> token) corrupt(path, "the PCD data holds more values than its header declares");
  return out;
}

PointFile read_binary(const std::string& path, std::ifstream& in, const PcdHeader& h, double available) {
  const auto xyz = coordinate_fields(path, h);
  std::vector<unsigned char> body;
  std::size_t stride = h.bytes;  // between a field's consecutive values
  std::array<std::size_t, 3> start{}, step{};
  if (h.data == "binary") {
    require_fits(path, h, h.points * double(h.bytes), available, "points");
    body.resize(std::size_t(h.points) * h.bytes);
    if (!in.read(reinterpret_cast<char*>(body.data()), std::streamsize(body.size()))) corrupt(path, "truncated PCD data");
    for (int k = 0; k < 3; ++k) start[std::size_t(k)] = xyz[std::size_t(k)]->offset;
    step.fill(stride);
  } else {
    std::uint32_t sizes[2] = {0, 0};  // compressed, uncompressed
    if (!in.read(reinterpret_cast<char*>(sizes), sizeof(sizes))) corrupt(path, "truncated compressed PCD data");
    require_declared_fits(path, double(sizes[0]), 8.0 + double(sizes[0]), available, "compressed bytes");
    // LZF expands at most ~90 times (264 bytes from a 3-byte back-reference).
    if (double(sizes[1]) != h.points * double(h.bytes) || double(sizes[1]) > 100.0 * double(sizes[0]) + 64.0) {
      corrupt(path, "the compressed PCD data does not match the declared points");
    }
    std::vector<unsigned char> packed(sizes[0]);
    if (!in.read(reinterpret_cast<char*>(packed.data()), std::streamsize(packed.size()))) corrupt(path, "truncated PCD data");
    body.resize(sizes[1]);
    if (sizes[1] > 0 && pcl::lzfDecompress(packed.data(), sizes[0], body.data(), sizes[1]) != sizes[1]) {
      corrupt(path, "the compressed PCD data does not decompress to the declared size");
    }
    // Field after field, each for all points.
    for (int k = 0; k < 3; ++k) {
      start[std::size_t(k)] = std::size_t(h.points) * xyz[std::size_t(k)]->offset;
      step[std::size_t(k)] = std::size_t(xyz[std::size_t(k)]->type.bytes);
    }
  }
  const bool swap = !host_is_little_endian();  // PCL writes the host's order, which is little-endian everywhere it runs
  PointFile out;
  out.points.reserve(std::size_t(h.points));
  for (std::size_t i = 0; i < std::size_t(h.points); ++i) {
    double c[3];
    for (std::size_t k = 0; k < 3; ++k) c[k] = decode_scalar(&body[start[k] + i * step[k]], xyz[k]->type, swap);
    add_point(out, c[0], c[1], c[2]);
  }
  return out;
}

}  // namespace

PointFile read_pcd_points(const std::string& path) {
  std::ifstream in;
  const double size = open_sized(path, in);
  const PcdHeader h = parse_header(path, in);
  const double available = size - double(h.body);
  if (h.points == 0) corrupt(path, "the PCD header declares no points");
  if (h.data == "ascii") return read_ascii(path, in, h, available);
  if (h.data == "binary" || h.data == "binary_compressed") return read_binary(path, in, h, available);
  corrupt(path, "unknown PCD DATA type '" + printable(h.data) + "' (ascii, binary or binary_compressed)");
}

}  // namespace lsr::adapters::detail
