// SPDX-License-Identifier: BSD-3-Clause
/// @file double_mesh_writer.h
/// @brief PLY (binary), OBJ and OFF in double precision. Written here because OpenMesh 9's
/// writers store float coordinates whatever the mesh holds (measured: 0.07 error on a surface
/// at 1e6, a georeferenced scan in metres). STL stays with OpenMesh: the format is float.
#pragma once

#include "lsrecon/adapters/openmesh_mesh.h"

#include <string>

namespace lsr::adapters {

/// @brief Writes `mesh` to `file` as `format` ("ply", "obj" or "off"), vertex normals included
/// when the mesh has them. False if the stream failed.
bool write_double_precision(const TriMesh& mesh, const std::string& format, const std::string& file);

}  // namespace lsr::adapters
