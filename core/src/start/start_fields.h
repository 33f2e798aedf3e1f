// SPDX-License-Identifier: BSD-3-Clause
/// @file start_fields.h
/// @brief The initial fields u0: a circle / sphere around or inside the data, or the tagged
/// start that hugs the data from outside (a flood from the box walls).
#pragma once

#include "geometry/nearest_point_index.h"
#include "lsrecon/core/level_set_reconstruction.h"
#include "lsrecon/core/simplex_geometry.h"
#include "sampling/local_sampling.h"
#include "sampling/unit_box_transform.h"
#include "start/cavity_sealing.h"
#include "start/open_side_closure.h"

#include <Eigen/Core>

#include <vector>

namespace lsr::detail {

// The data's bounding ball is mapped to radius 0.4, the enclosing start is the sphere of
// radius 0.45: 0.05 from the data's outermost point and from the box walls.
constexpr double kDataRadius = 0.4;
constexpr double kEnclosingRadius = 0.45;

template <int D>
Eigen::VectorXd initial_field(const SimplexMesh<D>& mesh, const NearestPointIndex<D>& data,
                              InitialFront front, double h_min);

// The signed distance to the boundary of the flooded vertices (> 0 in the flood); empty when
// the flood is empty or everything.
template <int D>
Eigen::VectorXd flood_distance(const SimplexMesh<D>& mesh, const VertexNeighbours& neighbours, const std::vector<char>& flooded,
                               double band, int threads);

// What the open-side closure (open_side_closure.h, 3D) and the nested outsides
// (nested_outsides.h) need besides the flood.
template <int D>
struct OpenSideInputs {
  const NearestPointIndex<D>& data;
  const Points<D>& normals;
  const std::vector<double>& point_scale;
  const std::vector<double>& dist;
  const std::vector<Index>& nearest;
};

// u0 for the tagged start: the region reachable from the walls while staying farther than
// gap_factor local scales from the data (`attraction`: the distance to the points, or to their
// tangent discs when holes are spanned). Over a hole the mesh is coarser than the gap: there a
// vertex also blocks when the discs pass within half its longest edge (`edge_guard`, empty
// without discs), so that no edge jumps the discs' plane; "over a hole" meaning the discs are
// nearer than the points by more than the gap, so that a coarse mesh over sampled parts does not
// push the start out. Cavities entered through an opening narrower than `seal_radius` are given
// back (cavity_sealing.h; `sealed`), and with `open` the pockets behind open sheets too
// (open_side_closure.h; `closed`), while the outsides nested in the data join the flood
// (nested_outsides.h). Empty when nothing is reachable (data against the walls).
template <int D>
Eigen::VectorXd tagged_start(const SimplexMesh<D>& mesh, const VertexNeighbours& neighbours, const Eigen::VectorXd& attraction,
                             const Eigen::VectorXd& distance, const Eigen::VectorXd& scale,
                             const std::vector<double>& edge_guard, double gap_factor, double band, double seal_radius,
                             SealedCavities& sealed, const OpenSideInputs<D>* open, OpenSides& closed, int threads);

// Half the longest edge at each vertex within `near` of the data (0 elsewhere): see tagged_start.
template <int D>
std::vector<double> half_longest_edges(const SimplexMesh<D>& mesh, const VertexNeighbours& n,
                                       const std::vector<double>& distance, const Eigen::VectorXd& near);

/// @brief u0 and what the tagged start found on its way.
template <int D>
struct StartField {
  Eigen::VectorXd u;
  std::vector<char> near_opening;  ///< #V: within the hole radius of a sealed opening; empty without
  std::vector<char> held;          ///< #V: no attraction (open_side_closure.h); empty without
  std::vector<char> kept;          ///< #V: the front kept, not fitted (open_side_closure.h); empty without
  Index open_side_points = 0;      ///< data points the flood reached from both sides
  int sealed_cavities = 0;         ///< see ReconstructionResult::sealed_cavities
  bool tagged = false;             ///< the tagged start (else a circle / sphere or the caller's)
  Eigen::VectorXd occupancy;       ///< #V: 1/2 - w of the occupancy start (occupancy_start.h); empty without
};

/// @brief u0: the caller's `custom_start` (input coordinates; `box` maps the unit box to them)
/// if given; else the tagged start pulled `start_offset` nearer the data where no hole is
/// spanned, or the enclosing sphere if nothing is reachable from the walls; else the circle /
/// sphere of options.start.initial_front.
/// @throw InvalidInput if the caller's function has no zero set in the box or is not finite.
template <int D>
StartField<D> start_field(const SimplexMesh<D>& mesh, const VertexNeighbours& neighbours, const NearestPointIndex<D>& data,
                          const LocalSampling<D>& sampling, const Eigen::VectorXd& attraction, const Eigen::VectorXd& distance,
                          const std::vector<double>& dist, const Eigen::VectorXd& scale, const ReconstructionOptions& o,
                          double hole_radius, double band, double h_min, const SignedDistance<D>* custom_start,
                          const UnitBoxTransform<D>& box, const OpenSideInputs<D>* open = nullptr);

// Behind open sheets (open_side_closure.h) the front is held by curvature alone: d := 0 where
// start.held, and where start.kept the stopping test and the rest past the data ignore the
// front (`near_hole`) and the fit keeps it (`near_opening`), as over a spanned hole.
template <int D>
void close_pocket(const StartField<D>& start, Eigen::VectorXd& attraction, std::vector<char>& near_hole,
                  std::vector<char>& near_opening);

}  // namespace lsr::detail
