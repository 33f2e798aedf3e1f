// SPDX-License-Identifier: BSD-3-Clause
/// @file tile_outputs.cpp
#include "tiles/tile_outputs.h"

#include "sampling/worker_collectives.h"

#include <algorithm>
#include <type_traits>

namespace lsr::detail {

template <int D>
TileSummary tile_summary(const ReconstructionResult<D>& r, int tile) {
  TileSummary s;
  s.tile = tile;
  s.status = r.status;
  s.stalled = r.stalled, s.tagged_start = r.tagged_start;
  s.iterations = r.iterations, s.best_iteration = r.best_iteration, s.sealed_cavities = r.sealed_cavities;
  s.residual = r.residual, s.tolerance = r.tolerance, s.h_min = r.h_min;
  s.time_step = r.time_step, s.alpha = r.alpha, s.curvature_weight = r.curvature_weight;
  s.unreached_points = r.unreached_points;
  s.mesh_vertices = r.mesh_vertices, s.mesh_simplices = r.mesh_simplices, s.open_side_points = r.open_side_points;
  s.solver_iterations = r.solver_iterations;
  return s;
}

template <int D>
void add_tile_summary(ReconstructionResult<D>& r, const TileSummary& t, bool first) {
  auto worse = [](ReconstructionStatus a, ReconstructionStatus b) { return int(a) > int(b) ? a : b; };
  r.status = first ? t.status : worse(r.status, t.status);
  r.stalled = r.stalled || t.stalled;
  r.iterations = std::max(r.iterations, t.iterations);
  r.best_iteration = std::max(r.best_iteration, t.best_iteration);
  r.residual = std::max(r.residual, t.residual);
  r.tolerance = std::max(r.tolerance, t.tolerance);
  r.unreached_points = std::max(r.unreached_points, t.unreached_points);
  r.mesh_vertices = std::max(r.mesh_vertices, t.mesh_vertices);
  r.mesh_simplices = std::max(r.mesh_simplices, t.mesh_simplices);
  r.h_min = first ? t.h_min : std::min(r.h_min, t.h_min);
  r.tagged_start = t.tagged_start;
  r.sealed_cavities = std::max(r.sealed_cavities, t.sealed_cavities);
  r.open_side_points = std::max(r.open_side_points, t.open_side_points);
  r.time_step = t.time_step, r.alpha = t.alpha, r.curvature_weight = t.curvature_weight;
  r.solver_iterations += t.solver_iterations;
}

namespace {

// One array of every tile of this worker to worker 0, concatenated in tile order; the tiles'
// own arrays are released on the way.
template <int D, class Member>
auto to_worker_zero(const TileExchange* x, std::vector<TileOutput<D>>& mine, Member member) {
  using T = typename std::decay_t<decltype(member(mine.front()))>::value_type;
  std::vector<std::vector<T>> out(workers_of(x));
  for (TileOutput<D>& t : mine) {
    auto& values = member(t);
    out[0].insert(out[0].end(), values.begin(), values.end());
    std::decay_t<decltype(values)>().swap(values);
  }
  return exchange_values(x, out);
}

template <class To, class T>
void take(To& to, const std::vector<T>& from, std::size_t& at, std::size_t n) {
  to.assign(from.begin() + long(at), from.begin() + long(at + n));
  at += n;
}

}  // namespace

template <int D>
std::vector<TileOutput<D>> gather_tile_outputs(const TileExchange* x, std::vector<TileOutput<D>> mine) {
  if (workers_of(x) == 1) return mine;
  std::vector<std::vector<TileSummary>> summaries(workers_of(x));
  for (const TileOutput<D>& t : mine) summaries[0].push_back(t.summary);
  summaries = exchange_values(x, summaries);
  // Every worker calls every exchange, with or without tiles.
  const auto normals = to_worker_zero<D>(x, mine, [](TileOutput<D>& t) -> auto& { return t.normals; });
  const auto on_data = to_worker_zero<D>(x, mine, [](TileOutput<D>& t) -> auto& { return t.on_data; });
  const auto seam = to_worker_zero<D>(x, mine, [](TileOutput<D>& t) -> auto& { return t.seam; });
  const auto vertices = to_worker_zero<D>(x, mine, [](TileOutput<D>& t) -> auto& { return t.shell.core.vertices; });
  const auto simplices = to_worker_zero<D>(x, mine, [](TileOutput<D>& t) -> auto& { return t.shell.core.simplices; });
  const auto values = to_worker_zero<D>(x, mine, [](TileOutput<D>& t) -> auto& { return t.shell.u; });
  if (worker_of(x) != 0) return {};
  std::vector<TileOutput<D>> all;
  for (std::size_t w = 0; w < summaries.size(); ++w) {
    std::size_t point = 0, seam_vertex = 0, vertex = 0, simplex = 0;
    for (const TileSummary& s : summaries[w]) {
      TileOutput<D> t;
      t.summary = s;
      std::size_t at = point;
      take(t.normals, normals[w], at, s.owned_points);
      take(t.on_data, on_data[w], point, s.owned_points);
      take(t.seam, seam[w], seam_vertex, s.seam_vertices);
      at = vertex;
      take(t.shell.core.vertices, vertices[w], at, s.shell_vertices);
      take(t.shell.u, values[w], vertex, s.shell_vertices);
      take(t.shell.core.simplices, simplices[w], simplex, s.shell_simplices);
      all.push_back(std::move(t));
    }
  }
  std::sort(all.begin(), all.end(), [](const TileOutput<D>& a, const TileOutput<D>& b) { return a.summary.tile < b.summary.tile; });
  return all;
}

template TileSummary tile_summary<2>(const ReconstructionResult<2>&, int);
template TileSummary tile_summary<3>(const ReconstructionResult<3>&, int);
template void add_tile_summary<2>(ReconstructionResult<2>&, const TileSummary&, bool);
template void add_tile_summary<3>(ReconstructionResult<3>&, const TileSummary&, bool);
template std::vector<TileOutput<2>> gather_tile_outputs<2>(const TileExchange*, std::vector<TileOutput<2>>);
template std::vector<TileOutput<3>> gather_tile_outputs<3>(const TileExchange*, std::vector<TileOutput<3>>);

}  // namespace lsr::detail
