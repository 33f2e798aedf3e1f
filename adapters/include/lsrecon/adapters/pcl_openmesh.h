// SPDX-License-Identifier: BSD-3-Clause
/// @file pcl_openmesh.h
/// @brief pcl::PolygonMesh -> OpenMesh triangle mesh, e.g. pcl::LevelSetReconstruction's output
/// for OpenMesh's decimation, smoothing or IO.
#pragma once

#include "lsrecon/adapters/openmesh_mesh.h"  // first: OpenMesh wants its IO header first

#include <pcl/PolygonMesh.h>

namespace lsr::adapters {

/// @brief The triangles of `mesh` over its vertices, with vertex normals when its cloud has
/// normal_x, normal_y, normal_z and the per-vertex distance to the data (kDistanceProperty)
/// when it has that field; polygons other than triangles are skipped.
/// @throw lsr::Error if OpenMesh refuses a triangle (a non-manifold mesh).
TriMesh to_openmesh(const pcl::PolygonMesh& mesh);

}  // namespace lsr::adapters
