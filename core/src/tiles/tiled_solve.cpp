// SPDX-License-Identifier: BSD-3-Clause
/// @file tiled_solve.cpp
#include "tiles/tiled_solve.h"

#include "evolution/front_on_mesh.h"
#include "evolution/renormalization.h"
#include "fit/fitted_field.h"
#include "fit/fitted_surface.h"
#include "geometry/coordinate_hash.h"
#include "mesh/data_mesh.h"
#include "mesh/tile_core.h"
#include "sampling/local_sampling.h"
#include "sampling/worker_collectives.h"
#include "start/outside_flood_fill.h"
#include "surface/closed_surface.h"
#include "surface/stitched_extraction.h"
#include "tiles/tile_outputs.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <unordered_map>

namespace lsr::detail {
namespace {

// Beyond its region a tile's mesh follows the data at this size, which is what carries the
// inside/outside decision of the whole box to its own flood: the coarsest finest size
// quartered (1/128 in 3D; calibrated).
template <int D>
constexpr double kCoarseSize = automatic_defaults(D).coarsest_finest_size / 4.0;

template <int D>
bool in_box(const Vec<D>& x, const Vec<D>& lo, const Vec<D>& hi) {
  return ((x - lo).array() >= 0.0).all() && ((hi - x).array() > 0.0).all();
}

template <int D>
std::array<double, D> key_of(const Vec<D>& x) {
  std::array<double, D> k;
  std::copy_n(x.data(), D, k.begin());
  return k;
}

template <int D>
TileField<D> field_on(const TileCore<D>& part, const Eigen::VectorXd& u) {
  TileField<D> f{part.mesh, std::vector<double>(part.vertex.size())};
  for (std::size_t i = 0; i < part.vertex.size(); ++i) f.u[i] = u[part.vertex[i]];
  return f;
}

// The level through the data lies within this many median scales of 0 (the stopping test's
// tolerance is one scale at every point), or the front is extracted at 0.
constexpr double kLevelWindow = 4.0;

// Seam vertices by their coordinates' bits: the tiles' meshes share them exactly.
template <int D>
using SeamValues = std::unordered_map<std::array<double, D>, double, CoordinateHash<std::size_t(D)>>;

// The tile's core simplices that a level within `window` of 0 may cross (u is a distance
// there), and into `seam`, the values of its own vertices that simplices outside its core use
// (the other tiles' seam layers).
template <int D>
TileField<D> core_shell(const SimplexMesh<D>& mesh, const Eigen::VectorXd& u, const TileBox<D>& box, double window,
                        std::vector<SeamValue<D>>& seam) {
  std::vector<char> kept(mesh.simplices.size(), 0), in_seam(mesh.vertices.size(), 0);
  for (std::size_t s = 0; s < mesh.simplices.size(); ++s) {
    Vec<D> c = Vec<D>::Zero();
    double lowest = std::numeric_limits<double>::infinity(), highest = -lowest;
    for (Index v : mesh.simplices[s]) {
      c += mesh.vertices[std::size_t(v)];
      lowest = std::min(lowest, u[v]), highest = std::max(highest, u[v]);
    }
    c /= double(D + 1);
    if (in_box<D>(c, box.lo, box.hi)) {
      // Its seam layer whatever its own values: the owners' may cross the level.
      bool all_owned = true;
      for (Index v : mesh.simplices[s]) all_owned = all_owned && in_box<D>(mesh.vertices[std::size_t(v)], box.lo, box.hi);
      kept[s] = !all_owned || (lowest <= window && highest >= -window);
      continue;
    }
    for (Index v : mesh.simplices[s]) in_seam[std::size_t(v)] = in_box<D>(mesh.vertices[std::size_t(v)], box.lo, box.hi);
  }
  for (std::size_t v = 0; v < in_seam.size(); ++v) {
    if (in_seam[v]) seam.push_back({key_of<D>(mesh.vertices[v]), u[Eigen::Index(v)]});
  }
  return field_on<D>(select_simplices<D>(mesh, kept), u);
}

// The fit's field (fit/fitted_field.h) over the tile's region, from the blended quadrics of the
// points within a margin of it, oriented by the tile's front; u beyond the region.
template <int D>
std::vector<double> tile_fitted_field(const SampledData<D>& sampled, const Points<D>& normals, const FrontOnMesh<D>& front,
                                      const SimplexMesh<D>& mesh, const TileBox<D>& box, double margin, const ReconstructionOptions& o) {
  const Points<D>& points = sampled.data.points();
  const Vec<D> lo = box.region_lo.array() - margin, hi = box.region_hi.array() + margin;
  Points<D> near, near_normals;
  std::vector<double> near_scale;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!in_closed_box<D>(points[i], lo, hi)) continue;
    near.push_back(points[i]);
    near_normals.push_back(normals[i]);
    near_scale.push_back(sampled.point_scale[i]);
  }
  std::vector<char> fitted(mesh.vertices.size());
  for (std::size_t v = 0; v < fitted.size(); ++v) fitted[v] = in_closed_box<D>(mesh.vertices[v], box.region_lo, box.region_hi);
  const NearestPointIndex<D> index(std::move(near));
  const QuadricImplicit<D> fit = fit_quadrics(index, near_normals, near_scale, o.limits.threads);
  const FrontToFit<D> to_fit{mesh,         front.neighbours, front.best, front.at_vertex.scale, front.at_vertex.distance, front.over_hole,
                             front.near_opening, sampled.data, normals,   o.sampling.gap_factor, o.limits.threads};
  return fitted_field(to_fit, fit, fitted).values;
}

