// SPDX-License-Identifier: BSD-3-Clause
/// @file adaptive_refinement.h
/// @brief A simplicial mesh of [0,1]^D graded towards a point set: fine (h_min) near the
/// data, coarse (h_max) far away, so the vertex count follows the data's surface measure
/// divided by h_min^(D-1), not the volume.
#pragma once

#include "geometry/nearest_point_index.h"
#include "lsrecon/core/errors.h"
#include "lsrecon/core/progress.h"
#include "lsrecon/core/simplex_geometry.h"
#include "mesh/kuhn_bisection.h"

#include <string>
#include <vector>

namespace lsr {

/// @brief Sizing of the adaptive mesh. "Size" of a simplex is KuhnBisectionForest::size():
/// longest edge / sqrt(D), the side of its Kuhn cube.
struct AdaptiveMeshOptions {
  double h_min = 1.0 / 128;  ///< finest size, reached on the data; in (0, 1). Resolution = 1/h_min
  double h_max = 1.0 / 8;    ///< coarsest size anywhere; in [h_min, 1]
  /// Optional size per data point (#N, unit box): near point i the mesh stops refining at
  /// max(h_min, point_size[i]) instead of h_min, so that it follows the local sampling.
  std::vector<double> point_size;
  /// Grading c: a simplex is refined while size > max(h_local, c * dist(simplex, data)), with
  /// dist bounded below by d(centroid) - circumradius. Smaller c widens the fine band around
  /// the data. The default 2 keeps simplices of size h_min within about 2.7 h_min of the data
  /// and a sphere mesh at 2.8% of the uniform one at h_min = 1/256. In (0, 100].
  double grading = 2.0;
  /// Refuse (lsr::MeshTooLarge) a mesh predicted to need more vertices than this.
  Index max_vertices = 20'000'000;
  int threads = 0;  ///< threads for the distance queries, 0 for all cores
  /// Optional box [region_lo, region_hi] (D coordinates each, or both empty for the whole box):
  /// only simplices meeting it are refined by the rule above, the others only where the
  /// conforming closure needs: a tile's mesh, whose core (tile_core.h) is the whole mesh's
  /// once the region reaches two background cells past it (tests/core/tile_mesh_test.cpp).
  std::vector<double> region_lo, region_hi;
};

/// @brief Thrown when the requested resolution would need more vertices than allowed.
class MeshTooLarge : public ResourceLimit {
 public:
  MeshTooLarge(const std::string& what, double largest_feasible_resolution)
      : ResourceLimit(what, "use a resolution of at most " +
                                std::to_string(int(largest_feasible_resolution)) +
                                " (h_min >= 1/" + std::to_string(int(largest_feasible_resolution)) +
                                ") or allow more memory (max_memory)"),
        largest_feasible_resolution(largest_feasible_resolution) {}
  double largest_feasible_resolution;  ///< 1/h_min that is expected to fit
};

/// @brief What the refinement did.
struct AdaptiveMeshStats {
  int passes = 0;             ///< refinement passes (one bisection level each)
  double finest_size = 0.0;   ///< smallest simplex size in the mesh
  Index uniform_vertices = 0; ///< vertices of the uniform Kuhn mesh with the finest spacing
};

/// @brief The adaptive mesh: the leaves of the bisection forest as a positively oriented
/// SimplexMesh, plus the forest for point location. The mesh's vertices are numbered along a
/// Z-order curve and its simplices by their first vertex in that order, so that neighbours in
/// space are near in memory (the forest creates them level by level, scattered over the box).
template <int D>
struct AdaptiveMesh {
  KuhnBisectionForest<D> forest{1};
  SimplexMesh<D> mesh;
  std::vector<Index> simplex_of_node;  ///< forest node -> mesh simplex, -1 for inner nodes
  std::vector<Index> vertex_of_node_vertex;  ///< forest vertex -> mesh vertex
  AdaptiveMeshStats stats;
};

/// @brief Refines a Kuhn mesh of [0,1]^D towards the points of data (which should lie in the
/// unit box; see unit_box_transform.h).
/// @throw InvalidInput for options out of range; MeshTooLarge when the mesh is predicted to
/// exceed options.max_vertices (checked before each pass allocates); Cancelled if progress asks.
template <int D>
AdaptiveMesh<D> build_adaptive_mesh(const NearestPointIndex<D>& data,
                                    const AdaptiveMeshOptions& options,
                                    const Progress& progress = Progress());

/// @brief Ends refinement of a forest and lists its leaves as a positively oriented mesh.
template <int D>
AdaptiveMesh<D> leaf_mesh(KuhnBisectionForest<D> refined);

/// @throw InvalidInput naming the first option out of range.
void validate(const AdaptiveMeshOptions& options);

}  // namespace lsr
