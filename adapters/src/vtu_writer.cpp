// SPDX-License-Identifier: BSD-3-Clause
/// @file vtu_writer.cpp
#include "lsrecon/adapters/vtu_writer.h"

#include "lsrecon/adapters/atomic_file.h"
#include "lsrecon/core/errors.h"

#include <fstream>
#include <iomanip>

namespace lsr {

template <int D, int K>
void write_vtu(const std::string& path, const Points<D>& points,
               const std::vector<std::array<Index, K>>& cells,
               const std::vector<NodalField>& fields, const std::vector<CellLabels>& labels) {
  static_assert(K >= 2 && K <= 4, "cells are lines, triangles or tetrahedra");
  for (const auto& f : fields) {
    if (f.values->size() != points.size()) {
      throw InvalidInput("field '" + f.name + "' has " + std::to_string(f.values->size()) +
                             " values for " + std::to_string(points.size()) + " points",
                         "pass one value per point");
    }
  }
  for (const auto& l : labels) {
    if (l.values->size() != cells.size()) {
      throw InvalidInput("labels '" + l.name + "' have " + std::to_string(l.values->size()) + " values for " +
                             std::to_string(cells.size()) + " cells",
                         "pass one label per cell");
    }
  }
  const int vtk_type = K == 2 ? 3 : K == 3 ? 5 : 10;
  write_file_atomically(path, [&](const std::string& file) {
    std::ofstream out(file);
    if (!out) throw Error("cannot open " + path + " for writing", "check the output folder");
    out << std::setprecision(17);
    out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\">\n"
        << "<UnstructuredGrid>\n<Piece NumberOfPoints=\"" << points.size()
        << "\" NumberOfCells=\"" << cells.size() << "\">\n";
    out << "<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (const auto& p : points) out << p[0] << ' ' << p[1] << ' ' << (D == 3 ? p[D - 1] : 0.0) << '\n';
    out << "</DataArray></Points>\n<Cells>\n"
        << "<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">\n";
    for (const auto& c : cells) {
      for (Index v : c) out << v << ' ';
      out << '\n';
    }
    out << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
    for (std::size_t i = 1; i <= cells.size(); ++i) out << i * K << '\n';
    out << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
    for (std::size_t i = 0; i < cells.size(); ++i) out << vtk_type << '\n';
    out << "</DataArray>\n</Cells>\n<PointData>\n";
    for (const auto& f : fields) {
      out << "<DataArray type=\"Float64\" Name=\"" << f.name << "\" format=\"ascii\">\n";
      for (double v : *f.values) out << v << '\n';
      out << "</DataArray>\n";
    }
    out << "</PointData>\n<CellData>\n";
    for (const auto& l : labels) {
      out << "<DataArray type=\"Int32\" Name=\"" << l.name << "\" format=\"ascii\">\n";
      for (int v : *l.values) out << v << '\n';
      out << "</DataArray>\n";
    }
    out << "</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
    out.close();
    if (!out) throw Error("writing " + path + " failed", "check free disk space");
  });
}

template void write_vtu<2, 2>(const std::string&, const Points<2>&,
                              const std::vector<std::array<Index, 2>>&, const std::vector<NodalField>&,
                              const std::vector<CellLabels>&);
template void write_vtu<2, 3>(const std::string&, const Points<2>&,
                              const std::vector<std::array<Index, 3>>&, const std::vector<NodalField>&,
                              const std::vector<CellLabels>&);
template void write_vtu<3, 3>(const std::string&, const Points<3>&,
                              const std::vector<std::array<Index, 3>>&, const std::vector<NodalField>&,
                              const std::vector<CellLabels>&);
template void write_vtu<3, 4>(const std::string&, const Points<3>&,
                              const std::vector<std::array<Index, 4>>&, const std::vector<NodalField>&,
                              const std::vector<CellLabels>&);

}  // namespace lsr
