// SPDX-License-Identifier: BSD-3-Clause
/// @file surface_topology.h
/// @brief Watertightness, manifoldness, orientation, components and genus of a triangle
/// surface; the checks every reconstruction is judged by.
#pragma once

#include "lsrecon/core/types.h"

#include <array>
#include <vector>

namespace lsr {

/// @brief Topological facts about a triangle surface.
struct SurfaceTopology {
  bool watertight = false;       ///< every edge has exactly two incident triangles
  bool edge_manifold = false;    ///< no edge has more than two incident triangles
  bool vertex_manifold = false;  ///< the triangles around each vertex form one fan
  bool oriented = false;         ///< every interior edge is used once in each direction
  int components = 0;            ///< connected components (through shared edges)
  std::vector<int> genus;        ///< per component, (2 - V + E - F) / 2 (valid when watertight)
  double signed_volume = 0.0;    ///< > 0 when closed and oriented with outward normals
  int degenerate_triangles = 0;  ///< triangles with a repeated vertex index
};

/// @brief Analyses triangles over vertices (#F triangles over #V points).
SurfaceTopology analyze_surface(const Points<3>& vertices,
                                const std::vector<std::array<Index, 3>>& triangles);

}  // namespace lsr
