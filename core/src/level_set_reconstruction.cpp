// SPDX-License-Identifier: BSD-3-Clause
/// @file level_set_reconstruction.cpp
/// @brief The pipeline of the paper's figure 2, stage by stage (core/src/<stage>/, see
/// docs/how-it-works.md): data -> sampling -> mesh -> distance -> operators -> u0 -> time loop
/// -> fitted surface -> back to input coordinates.
#include "lsrecon/core/level_set_reconstruction.h"

#include "evolution/front_on_mesh.h"
#include "evolution/renormalization.h"
#include "evolution/stopping_test.h"
#include "fit/fitted_surface.h"
#include "limits/memory_budget.h"
#include "limits/option_checks.h"
#include "mesh/data_mesh.h"
#include "sampling/data_preparation.h"
#include "sampling/mesh_resolution_data.h"
#include "sampling/sampled_data.h"
#include "stage_clock.h"
#include "surface/closed_surface.h"
#include "surface/embedded_moves.h"
#include "surface/facet_normals.h"
#include "surface/unsupported_parts.h"
#include "tiles/tiled_solve.h"

namespace lsr {
namespace {

using namespace detail;

// 4-9 on one mesh. Returns the surface's vertices as extracted (embedded): the fit moves them.
template <int D>
Points<D> surface_on_one_mesh(SampledData<D>& sampled, const ReconstructionOptions& o, double hole_radius, Index max_vertices,
                         const SignedDistance<D>* custom_start, ReconstructionResult<D>& r, const Progress& progress, StageClock& clock) {
  const DataPoints<D>& in = sampled.in;
  const UnitBoxTransform<D>& box = sampled.box;
  const NearestPointIndex<D>& data = sampled.data;
  const LocalSampling<D>& sampling = sampled.sampling;
  std::vector<double>& point_scale = sampled.point_scale;  // raised where the mesh cannot resolve it
  const bool anisotropic = o.mesh.anisotropic;

  // 4. The mesh, fine near the data, coarse away from it; anisotropic, long along flat data.
  AdaptiveMesh<D> adaptive;
  if (anisotropic) {
    adaptive.mesh = anisotropic_data_mesh(data, sampling, point_scale, o, max_vertices, progress, r.h_min);
  } else {
    adaptive = data_mesh(data, point_scale, o, max_vertices, progress, r.h_min);
  }
  const SimplexMesh<D>& mesh = adaptive.mesh;
  r.mesh_vertices = Index(mesh.vertices.size());
  r.mesh_simplices = Index(mesh.simplices.size());
  clock.end("mesh");

  // 5-8. The distance at the vertices, the operators, u0 and the time loop; the best iterate.
  FrontOnMesh<D> front = front_on_mesh(sampled, point_scale, adaptive, o, hole_radius, custom_start, r, progress, clock);
  Eigen::VectorXd& best = front.best;
  const VertexFields<D>& at_vertex = front.at_vertex;
  const Eigen::VectorXd& scale = at_vertex.scale;

  // 9. The input's normals, then the surface: the fit through the data, or the front itself.
  const Points<D> normals = oriented_normals(sampling, front.at, front.ops.gradient_times(best));
  if (!in.kept.empty()) r.point_normals = in.input_normals(every_point_normals(sampled.left_out, normals), r.input_points);
  progress.update(o.output.fit_surface ? "fit" : "extract", -1.0);
  if (o.output.fit_surface) {
    // The fit's band is measured in distances to the front: the best iterate as one.
    if (!front.best_is_distance) renormalize(mesh, front.neighbours, best, front.band, o.limits.threads);
    front.ops = P1Operators<D>();  // done with G: the fit's index and blends reuse its memory (the peak)
    const QuadricImplicit<D> fit = fit_quadrics(data, normals, point_scale, o.limits.threads, progress);
    const FrontToFit<D> to_fit{mesh, front.neighbours, best, scale, at_vertex.distance, front.over_hole, front.near_opening,
                               data, normals, o.sampling.gap_factor, o.limits.threads};
    Points<D> extracted = attach_fit(r, to_fit, fit, o.output.volume_mesh);
    if (anisotropic && !o.output.volume_mesh) refine_onto_fit(r, fit, scale, at_vertex.distance, extracted, o.limits.threads);
    clock.end("fit");
    return extracted;
  }
  r.output_level = o.output.level_through_data ? median_on_data(front.at, best) / box.scale() : 0.0;
  attach_front(r, mesh, front.ops, best, r.output_level * box.scale(), data.points(), o.output.volume_mesh, o.limits.threads);
  clock.end("extract");
  return r.surface.vertices;
}

// 4-9 in tiles (tiles/tiled_solve.h): the tiles' fields welded (each tile's fitted field, or
// its front at the level through the data), the pieces no sample supports dropped; with the
// fit, the vertices projected onto the whole sample's fit. Returns the vertices as welded.
template <int D>
Points<D> surface_in_tiles(SampledData<D>& sampled, const ReconstructionOptions& o, double hole_radius, Index max_vertices,
                      const SignedDistance<D>* custom_start, ReconstructionResult<D>& r, const Progress& progress, StageClock& clock) {
  // Each point's scale raised to its mesh size, as one mesh does (data_mesh.h).
  const std::vector<double> size = local_mesh_sizes<D>(sampled.point_scale, o.mesh.h_min, o.mesh.max_resolution);
  for (std::size_t i = 0; i < size.size(); ++i) sampled.point_scale[i] = std::max(sampled.point_scale[i], size[i]);
  TiledFront<D> tiled = solve_in_tiles(sampled, o, hole_radius, max_vertices, custom_start, r, progress, clock);
  if (r.status == ReconstructionStatus::cancelled || r.status == ReconstructionStatus::shared) return {};  // or another worker's
  if (!sampled.in.kept.empty()) r.point_normals = sampled.in.input_normals(every_point_normals(sampled.left_out, tiled.normals), r.input_points);
  r.surface = std::move(tiled.surface);
  drop_unsupported_pieces(r.surface, sampled.data.points(), o.limits.threads);
  const Points<D> welded = r.surface.vertices;
  if (o.output.fit_surface) {
    progress.update("fit", -1.0);
    const QuadricImplicit<D> fit = fit_quadrics(sampled.data, tiled.normals, sampled.point_scale, o.limits.threads, progress);
    // A vertex's scale: its nearest sample's.
    LargeVector<Index> nearest;
    sampled.data.query_k(r.surface.vertices, 1, nearest, o.limits.threads);
    std::vector<double> vertex_scale(r.surface.vertices.size());
    for (std::size_t i = 0; i < vertex_scale.size(); ++i) vertex_scale[i] = sampled.point_scale[std::size_t(nearest[i])];
    project_onto_fit(r, fit, {}, vertex_scale, sampled.data, o.limits.threads);
    clock.end("fit");
  } else {
    r.output_level = tiled.level / sampled.box.scale();
    r.normals.assign(r.surface.vertices.size(), Vec<D>::Zero());
    set_facet_normals(r.surface, std::vector<char>(r.surface.vertices.size(), 1), r.normals);
  }
  return welded;
}

template <int D>
ReconstructionResult<D> run_pipeline(const Points<D>& input, const ReconstructionOptions& given,
                                     const ProgressCallback& callback, const SignedDistance<D>* custom_start) {
  check_options(given);
  // Before anything is allocated for the points.
  if (given.limits.max_vertices <= 0) require_cloud_fits<D>(given, input.size());
  ReconstructionResult<D> r;
  StageClock clock(r.seconds, r.stages);
  const Progress progress(callback);

  // 1-3. The data, normalised: distinct finite points in the unit box, along a Z-order curve;
  // its local sampling: spacing, noise, normals, rims; isolated points left out. Where the data
  // are denser than the mesh resolves, the rest reads a sample at its size.
  progress.update("unit box", -1.0);
  r.input_points = input.size();
  // In 3D only the rim points carry discs (LocalSampling::rim); in 2D, where spanning is off
  // unless asked for, every point does.
  const bool rims_only = D == 3;
  // The anisotropic mesh needs every point's curvature (its height field); the rims are still
  // found for the discs.
  const bool anisotropic = given.mesh.anisotropic;
  const double given_radius = given.sampling.hole_radius;  // its unit does not change its sign
  const bool spans = given_radius > 0.0 || (given_radius < 0.0 && automatic_defaults(D).hole_radius > 0.0);
  const HeightFieldsAt spanning = !spans ? HeightFieldsAt::none : rims_only ? HeightFieldsAt::rims : HeightFieldsAt::all;
  const HeightFieldsAt fields = !anisotropic                       ? spanning
                                : spanning == HeightFieldsAt::rims ? HeightFieldsAt::all_and_rims
                                                                   : HeightFieldsAt::all;
  std::optional<SampledData<D>> sampled;
  if (given.limits.exchange && given.limits.exchange->workers() > 1) {
    if constexpr (D == 3) sampled = shared_sampled_data(input, given, fields, progress, r, clock);
    if constexpr (D == 2) throw InvalidInput("curves are reconstructed in one process", "reconstruct 2D clouds without workers");
  } else {
    sampled = sampled_data(input, given, fields, progress, r, clock);
  }
  clock.end("sampling");
  if (!sampled) {
    r.status = ReconstructionStatus::shared;  // worker 0 carries on alone
    return r;
  }
  const UnitBoxTransform<D>& box = sampled->box;
  const ReconstructionOptions o = in_unit_box(given, box.scale());
  const double hole_radius = o.sampling.hole_radius >= 0.0 ? o.sampling.hole_radius : automatic_defaults(D).hole_radius;
  r.noise = sampled->noise / box.scale();
  r.scan_lines = sampled->sampling.scan_lines;
  r.spacing = sampled->spacing / box.scale();

  // 4-9. The mesh, the front on it and the surface; or the same in tiles.
  const Index max_vertices =
      o.limits.max_vertices > 0 ? o.limits.max_vertices : memory_limited_vertices<D>(o, input.size(), sampled->data.points().size());
  Points<D> embedded = o.limits.solve_tiles > 1 ? surface_in_tiles(*sampled, o, hole_radius, max_vertices, custom_start, r, progress, clock)
                                                 : surface_on_one_mesh(*sampled, o, hole_radius, max_vertices, custom_start, r, progress, clock);

  // 10. Back to the input's coordinates.
  for (auto& x : r.surface.vertices) x = box.from_unit(x);
  for (auto& x : embedded) x = box.from_unit(x);
  for (auto& x : r.volume.vertices) x = box.from_unit(x);

  // 11. The moves since the extraction kept embedded, as written: on floats where rounding to
  // them moves vertices less than the extraction places them.
  progress.update("embed", -1.0);
  const bool float_grid = float_grid_is_finer(r.surface.vertices, kOutputEdgeMargin * r.h_min / box.scale());
  keep_embedded(r.surface, std::move(embedded), float_grid, r.normals, o.limits.threads);
  for (std::size_t i = 0; i < r.surface.vertices.size() && !r.volume.vertices.empty(); ++i) {
    r.volume.vertices[std::size_t(r.volume.interface_offset) + i] = r.surface.vertices[i];
  }
  clock.end("embed");

  // 12. How far each vertex lies from the data: large where the surface is a guess.
  sampled->data.query(box.to_unit(r.surface.vertices), r.distance_to_data, nullptr, o.limits.threads);
  for (double& d : r.distance_to_data) d /= box.scale();
  if constexpr (D == 2) r.loops = closed_loops(r.surface);
  return r;
}

// Cancellation outside the time loop (which keeps its best iterate) leaves an empty result.
template <int D>
ReconstructionResult<D> cancellable_pipeline(const Points<D>& input, const ReconstructionOptions& o,
                                             const ProgressCallback& callback, const SignedDistance<D>* custom_start) {
  try {
    return run_pipeline<D>(input, o, callback, custom_start);
  } catch (const Cancelled&) {
    ReconstructionResult<D> r;
    r.status = ReconstructionStatus::cancelled;
    r.input_points = input.size();
    return r;
  }
}

}  // namespace

template <int D>
ReconstructionResult<D> reconstruct(const Points<D>& points, const ReconstructionOptions& options,
                                    const ProgressCallback& progress) {
  return cancellable_pipeline<D>(points, options, progress, nullptr);
}

template <int D>
ReconstructionResult<D> reconstruct_from(const Points<D>& points, const SignedDistance<D>& initial,
                                         const ReconstructionOptions& options, const ProgressCallback& progress) {
  if (options.evolution.alpha == 0.0 && !options.evolution.two_sided) {
    throw InvalidInput("a custom start needs an explicit alpha, or two-sided attraction",
                       "set alpha > 0 (e.g. 2) if the start encloses the data, < 0 (e.g. -2) if it lies inside, "
                       "or two_sided if it crosses the data");
  }
  ReconstructionOptions o = options;
  o.start.initial_front = options.evolution.alpha >= 0.0 ? InitialFront::enclosing : InitialFront::inside;
  return cancellable_pipeline<D>(points, o, progress, &initial);
}

template ReconstructionResult<2> reconstruct_from<2>(const Points<2>&, const SignedDistance<2>&, const ReconstructionOptions&, const ProgressCallback&);
template ReconstructionResult<3> reconstruct_from<3>(const Points<3>&, const SignedDistance<3>&, const ReconstructionOptions&, const ProgressCallback&);
template ReconstructionResult<2> reconstruct<2>(const Points<2>&, const ReconstructionOptions&, const ProgressCallback&);
template ReconstructionResult<3> reconstruct<3>(const Points<3>&, const ReconstructionOptions&, const ProgressCallback&);

}  // namespace lsr
