// SPDX-License-Identifier: BSD-3-Clause
/// @file mesh_file_vertices.h
/// @brief The vertices of OBJ, OFF and STL files, as input points (faces are not needed).
/// Written here rather than read through OpenMesh: fuzzing found OpenMesh 9's OFF reader
/// allocating without bound on a corrupt face line, and points need none of its mesh building.
#pragma once

#include "lsrecon/core/types.h"

#include <string>

namespace lsr::adapters {

/// @brief Vertex positions, in file order; STL triangle corners welded (first occurrence kept).
/// Extra columns (OFF colours and normals, OBJ weights) are ignored; binary OFF is refused.
/// @throw lsr::Error naming the file and line when it is malformed or truncated.
Points<3> read_mesh_file_vertices(const std::string& path);

}  // namespace lsr::adapters
