// SPDX-License-Identifier: BSD-3-Clause
#include "lsrecon/adapters/volume_mesh_files.h"

#include "lsrecon/adapters/atomic_file.h"
#include "lsrecon/adapters/point_files.h"
#include "lsrecon/adapters/vtu_writer.h"
#include "lsrecon/core/errors.h"

#include <fstream>
#include <iomanip>

namespace lsr::adapters {
namespace {

template <int D>
void write_point(std::ostream& out, const Vec<D>& p) {
  for (int k = 0; k < D; ++k) out << (k ? " " : "") << p[k];
}

// Medit: 1-based indices, a reference per entity.
template <int D>
void write_medit(std::ostream& out, const VolumeMesh<D>& m) {
  out << "MeshVersionFormatted 2\n\nDimension " << D << "\n\nVertices\n" << m.vertices.size() << '\n';
  for (const auto& p : m.vertices) {
    write_point<D>(out, p);
    out << " 0\n";
  }
  out << '\n' << (D == 3 ? "Tetrahedra" : "Triangles") << '\n' << m.simplices.size() << '\n';
  for (std::size_t s = 0; s < m.simplices.size(); ++s) {
    for (Index v : m.simplices[s]) out << v + 1 << ' ';
    out << m.regions[s] << '\n';
  }
  out << '\n' << (D == 3 ? "Triangles" : "Edges") << '\n' << m.interface.size() + m.walls.size() << '\n';
  for (const auto* facets : {&m.interface, &m.walls}) {
    const int label = facets == &m.interface ? kInterfaceLabel : kWallLabel;
    for (const auto& f : *facets) {
      for (Index v : f) out << v + 1 << ' ';
      out << label << '\n';
    }
  }
  out << "\nEnd\n";
}

// Gmsh 2.2 ASCII: physical groups name the labels; element types 1 line, 2 triangle, 4 tet.
template <int D>
void write_gmsh(std::ostream& out, const VolumeMesh<D>& m) {
  const int cell_type = D == 3 ? 4 : 2, facet_type = D == 3 ? 2 : 1;
  out << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n4\n"
      << D << " 1 \"inside\"\n" << D << " 2 \"outside\"\n"
      << D - 1 << ' ' << kInterfaceLabel << " \"surface\"\n" << D - 1 << ' ' << kWallLabel << " \"box\"\n"
      << "$EndPhysicalNames\n$Nodes\n" << m.vertices.size() << '\n';
  for (std::size_t i = 0; i < m.vertices.size(); ++i) {
    out << i + 1 << ' ';
    write_point<D>(out, m.vertices[i]);
    out << (D == 2 ? " 0\n" : "\n");
  }
  out << "$EndNodes\n$Elements\n" << m.simplices.size() + m.interface.size() + m.walls.size() << '\n';
  std::size_t id = 0;
  auto element = [&](int type, int label, const auto& vertices) {
    out << ++id << ' ' << type << " 2 " << label << ' ' << label;
    for (Index v : vertices) out << ' ' << v + 1;
    out << '\n';
  };
  for (std::size_t s = 0; s < m.simplices.size(); ++s) element(cell_type, m.regions[s], m.simplices[s]);
  for (const auto& f : m.interface) element(facet_type, kInterfaceLabel, f);
  for (const auto& f : m.walls) element(facet_type, kWallLabel, f);
  out << "$EndElements\n";
}

}  // namespace

template <int D>
void write_volume_mesh(const std::string& path, const VolumeMesh<D>& mesh) {
  const std::string ext = file_extension(path);
  if (ext == "vtu") {
    write_vtu<D, D + 1>(path, mesh.vertices, mesh.simplices, {}, {{"region", &mesh.regions}});
    return;
  }
  if (!has_role(ext, FileRole::volume_output)) {
    throw InvalidInput("cannot write a volume mesh as '" + path + "'", "use " + extensions(FileRole::volume_output));
  }
  write_file_atomically(path, [&](const std::string& file) {
    std::ofstream out(file);
    if (!out) throw Error("cannot open " + path + " for writing", "check the output folder");
    out << std::setprecision(17);
    if (ext == "mesh") {
      write_medit<D>(out, mesh);
    } else {
      write_gmsh<D>(out, mesh);
    }
    out.close();
    if (!out) throw Error("writing " + path + " failed", "check free disk space");
  });
}

template void write_volume_mesh<2>(const std::string&, const VolumeMesh<2>&);
template void write_volume_mesh<3>(const std::string&, const VolumeMesh<3>&);

}  // namespace lsr::adapters
