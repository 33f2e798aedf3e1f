// SPDX-License-Identifier: BSD-3-Clause
/// @file facet_mesh_distance.h
/// @brief Exact distances from points to a mesh of facets (segments in 2D, triangles in 3D),
/// and the signed distance to a closed one (negative inside): for comparing with a ground
/// truth, and for starting from a given curve or surface.
///
/// Nearest facet: a facet whose centroid c lies r from its farthest corner is at least
/// |q - c| - r from q, so with the nearest mesh vertex at d_v only centroids within d_v + r can
/// hold the closest point. The few facets much larger than the rest are checked for every
/// query instead of widening r for all. Sign: the parity of the crossings of a ray from q along
/// +x, counted on a grid of the facets' shadows across x, with a symbolic perturbation of q so
/// that a ray through an edge or a vertex of a closed mesh crosses it exactly once.
#pragma once

#include "geometry/nearest_point_index.h"

#include <array>
#include <vector>

namespace lsr {

template <int D>
class FacetMeshDistance {
 public:
  using Facet = std::array<Index, D>;

  /// @throw InvalidInput if there is no facet or an index is out of range.
  FacetMeshDistance(Points<D> vertices, std::vector<Facet> facets);

  /// @brief Distance from q to the nearest facet.
  double distance(const Vec<D>& q) const;
  /// @brief The same for many points, in parallel.
  std::vector<double> distances(const Points<D>& queries, int threads = 0) const;
  /// @brief distance(q), negative when q is inside the mesh, which must be closed (watertight)
  /// for the sign to mean anything.
  double signed_distance(const Vec<D>& q) const;
  /// @brief Whether q is inside (an odd number of crossings along +x).
  bool inside(const Vec<D>& q) const;

 private:
  double facet_distance(const Vec<D>& q, Index f) const;
  double nearest(const Vec<D>& q, double vertex_distance, std::vector<Index>& scratch) const;
  std::size_t cell_of(const Vec<D>& q) const;

  Points<D> vertices_;
  std::vector<Facet> facets_;
  NearestPointIndex<D> vertex_index_;
  NearestPointIndex<D> centroid_index_;
  std::vector<Index> large_facets_;
  double small_reach_ = 0.0;
  // Ray crossings: the facets whose shadow across x (y in 2D, (y, z) in 3D) meets each cell.
  Vec<D> lo_, hi_;
  int cells_ = 1;  ///< per axis
  std::vector<Index> cell_offsets_, cell_facets_;
};

using TriangleMeshDistance = FacetMeshDistance<3>;
using CurveDistance = FacetMeshDistance<2>;

}  // namespace lsr