template <int D>
int tile_count(int k) {
  int tiles = 1;
  for (int a = 0; a < D; ++a) tiles *= k;
  return tiles;
}

// The background cells shrink with the tiles, and a tile's mesh equals the whole mesh in its
// core once its region reaches two of them past it (mesh/tile_core.h).
template <int D>
ReconstructionOptions tile_options(const ReconstructionOptions& o) {
  ReconstructionOptions to = o;
  to.mesh.h_max = std::min(o.mesh.h_max, 1.0 / (8.0 * o.limits.solve_tiles));
  return to;
}

// Tile t alone: its mesh, its front, with the fit its fitted field; what it gives the weld.
template <int D>
TileOutput<D> solve_tile(int t, const SampledData<D>& sampled, const ReconstructionOptions& o, double hole_radius, Index max_vertices,
                         const SignedDistance<D>* custom_start, const Progress& progress, StageClock& clock) {
  const int k = o.limits.solve_tiles;
  const ReconstructionOptions to = tile_options<D>(o);
  const double margin = 2.0 * to.mesh.h_max;
  const Points<D>& points = sampled.data.points();
  const TileBox<D> box = tile_box<D>(t, k, margin);
  const std::string name = "tile " + std::to_string(t + 1) + "/" + std::to_string(tile_count<D>(k)) + " ";
  const Progress tile_progress([&](const std::string& stage, double fraction) {
    progress.update(name + stage, fraction);
    return true;
  });
  std::vector<double> scale = sampled.point_scale;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!in_closed_box<D>(points[i], box.region_lo, box.region_hi)) scale[i] = std::max(scale[i], kCoarseSize<D>);
  }
  ReconstructionResult<D> tr;
  AdaptiveMesh<D> adaptive = data_mesh(sampled.data, scale, to, max_vertices, tile_progress, tr.h_min);
  tr.mesh_vertices = Index(adaptive.mesh.vertices.size());
  tr.mesh_simplices = Index(adaptive.mesh.simplices.size());
  clock.end("mesh");
  // Its stopping test reads its core and half its margin: not the coarse part, whose front is
  // other tiles' to place, nor the fine front next to it, which the coarse one holds back; not
  // its core alone either: the front it keeps must have settled where its neighbours' fronts
  // meet it.
  const TileBox<D> tested = tile_box<D>(t, k, margin / 2.0);
  const std::array<Vec<D>, 2> region{tested.region_lo, tested.region_hi};
  FrontOnMesh<D> front = front_on_mesh(sampled, scale, adaptive, to, hole_radius, custom_start, tr, tile_progress, clock, &region);
  TileOutput<D> out;
  out.summary = tile_summary(tr, t);
  if (tr.status == ReconstructionStatus::cancelled) return out;
  const SimplexMesh<D>& mesh = adaptive.mesh;
  Eigen::VectorXd& u = front.best;

  // The data points it owns take their normals and values from its front.
  const Points<D> normals = oriented_normals(sampled.sampling, front.at, front.ops.gradient_times(u));
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!in_box<D>(points[i], box.lo, box.hi)) continue;
    out.normals.push_back(normals[i]);
    double value = 0.0;
    for (int j = 0; j <= D; ++j) value += front.at[i].weights[j] * u[front.at[i].vertices[j]];
    out.on_data.push_back(value);
  }
  if (o.output.fit_surface) {
    // The fit's field in its region, from a fit of the points near it with its own normals.
    if (!front.best_is_distance) renormalize(mesh, front.neighbours, u, front.band, o.limits.threads);
    front.ops = P1Operators<D>();
    u = Eigen::Map<const Eigen::VectorXd>(tile_fitted_field(sampled, normals, front, mesh, box, margin, o).data(), u.size());
  }
  out.shell = core_shell<D>(mesh, u, box, kLevelWindow * median(sampled.point_scale), out.seam);
  out.summary.owned_points = out.normals.size();
  out.summary.seam_vertices = out.seam.size();
  out.summary.shell_vertices = out.shell.u.size();
  out.summary.shell_simplices = out.shell.core.simplices.size();
  return out;
}

}  // namespace

