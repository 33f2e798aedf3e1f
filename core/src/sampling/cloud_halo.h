// SPDX-License-Identifier: BSD-3-Clause
/// @file cloud_halo.h
/// @brief A worker's run of the cloud plus its halo: the other workers' points that its queries
/// reach (lsrecon/core/tile_exchange.h). The sampling reads at most the 32 nearest of a point
/// and a ball of half their radius one radius away (the rim test), so its halo holds every point
/// within 1.5 times the distance to an own point's 32nd nearest among this worker's own points,
/// which bounds the distance among all. The k nearest of an own point in own + halo are then
/// those in the whole cloud; the halo keeps the cloud's order, so the index breaks ties as one
/// process does.
#pragma once

#include "lsrecon/core/progress.h"
#include "lsrecon/core/tile_exchange.h"
#include "lsrecon/core/types.h"
#include "sampling/worker_collectives.h"

#include <functional>
#include <vector>

namespace lsr {

/// @brief Where a worker's own points and its halo lie among its local points, and which of its
/// own points the others' halos hold.
struct CloudHalo {
  std::size_t first = 0, end = 0;                ///< own points: local [first, end)
  std::size_t global_first = 0, global_size = 0;  ///< the global index of local `first`; the cloud's points
  std::vector<std::vector<std::size_t>> send;    ///< per worker: own local indices in its halo
  std::vector<std::size_t> from;                 ///< workers + 1: worker u's points are local [from[u], from[u + 1])
  const TileExchange* exchange = nullptr;

  /// The own points' values (plain data) to the halos that hold them; the halo's from theirs.
  template <class T, class A>
  void share(std::vector<T, A>& values) const {
    std::vector<std::vector<T>> out(send.size());
    for (std::size_t v = 0; v < send.size(); ++v) {
      for (const std::size_t i : send[v]) out[v].push_back(values[i]);
    }
    const std::vector<std::vector<T>> in = exchange_values(exchange, out);
    const std::size_t me = worker_of(exchange);
    for (std::size_t u = 0; u < in.size(); ++u) {
      if (u == me) continue;
      for (std::size_t j = 0; j < in[u].size(); ++j) values[from[u] + j] = in[u][j];
    }
  }

  /// The reverse: the halo's values added to those of the points they copy.
  template <class T, class A>
  void add_to_owners(std::vector<T, A>& values) const {
    const std::size_t me = worker_of(exchange);
    std::vector<std::vector<T>> out(send.size());
    for (std::size_t u = 0; u < send.size(); ++u) {
      if (u != me) out[u].assign(values.begin() + long(from[u]), values.begin() + long(from[u + 1]));
    }
    const std::vector<std::vector<T>> in = exchange_values(exchange, out);
    for (std::size_t v = 0; v < send.size(); ++v) {
      if (v == me) continue;
      for (std::size_t j = 0; j < in[v].size(); ++j) values[send[v][j]] += in[v][j];
    }
  }
};

/// @brief Where a halo must reach: around each query point at[q], the ball of radius reach[q].
template <int D>
struct HaloQueries {
  Points<D> at;
  std::vector<double> reach;
};

/// @brief This worker's own points (unit box, in the cloud's order, global indices from
/// global_first) with their halo, in the cloud's order.
template <int D>
struct HaloCloud {
  Points<D> points;
  CloudHalo halo;
};

/// @brief Builds the halo of `own` from the other workers' points (every worker calls it): the
/// points within reach of `queries()`, called only when there are other workers. In `own`,
/// consecutive queries should be near each other (the Z-order): blocks of them are boxed.
template <int D>
HaloCloud<D> with_halo(const Points<D>& own, std::size_t global_first, std::size_t global_size, const TileExchange* exchange,
                       const std::function<HaloQueries<D>()>& queries);

/// @brief The queries of the own points' k nearest, and of balls up to (factor - 1) times their
/// distance beyond: factor times the distance to the k-th nearest among `own`, which bounds
/// the distance among all; infinite with fewer than k + 1 own points.
template <int D>
HaloQueries<D> own_neighbourhoods(const Points<D>& own, int k, double factor, int threads, const Progress& progress);

}  // namespace lsr
