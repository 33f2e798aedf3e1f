// SPDX-License-Identifier: BSD-3-Clause
/// @file mesh_measures.h
/// @brief What lsrecon-compare measures on a produced mesh beside the distances to the truth:
/// welding a triangle soup so its topology can be judged, the surface's area and the share of
/// it far from the data.
#pragma once

#include "lsrecon/core/types.h"

#include <pcl/PolygonMesh.h>

#include <array>
#include <vector>

namespace lsr::demos {

// PCL's marching cubes output a triangle soup whose copies of an edge point differ by rounding:
// weld positions within 1e-6 of the diagonal so topology can be judged. lsrecon's meshes are
// indexed and taken as written: where its surface has two sides on one sheet of data they may
// lie closer than any tolerance meant for rounding.
void weld(const pcl::PolygonMesh& mesh, double diagonal, Points<3>& vertices, std::vector<std::array<Index, 3>>& triangles);

// The surface's area, and the share of it farther than 2 spacings (the median distance to
// the 8th nearest point) from every point, by facet centroids: where the surface is a guess.
struct SupportFigures {
  double area = 0.0, far_share = 0.0;
};

SupportFigures support_figures(const Points<3>& vertices, const std::vector<std::array<Index, 3>>& triangles,
                               const Points<3>& points);

}  // namespace lsr::demos
