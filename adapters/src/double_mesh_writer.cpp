// SPDX-License-Identifier: BSD-3-Clause
/// @file double_mesh_writer.cpp
#include "double_mesh_writer.h"

#include <cstdint>
#include <cstring>
#include <fstream>

namespace lsr::adapters {
namespace {

bool little_endian() {
  const std::uint16_t one = 1;
  unsigned char first = 0;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

template <class T>
void put(std::ofstream& out, T value) {
  out.write(reinterpret_cast<const char*>(&value), sizeof(T));
}

void write_ply(const TriMesh& mesh, std::ofstream& out) {
  const bool normals = mesh.has_vertex_normals();
  out << "ply\nformat " << (little_endian() ? "binary_little_endian" : "binary_big_endian") << " 1.0\n"
      << "comment lsrecon\nelement vertex " << mesh.n_vertices() << "\nproperty double x\nproperty double y\n"
      << "property double z\n";
  if (normals) out << "property double nx\nproperty double ny\nproperty double nz\n";
  const auto distance = distance_to_data(mesh);
  if (distance) out << "property double " << kDistanceProperty << "\n";
  out << "element face " << mesh.n_faces() << "\nproperty list uchar int vertex_indices\nend_header\n";
  for (const auto& v : mesh.vertices()) {
    for (int k = 0; k < 3; ++k) put(out, mesh.point(v)[k]);
    if (normals) {
      for (int k = 0; k < 3; ++k) put(out, mesh.normal(v)[k]);
    }
    if (distance) put(out, mesh.property(*distance, v));
  }
  for (const auto& f : mesh.faces()) {
    put(out, std::uint8_t(3));
    for (const auto& v : mesh.fv_range(f)) put(out, std::int32_t(v.idx()));
  }
}

void write_obj(const TriMesh& mesh, std::ofstream& out) {
  const bool normals = mesh.has_vertex_normals();
  for (const auto& v : mesh.vertices()) {
    const auto& p = mesh.point(v);
    out << "v " << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
    if (normals) out << "vn " << mesh.normal(v)[0] << ' ' << mesh.normal(v)[1] << ' ' << mesh.normal(v)[2] << '\n';
  }
  for (const auto& f : mesh.faces()) {
    out << 'f';
    for (const auto& v : mesh.fv_range(f)) {
      out << ' ' << v.idx() + 1;
      if (normals) out << "//" << v.idx() + 1;
    }
    out << '\n';
  }
}

void write_off(const TriMesh& mesh, std::ofstream& out) {
  const bool normals = mesh.has_vertex_normals();
  out << (normals ? "NOFF\n" : "OFF\n") << mesh.n_vertices() << ' ' << mesh.n_faces() << " 0\n";
  for (const auto& v : mesh.vertices()) {
    const auto& p = mesh.point(v);
    out << p[0] << ' ' << p[1] << ' ' << p[2];
    if (normals) out << ' ' << mesh.normal(v)[0] << ' ' << mesh.normal(v)[1] << ' ' << mesh.normal(v)[2];
    out << '\n';
  }
  for (const auto& f : mesh.faces()) {
    out << '3';
    for (const auto& v : mesh.fv_range(f)) out << ' ' << v.idx();
    out << '\n';
  }
}

}  // namespace

bool write_double_precision(const TriMesh& mesh, const std::string& format, const std::string& file) {
  std::ofstream out(file, std::ios::binary);
  out.precision(17);
  if (format == "ply") write_ply(mesh, out);
  else if (format == "obj") write_obj(mesh, out);
  else if (format == "off") write_off(mesh, out);
  else return false;
  return bool(out.flush());
}

}  // namespace lsr::adapters
