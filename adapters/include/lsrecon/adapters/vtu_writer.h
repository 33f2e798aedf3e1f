// SPDX-License-Identifier: BSD-3-Clause
/// @file vtu_writer.h
/// @brief Debugging output: a mesh and nodal fields as a VTK XML unstructured grid (.vtu),
/// readable by ParaView and VisIt.
#pragma once

#include "lsrecon/core/types.h"

#include <array>
#include <string>
#include <vector>

namespace lsr {

/// @brief A named field with one value per vertex.
struct NodalField {
  std::string name;
  const std::vector<double>* values;
};

/// @brief A named integer label per cell (e.g. a region).
struct CellLabels {
  std::string name;
  const std::vector<int>* values;
};

/// @brief Writes points (2D points get z = 0) and cells with K vertices each (K = 2 lines,
/// 3 triangles, 4 tetrahedra), nodal fields and cell labels, atomically.
/// @throw InvalidInput if a field has the wrong length; Error if the file cannot be written.
template <int D, int K>
void write_vtu(const std::string& path, const Points<D>& points,
               const std::vector<std::array<Index, K>>& cells,
               const std::vector<NodalField>& fields = {}, const std::vector<CellLabels>& labels = {});

}  // namespace lsr
