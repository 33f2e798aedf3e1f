// SPDX-License-Identifier: BSD-3-Clause
/// @file triangle_mesh_distance.h
/// @brief Exact distances from points to a triangle mesh, and the signed distance to a closed
/// one (negative inside): for comparing with a ground truth and for starting from a user's mesh.
///
/// Nearest triangle: a triangle whose centroid c lies r from its farthest corner is at least
/// |q - c| - r from q, so with the nearest mesh vertex at d_v only centroids within d_v + r can
/// hold the closest point. The few triangles much larger than the rest are checked for every
/// query instead of widening r for all. Sign: the parity of the crossings of a ray from q along
/// +x, counted on a grid of the triangles' (y, z) shadows with a symbolic perturbation of q, so
/// that a ray through an edge or a vertex of a watertight mesh crosses it exactly once.
#pragma once

#include "lsrecon/core/nearest_point_index.h"

#include <array>
#include <vector>

namespace lsr {

class TriangleMeshDistance {
 public:
  /// @throw InvalidInput if there is no triangle or an index is out of range.
  TriangleMeshDistance(Points<3> vertices, std::vector<std::array<Index, 3>> triangles);

  /// @brief Distance from q to the nearest triangle.
  double distance(const Vec<3>& q) const;
  /// @brief The same for many points, in parallel.
  std::vector<double> distances(const Points<3>& queries, int threads = 0) const;
  /// @brief distance(q), negative when q is inside the mesh, which must be closed (watertight)
  /// for the sign to mean anything.
  double signed_distance(const Vec<3>& q) const;
  /// @brief Whether q is inside (an odd number of crossings along +x).
  bool inside(const Vec<3>& q) const;

 private:
  double triangle_distance_to(const Vec<3>& q, Index f) const;

  Points<3> vertices_;
  std::vector<std::array<Index, 3>> triangles_;
  NearestPointIndex<3> vertex_index_;
  NearestPointIndex<3> centroid_index_;
  std::vector<Index> large_triangles_;
  double small_reach_ = 0.0;
  // Ray crossings: the triangles whose (y, z) bounding box meets each cell of a grid.
  Vec<3> lo_, hi_;
  int cells_ = 1;
  std::vector<Index> cell_offsets_, cell_triangles_;
};

}  // namespace lsr
