// SPDX-License-Identifier: BSD-3-Clause
/// @file isolated_points.h
/// @brief Isolated points (drop_isolated: the nearest distinct neighbour farther than `factor`
/// local spacings) are left out and the sampling is estimated again without them, as the box and
/// every scale follow the data without them. So they are looked for as soon as the spacing is
/// known up to its raise over gaps (spacing_over_gaps.h), which takes more than half of the
/// sampling's time on scan lines: at 10M points one estimate then costs about 25 s, not 65 s.
#pragma once

#include "sampling/local_sampling.h"
#include "sampling/tile_runs.h"

namespace lsr {

/// @brief Whether any point of the cloud (of every worker) is isolated, where s.spacing is not
/// yet raised over gaps and `raised` says whether it will be. A raise only widens the spacing,
/// so only a point isolated under the spacing as it stands can be; its raised spacing reads the
/// gap widths of its kNeighbours nearest (`neighbours`, as estimate_local_sampling holds them),
/// which their owners compute. If any is, each such candidate's s.spacing becomes the raised
/// one, so that drop_isolated drops exactly the points the whole estimate would have.
template <int D>
bool isolated_points_found(const NearestPointIndex<D>& data, const LargeVector<Index>& neighbours, bool raised, double factor,
                           int threads, const TileRuns& tiles, LocalSampling<D>& s);

}  // namespace lsr
