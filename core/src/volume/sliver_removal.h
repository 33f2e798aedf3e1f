// SPDX-License-Identifier: BSD-3-Clause
/// @file sliver_removal.h
/// @brief The thin and tiny simplices a cut along a level set leaves: where the surface passes
/// close to a box-mesh vertex, the simplices between that vertex and the surface. The vertex
/// moves away; the surface vertices never move, so the surface stays exactly the boundary
/// between the regions. (Merging such a vertex into a surface vertex, an edge collapse, was
/// tried: where the surface runs straight past the vertex it flattens the re-coned simplices.)
#pragma once

#include "lsrecon/core/level_set_volume_mesh.h"

#include <cstddef>

namespace lsr {

/// Simplices with an angle below this are worth changing the mesh for.
inline constexpr double kSliverAngleDegrees = 10.0;
/// A simplex below this fraction of the mean simplex measure is flat: a simulation code's
/// element matrices lose about 9 digits there (the bar issue 46 sets).
inline constexpr double kFlatMeasure = 1e-9;
/// A cut within 1% of an edge from a box vertex leaves a corner of 1e-6 of its simplex (3D):
/// small enough to move the vertex away, even when the corner is well shaped.
inline constexpr double kSmallMeasure = 1e-6;

/// @brief Moves box vertices near slivers (an angle below kSliverAngleDegrees, or a measure
/// below kSmallMeasure of the mean) towards the centroid of their neighbours, or part of
/// the way, when that raises the worst simplex around them (so keeps them positive): its
/// smallest angle, or less for a simplex below kSmallMeasure (in proportion to its measure).
template <int D>
void smooth_near_slivers(VolumeMesh<D>& mesh, int passes);

}  // namespace lsr
