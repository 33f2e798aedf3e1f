// SPDX-License-Identifier: BSD-3-Clause
/// @file normal_propagation.h
/// @brief Consistent senses for unoriented normals: each point's normal flipped so that it
/// agrees with its neighbours', along a minimum spanning tree of the k-nearest graph (Hoppe et
/// al., "Surface reconstruction from unorganized points", 1992). Two normals are compared as
/// König and Gumhold ("Consistent propagation of normal orientations in point clouds", 2009)
/// do: n_q against n_p mirrored in the plane bisecting the chord pq, which maps a sphere's
/// normals onto each other exactly and is n_p . n_q where the chord is tangent. Across a gap
/// between sheets facing each other (two bodies nearly touching, the two sides of a thin wall)
/// the chord is along the normals and the mirror keeps their senses apart, where Hoppe's
/// n_p . n_q would flip one sheet against the other. Edges weigh 1 - |agreement|, so a sense
/// travels where the comparison is clearest. It fixes senses relative to each other only: one
/// tree per connected part of the graph, each with an arbitrary overall sense.
#pragma once

#include "lsrecon/core/types.h"

#include <vector>

namespace lsr::detail {

/// @brief What propagate_senses found.
struct PropagatedSenses {
  std::vector<signed char> sense;  ///< #N +1 / -1: the normal as given / flipped
  std::vector<Index> part;         ///< #N the connected part of the k-nearest graph (0, 1, ...)
  Index parts = 0;
};

/// @param points the points, `normals` their unit normals, `knn` each point's k nearest (row-major, k per point; a point
/// may list itself, which is skipped)
/// @param noise each point's noise deviation (LocalSampling::noise), or empty: none
template <int D>
PropagatedSenses propagate_senses(const Points<D>& points, const Points<D>& normals, const LargeVector<Index>& knn, int k,
                                  const std::vector<double>& noise = {});

}  // namespace lsr::detail
