// SPDX-License-Identifier: BSD-3-Clause
/// @file closed_surface.h
/// @brief The output surface: closed at the walls, without unsupported parts, with the
/// inside / outside meshes and normals.
#pragma once

#include "evolution/p1_operators.h"
#include "lsrecon/core/level_set_reconstruction.h"
#include "lsrecon/core/simplex_geometry.h"
#include "mesh/point_location.h"
#include "sampling/local_sampling.h"
#include "start/outside_flood_fill.h"

#include <Eigen/Core>

#include <algorithm>
#include <limits>
#include <vector>

namespace lsr::detail {

// Output vertices keep 1% of their mesh edge from its ends: moves them by at most that (the
// fit's projection then puts them back on the surface) and keeps any two of them apart.
constexpr double kOutputEdgeMargin = 0.01;

// The output surface of `values`, closed: a front or fit that reaches the box (a handful of
// points spanning the box, a fit extrapolated past the data) is capped just inside the walls.
// Parts that no data point is nearest to go (unsupported_parts.h; a void inside such a part
// becomes one in turn, hence the loop). The values are left as extracted in `values`: the
// volume split cuts along the same level set.
template <int D, class Values>
void cap_at_walls(const SimplexMesh<D>& mesh, Values& values) {
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (on_wall<D>(mesh.vertices[v])) values[v] = std::max(values[v], std::numeric_limits<double>::min());
  }
}

template <int D>
LevelSetMesh<D> extract_closed_surface(const SimplexMesh<D>& mesh, const Points<D>& points, std::vector<double>& values,
                                       int threads);

// The inside and outside meshes, sharing the output surface, when asked for.
template <int D>
void attach_volume(ReconstructionResult<D>& r, const SimplexMesh<D>& mesh, const std::vector<double>& values,
                   bool wanted);

// The front's own surface (no fit): the level `level` of u, normals from grad u.
template <int D>
void attach_front(ReconstructionResult<D>& r, const SimplexMesh<D>& mesh, const P1Operators<D>& ops,
                  const Eigen::VectorXd& u, double level, const Points<D>& points, bool volume, int threads);

// PCA normals turned to agree with grad u at each point: outward wherever the front found the
// right side, which the topology of the front decides, not a centroid or a viewpoint.
template <int D>
Points<D> oriented_normals(const LocalSampling<D>& s, const std::vector<Location<D>>& at, const Eigen::VectorXd& gradient);

}  // namespace lsr::detail
