// SPDX-License-Identifier: BSD-3-Clause
/// @file volume_mesh_files.h
/// @brief Inside/outside meshes (level_set_volume_mesh.h) for simulation codes: Medit .mesh
/// (Mmg, FreeFEM), Gmsh .msh (format 2.2, read by Gmsh 2-4 and most solvers) and VTK .vtu
/// (ParaView), written atomically in double precision.
///
/// Labels, the same in every format: inside simplices 1, outside 2 (Medit references, Gmsh
/// physical groups, the vtu's "region" cell array); the interface (the reconstructed surface)
/// 10 and the box walls 20 as boundary triangles (3D) or edges (2D) in .mesh and .msh.
#pragma once

#include "lsrecon/core/level_set_volume_mesh.h"

#include <string>

namespace lsr::adapters {

inline constexpr int kInterfaceLabel = 10;
inline constexpr int kWallLabel = 20;

/// @brief Writes the mesh in the format of the file's extension (.mesh, .msh or .vtu).
/// @throw lsr::InvalidInput for another extension; lsr::Error if the file cannot be written
/// (an existing file is left as it was).
template <int D>
void write_volume_mesh(const std::string& path, const VolumeMesh<D>& mesh);

}  // namespace lsr::adapters
