// SPDX-License-Identifier: BSD-3-Clause
/// @file file_formats.cpp
/// The one table of file formats: a new format is a row here and a reader or writer of its own
/// in this folder.
#include "lsrecon/adapters/file_formats.h"

#include <algorithm>
#include <cctype>
#include <vector>

namespace lsr::adapters {

std::string file_extension(const std::string& path) {
  const std::size_t dot = path.find_last_of('.');
  const std::size_t slash = path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

namespace {

struct Format {
  const char* extension;
  std::vector<FileRole> roles;
};

const std::vector<Format>& formats() {
  using R = FileRole;
  static const std::vector<Format> table = {
      {"xyz", {R::point_input}}, {"txt", {R::point_input, R::curve_output}}, {"xy", {R::point_input}},
      {"pts", {R::point_input}}, {"pcd", {R::point_input}}, {"ply", {R::point_input, R::mesh_output}},
      {"obj", {R::point_input, R::mesh_output}}, {"off", {R::point_input, R::mesh_output}},
      {"stl", {R::point_input, R::mesh_output}}, {"pgm", {R::image_input}}, {"ppm", {R::image_input}},
      {"pbm", {R::image_input}}, {"pnm", {R::image_input}}, {"png", {R::image_input}}, {"svg", {R::curve_output}},
      {"vtk", {R::mesh_output}}, {"mesh", {R::volume_output}}, {"msh", {R::volume_output}},
      {"vtu", {R::volume_output}}, {"conf", {R::point_input}}};
  return table;
}

}  // namespace

bool has_role(const std::string& ext, FileRole role) {
  for (const Format& f : formats()) {
    if (ext == f.extension) return std::find(f.roles.begin(), f.roles.end(), role) != f.roles.end();
  }
  return false;
}

std::string extensions(FileRole role) {
  std::string list;
  for (const Format& f : formats()) {
    if (has_role(f.extension, role)) list += (list.empty() ? "." : " .") + std::string(f.extension);
  }
  return list;
}

}  // namespace lsr::adapters
