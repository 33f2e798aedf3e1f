// SPDX-License-Identifier: BSD-3-Clause
/// @file ply_header.cpp
#include "ply_header.h"

#include "header_lines.h"

#include "lsrecon/core/errors.h"

#include <map>

namespace lsr::adapters::detail {
namespace {

[[noreturn]] void corrupt(const std::string& path, const std::string& why) {
  throw Error(path + ": " + why, "the file is corrupt or truncated; re-export it");
}

ScalarType ply_type(const std::string& path, const std::string& name) {
  using K = ScalarType::Kind;
  static const std::map<std::string, ScalarType> types = {
      {"char", {K::signed_integer, 1}},    {"int8", {K::signed_integer, 1}},   {"uchar", {K::unsigned_integer, 1}},
      {"uint8", {K::unsigned_integer, 1}}, {"short", {K::signed_integer, 2}},  {"int16", {K::signed_integer, 2}},
      {"ushort", {K::unsigned_integer, 2}}, {"uint16", {K::unsigned_integer, 2}}, {"int", {K::signed_integer, 4}},
      {"int32", {K::signed_integer, 4}},   {"uint", {K::unsigned_integer, 4}}, {"uint32", {K::unsigned_integer, 4}},
      {"float", {K::floating, 4}},         {"float32", {K::floating, 4}},      {"double", {K::floating, 8}},
      {"float64", {K::floating, 8}}};
  const auto it = types.find(name);
  if (it == types.end()) corrupt(path, "unknown PLY property type '" + printable(name) + "'");
  return it->second;
}

}  // namespace

double PlyElement::minimum_row_bytes(bool ascii) const {
  double bytes = 0.0;
  for (const PlyProperty& p : properties) bytes += ascii ? 2.0 : double(p.is_list() ? p.list_count.bytes : p.type.bytes);
  return bytes;
}

double PlyHeader::minimum_body_bytes() const {
  const bool ascii = format == Format::ascii;
  double bytes = 0.0;
  for (const PlyElement& e : elements) bytes += e.count * e.minimum_row_bytes(ascii);
  return ascii ? std::max(0.0, bytes - 1.0) : bytes;  // no separator after the last value
}

PlyHeader parse_ply_header(const std::string& path, std::istream& in) {
  std::vector<std::vector<std::string>> lines;
  PlyHeader h;
  if (!read_header_lines(in, "end_header", false, lines, h.body) || lines.empty() || lines[0][0] != "ply") {
    corrupt(path, "no PLY header (ply ... end_header)");
  }
  bool format = false;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const auto& l = lines[i];
    if (l[0] == "format") {
      if (l.size() != 3 || format) corrupt(path, "malformed or repeated PLY format line");
      if (l[1] == "ascii") h.format = PlyHeader::Format::ascii;
      else if (l[1] == "binary_little_endian") h.format = PlyHeader::Format::binary_little_endian;
      else if (l[1] == "binary_big_endian") h.format = PlyHeader::Format::binary_big_endian;
      else corrupt(path, "unknown PLY format '" + printable(l[1]) + "'");
      format = true;
    } else if (l[0] == "element") {
      if (l.size() != 3) corrupt(path, "malformed PLY element line");
      h.elements.push_back({l[1], parse_header_count(path, l[2]), {}});
    } else if (l[0] == "property") {
      if (h.elements.empty()) corrupt(path, "a PLY property before any element");
      PlyProperty p;
      if (l.size() == 5 && l[1] == "list") {
        p.list_count = ply_type(path, l[2]);
        if (p.list_count.kind == ScalarType::floating) corrupt(path, "a PLY list whose length is a float");
        p.type = ply_type(path, l[3]);
        p.name = l[4];
      } else if (l.size() == 3 && l[1] != "list") {
        p.type = ply_type(path, l[1]);
        p.name = l[2];
      } else {
        corrupt(path, "malformed PLY property line");
      }
      h.elements.back().properties.push_back(p);
    } else if (l[0] != "comment" && l[0] != "obj_info" && l[0] != "end_header") {
      corrupt(path, "unknown PLY header line '" + printable(l[0]) + "'");
    }
  }
  if (!format) corrupt(path, "the PLY header has no format line");
  return h;
}

}  // namespace lsr::adapters::detail
