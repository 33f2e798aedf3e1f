// SPDX-License-Identifier: BSD-3-Clause
/// @file ply_points.cpp
/// @brief The vertex element's x, y, z from a PLY file: ascii rows are read as a stream of
/// tokens, binary rows as bytes; rows of elements before the vertices are skipped.
#include "binary_scalars.h"
#include "header_lines.h"
#include "ply_header.h"
#include "point_file_readers.h"

#include "lsrecon/core/errors.h"

#include <array>
#include <cmath>
#include <fstream>

namespace lsr::adapters::detail {
namespace {

[[noreturn]] void corrupt(const std::string& path, const std::string& why) {
  throw Error(path + ": " + why, "the file is corrupt or truncated; re-export it");
}

// Reads rows one property at a time, from text or bytes.
class RowReader {
 public:
  RowReader(const std::string& path, std::istream& in, PlyHeader::Format format)
      : path_(path), in_(in), ascii_(format == PlyHeader::Format::ascii),
        swap_((format == PlyHeader::Format::binary_little_endian) != host_is_little_endian()) {}

  double value(ScalarType type) {
    double v = 0.0;
    if (ascii_) {
      if (!(in_ >> token_)) corrupt(path_, "the PLY data ends before the last vertex");
      if (!parse_number(token_, v)) corrupt(path_, "'" + printable(token_) + "' in the PLY data is not a number");
      return as_declared(v, type);
    }
    unsigned char bytes[8];
    if (!in_.read(reinterpret_cast<char*>(bytes), type.bytes)) corrupt(path_, "the PLY data ends before the last vertex");
    return decode_scalar(bytes, type, swap_);
  }

  // A list's items are read and dropped (no list is a coordinate).
  void skip_list(const PlyProperty& p) {
    const double n = value(p.list_count);
    // Checked before any conversion: a length past 2^53 (text can say 6.9e79) fits no integer.
    if (!(n >= 0.0 && n <= 9007199254740992.0) || n != std::floor(n)) {
      corrupt(path_, "a PLY list has a negative, fractional or impossible length");
    }
    if (ascii_) {
      for (double i = 0; i < n; ++i) value(p.type);
    } else {
      in_.seekg(std::streamoff(n) * p.type.bytes, std::ios::cur);
      if (!in_) corrupt(path_, "the PLY data ends before the last vertex");
    }
  }

  // The element's rows [first, end) (all by default), the values of properties `wanted` (index
  // per property, -1 if not) in out; the rows before are skipped, by a seek where they are bytes
  // of one size.
  template <class Row>
  void rows(const PlyElement& e, const std::vector<int>& wanted, Row row, double first = 0, double end = -1) {
    std::array<double, 3> out{};
    if (e.properties.empty()) return;  // rows of nothing, however many (a fuzzer's 6.7e13 took minutes)
    if (end < 0) end = e.count;
    const bool fixed = std::none_of(e.properties.begin(), e.properties.end(), [](const PlyProperty& p) { return p.is_list(); });
    if (!ascii_ && fixed && first > 0) {
      in_.seekg(std::streamoff(first * e.minimum_row_bytes(false)), std::ios::cur);
      if (!in_) corrupt(path_, "the PLY data ends before the last vertex");
    } else {
      for (double r = 0; r < first; ++r) {
        for (const PlyProperty& p : e.properties) {
          if (p.is_list()) {
            skip_list(p);
          } else {
            value(p.type);
          }
        }
      }
    }
    for (double r = first; r < end; ++r) {
      for (std::size_t p = 0; p < e.properties.size(); ++p) {
        if (e.properties[p].is_list()) {
          skip_list(e.properties[p]);
        } else {
          const double v = value(e.properties[p].type);
          if (wanted[p] >= 0) out[std::size_t(wanted[p])] = v;
        }
      }
      row(out);
    }
  }

 private:
  const std::string& path_;
  std::istream& in_;
  bool ascii_;
  bool swap_;
  std::string token_;
};

}  // namespace

PointFile read_ply_points(const std::string& path, FileShare share) {
  std::ifstream in;
  const double size = open_sized(path, in);
  const PlyHeader h = parse_ply_header(path, in);
  const bool ascii = h.format == PlyHeader::Format::ascii;
  double elements = 0.0;
  for (const PlyElement& e : h.elements) elements += e.count;
  require_declared_fits(path, elements, h.minimum_body_bytes(), size - double(h.body), "elements");
  RowReader reader(path, in, h.format);
  for (const PlyElement& e : h.elements) {
    std::vector<int> wanted(e.properties.size(), -1);
    int found = 0;
    for (std::size_t p = 0; p < e.properties.size(); ++p) {
      for (int k = 0; k < 3; ++k) {
        if (e.properties[p].name == std::string(1, char('x' + k)) && !e.properties[p].is_list()) {
          wanted[p] = k;
          ++found;
        }
      }
    }
    if (e.name != "vertex") {
      const bool fixed = std::none_of(e.properties.begin(), e.properties.end(), [](const PlyProperty& p) { return p.is_list(); });
      if (!ascii && fixed) {
        in.seekg(std::streamoff(e.count * e.minimum_row_bytes(false)), std::ios::cur);
      } else {
        reader.rows(e, wanted, [](const std::array<double, 3>&) {});
      }
      if (!in) corrupt(path, "the PLY data ends before the vertices");
      continue;
    }
    if (found != 3) corrupt(path, "the PLY vertex element has no x, y and z (or has one twice)");
    if (e.count == 0) break;
    PointFile out;
    const std::size_t rows = std::size_t(e.count), first = share.part * rows / share.parts, end = (share.part + 1) * rows / share.parts;
    out.other_rows = rows - (end - first);
    out.points.reserve(end - first);
    reader.rows(e, wanted, [&](const std::array<double, 3>& c) {
      const Vec<3> p(c[0], c[1], c[2]);
      if (p.allFinite()) {
        out.points.push_back(p);
      } else {
        ++out.skipped;
      }
    }, double(first), double(end));
    return out;
  }
  corrupt(path, "no vertex element (or an empty one) with x, y and z in the PLY header");
}

}  // namespace lsr::adapters::detail