template <int D>
TileBox<D> tile_box(int t, int k, double margin) {
  TileBox<D> b;
  for (int a = 0; a < D; ++a, t /= k) {
    const int i = t % k;
    b.lo[a] = double(i) / k;
    b.hi[a] = i + 1 == k ? 2.0 : double(i + 1) / k;
    b.region_lo[a] = std::max(0.0, b.lo[a] - margin);
    b.region_hi[a] = std::min(1.0, b.hi[a] + margin);
  }
  return b;
}

template <int D>
TiledFront<D> solve_in_tiles(const SampledData<D>& sampled, const ReconstructionOptions& o, double hole_radius, Index max_vertices,
                             const SignedDistance<D>* custom_start, ReconstructionResult<D>& r, const Progress& progress, StageClock& clock) {
  const int k = o.limits.solve_tiles, tiles = tile_count<D>(k);
  // Each worker solves every workers()-th tile; worker 0 welds them.
  const TileExchange* x = o.limits.exchange.get();
  std::vector<TileOutput<D>> solved;
  for (int t = int(worker_of(x)); t < tiles; t += int(workers_of(x))) {
    solved.push_back(solve_tile(t, sampled, o, hole_radius, max_vertices, custom_start, progress, clock));
    if (solved.back().summary.status == ReconstructionStatus::cancelled) break;
  }
  solved = gather_tile_outputs<D>(x, std::move(solved));
  if (worker_of(x) != 0) {
    r.status = ReconstructionStatus::shared;
    return TiledFront<D>();
  }

  // The values of the seam vertices each tile owns; the core simplices near each tile's front
  // (those that read another tile's values: its seam layer), extracted once every tile is
  // solved, at the level through the data if asked (one level for all, or the seams would
  // open); u at the data points, each from its owner.
  const Points<D>& points = sampled.data.points();
  const double margin = 2.0 * tile_options<D>(o).mesh.h_max;
  TiledFront<D> out;
  out.normals.assign(points.size(), Vec<D>::Zero());
  SeamValues<D> seam_value;
  std::vector<double> on_data;
  on_data.reserve(points.size());
  for (std::size_t i = 0; i < solved.size(); ++i) {
    TileOutput<D>& t = solved[i];
    add_tile_summary(r, t.summary, i == 0);
    if (t.summary.status == ReconstructionStatus::cancelled) return TiledFront<D>();
    const TileBox<D> box = tile_box<D>(t.summary.tile, k, margin);
    for (std::size_t p = 0, j = 0; p < points.size(); ++p) {
      if (in_box<D>(points[p], box.lo, box.hi)) out.normals[p] = t.normals[j++];
    }
    on_data.insert(on_data.end(), t.on_data.begin(), t.on_data.end());
    for (const SeamValue<D>& v : t.seam) seam_value[v.x] = v.u;
    t.normals = Points<D>(), t.on_data = {}, t.seam = {};
  }
  progress.update("extract", -1.0);
  // With the fit, its zero set (as on one mesh).
  const double window = kLevelWindow * median(sampled.point_scale);
  out.level = !o.output.fit_surface && o.output.level_through_data && !on_data.empty() ? median(on_data) : 0.0;
  if (std::abs(out.level) >= window) out.level = 0.0;  // a front far from its data: its own level
  StitchedSurface<D> stitched(kOutputEdgeMargin, o.limits.threads);
  for (TileOutput<D>& t : solved) {
    const TileBox<D> box = tile_box<D>(t.summary.tile, k, margin);
    TileField<D>& field = t.shell;
    for (std::size_t i = 0; i < field.u.size(); ++i) {
      const Vec<D>& x = field.core.vertices[i];
      if (!in_box<D>(x, box.lo, box.hi)) {
        const auto it = seam_value.find(key_of<D>(x));
        if (it == seam_value.end()) {
          ++out.seam_mismatches;
        } else {
          field.u[i] = it->second;
        }
      }
      field.u[i] -= out.level;
      if (on_wall<D>(x)) field.u[i] = std::max(field.u[i], std::numeric_limits<double>::min());
    }
    stitched.add(field);
    field = TileField<D>();
  }
  clock.end("extract");
  out.surface = stitched.take();
  return out;
}

template TileBox<2> tile_box<2>(int, int, double);
template TileBox<3> tile_box<3>(int, int, double);
template TiledFront<2> solve_in_tiles<2>(const SampledData<2>&, const ReconstructionOptions&, double, Index,
                                         const SignedDistance<2>*, ReconstructionResult<2>&,
                                         const Progress&, StageClock&);
template TiledFront<3> solve_in_tiles<3>(const SampledData<3>&, const ReconstructionOptions&, double, Index,
                                         const SignedDistance<3>*, ReconstructionResult<3>&,
                                         const Progress&, StageClock&);

}  // namespace lsr::detail
