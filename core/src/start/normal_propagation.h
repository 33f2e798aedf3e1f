// SPDX-License-Identifier: BSD-3-Clause
/// @file normal_propagation.h
/// @brief Consistent senses for unoriented normals: each point's normal flipped so that it
/// agrees with its neighbours', along a minimum spanning tree of the k-nearest graph weighted
/// by 1 - |n_p . n_q| (Hoppe et al., "Surface reconstruction from unorganized points", 1992).
/// The tree crosses from one normal to the next where they are nearly parallel, so a sense
/// travels along smooth sheets and round creases last. It fixes senses relative to each
/// other only: one tree per connected part of the graph, each with an arbitrary overall sense.
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

/// @param normals unit normals, `knn` each point's k nearest (row-major, k per point; a point
/// may list itself, which is skipped)
template <int D>
PropagatedSenses propagate_senses(const Points<D>& normals, const LargeVector<Index>& knn, int k);

}  // namespace lsr::detail
