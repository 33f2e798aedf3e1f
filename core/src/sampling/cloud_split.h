// SPDX-License-Identifier: BSD-3-Clause
/// @file cloud_split.h
/// @brief The data of distinct_finite_points, the unit box and in_z_order for a cloud split among
/// workers (lsrecon/core/tile_exchange.h): each passes its share of the input, the workers agree
/// on the box by reductions and sort the points along the Z-order curve among them (samples of
/// the keys cut the curve into one run per worker), and each drops the copies in its run. Each
/// worker ends with a run of the order one process gives, the same box, to the bit.
#pragma once

#include "lsrecon/core/tile_exchange.h"
#include "lsrecon/core/types.h"
#include "sampling/unit_box_transform.h"

#include <vector>

namespace lsr::detail {

template <int D>
struct SplitCloud {
  Points<D> points;                ///< this worker's run: distinct finite points, input coordinates, in Z-order
  std::size_t global_first = 0;    ///< the global index of points[0] among every worker's
  std::size_t global_size = 0;     ///< distinct finite points in all
  std::size_t input_points = 0, skipped_points = 0, duplicate_points = 0;  ///< in all
};

/// @brief Distinct finite points of the workers' shares (worker w's input indices follow worker
/// w - 1's), each worker's run along the Z-order curve of the box fit_ball(kDataRadius) gives.
/// @throw InvalidInput as require_spanning.
template <int D>
SplitCloud<D> split_cloud(const Points<D>& share, const TileExchange* exchange, double data_radius, UnitBoxTransform<D>& box);

/// @brief require_spanning on the points of all workers.
template <int D>
void require_spanning_over_workers(const Points<D>& points, const TileExchange* exchange);

/// @brief The box of fit_ball(points of all workers, radius), by reductions.
template <int D>
UnitBoxTransform<D> ball_over_workers(const Points<D>& points, std::size_t count, const TileExchange* exchange, double radius);

}  // namespace lsr::detail
