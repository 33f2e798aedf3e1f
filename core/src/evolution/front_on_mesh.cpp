// SPDX-License-Identifier: BSD-3-Clause
/// @file front_on_mesh.cpp
#include "evolution/front_on_mesh.h"

#include "evolution/drives.h"
#include "evolution/evolution_settings.h"
#include "evolution/front_evolution.h"
#include "evolution/pinning.h"
#include "evolution/renormalization.h"
#include "mesh/vertices_near.h"
#include "start/occupancy_start.h"
#include "start/start_fields.h"

namespace lsr::detail {

namespace {

// Per point, whether it lies in the closed box `region` (lower and upper corners); empty without one.
template <int D>
std::vector<char> inside_region(const Points<D>& points, const std::array<Vec<D>, 2>* region) {
  std::vector<char> inside;
  if (region == nullptr) return inside;
  inside.reserve(points.size());
  for (const Vec<D>& x : points) inside.push_back(in_closed_box<D>(x, (*region)[0], (*region)[1]));
  return inside;
}

// The mesh's edge graph and the P1 operators of the scheme, into f.
template <int D>
void assemble_operators(const SimplexMesh<D>& mesh, const ReconstructionOptions& o, FrontOnMesh<D>& f) {
  const bool reference = o.evolution.solver == LinearSolver::gmres_reference;
  const SimplexGeometry<D> geometry = compute_simplex_geometry(mesh, reference);
  f.neighbours = vertex_neighbours(mesh, geometry, o.limits.threads);
  f.ops = assemble_p1_operators(mesh, geometry, reference, &f.neighbours, o.limits.threads);
}

// The scheme's settings as the result reports them (the tolerance in input units).
template <int D>
void report_settings(const EvolutionSettings& settings, double box_scale, ReconstructionResult<D>& r) {
  r.time_step = settings.step.time_step;
  r.alpha = settings.step.alpha;
  r.curvature_weight = settings.step.curvature_weight;
  r.tolerance = settings.median_eps / box_scale;
}

}  // namespace

template <int D>
FrontOnMesh<D> front_on_mesh(const SampledData<D>& sampled, const std::vector<double>& point_scale, AdaptiveMesh<D>& adaptive,
                             const ReconstructionOptions& o, double hole_radius, const SignedDistance<D>* custom_start,
                             ReconstructionResult<D>& r, const Progress& progress, StageClock& clock,
                             const std::array<Vec<D>, 2>* tested) {
  const NearestPointIndex<D>& data = sampled.data;
  const LocalSampling<D>& sampling = sampled.sampling;
  const UnitBoxTransform<D>& box = sampled.box;
  const SimplexMesh<D>& mesh = adaptive.mesh;
  FrontOnMesh<D> f;

  // 5. The distance d at the vertices, each vertex's scale, each point's place in the mesh.
  progress.update("distance", -1.0);
  f.at_vertex = vertex_fields(data, mesh, sampling, point_scale, o.limits.threads);
  const VertexFields<D>& at_vertex = f.at_vertex;
  const Eigen::VectorXd& scale = at_vertex.scale;
  const std::vector<double>& dist = at_vertex.dist;
  const VertexCells cells = pin_cells(scale, data.points().size(), dist, at_vertex.nearest, o.evolution.pin_factor);
  f.at = o.mesh.anisotropic ? locate_all(mesh, data.points(), o.limits.threads) : locate_all(adaptive, data.points(), o.limits.threads);
  release_forest(adaptive);  // its last use: a third of the peak at 200k points
  clock.end("distance");

  // 6. The P1 operators of the scheme.
  progress.update("operators", -1.0);
  assemble_operators(mesh, o, f);
  clock.end("operators");

  // 7. The settings, the attraction (spanned holes included) and u0.
  progress.update("setup", -1.0);
  const EvolutionSettings settings = resolve_evolution_settings(
      o, scale, at_vertex.noise, point_scale, sampled.spacing,
      (o.start.initial_front != InitialFront::tagged && o.start.initial_front != InitialFront::occupancy) || custom_start);
  report_settings(settings, box.scale(), r);
  f.band = settings.schedule.band;
  // In 3D only the rim points carry discs (LocalSampling::rim); in 2D every point does.
  Attraction attract = attraction(data, sampling, mesh, dist, at_vertex.distance, scale, o.sampling.gap_factor, hole_radius, D == 3, o.limits.threads);
  const OpenSideInputs<D> open{data, sampling.normals, point_scale, dist, at_vertex.nearest};
  const StartField<D> start = start_field(mesh, f.neighbours, data, sampling, attract.d, at_vertex.distance, dist, scale, o, hole_radius,
                                          settings.schedule.band, r.h_min, custom_start, box, &open);
  r.sealed_cavities = start.sealed_cavities;
  r.open_side_points = start.held.empty() ? 0 : start.open_side_points;
  r.tagged_start = start.tagged;
  clock.end("setup");
  // Within a hole's radius of a vertex over it; empty without spanned holes.
  std::vector<char> near_hole = attract.over_hole.empty() ? std::vector<char>() : near_any(mesh.vertices, attract.over_hole, hole_radius, o.limits.threads);
  f.near_opening = start.near_opening;
  close_pocket(start, attract.d, near_hole, f.near_opening);
  // From the occupancy start the drive takes its side from the occupancy: alpha d (1 - 2w) moves
  // the front inwards where w < 1/2 and outwards where w > 1/2, at the data's attraction, and
  // vanishes on the data (d = 0) and, where the data are silent (an unseen underside, a gap
  // between scan lines), on the occupancy's boundary (w = 1/2), where the start put it.
  if (start.occupancy.size() > 0) attract.d = attract.d.cwiseProduct(2.0 * start.occupancy);
  const Points<D> away = o.evolution.two_sided || settings.schedule.rest_past_data ? away_from_data(data, mesh, at_vertex) : Points<D>();

  // 8. The time loop: the front evolves to the data; the best iterate is kept.
  const std::vector<char> tested_points = inside_region(data.points(), tested);
  const std::vector<char> tested_vertices = inside_region(mesh.vertices, tested);
  const FrontProblem<D> problem{mesh,         f.neighbours,         f.ops, f.at,          cells,
                                settings.eps, settings.reach,       settings.front_tolerance,
                                scale,        dist,                 away,  near_hole,     sampled.left_out.represented,
                                tested_points, tested_vertices};
  FrontEvolution<D> evolution(problem, o, settings.schedule, settings.step);
  // A start across the data can leave a pair of sheets over a gap of the data (the caps of a
  // sphere through a torus's tube, over its hole): there the two-sided drive points along the
  // sheets and vanishes, and they stall apart. The front cannot say which side is inside either:
  // it reaches the data from the side the start was on. The data's own occupancy, their
  // winding number with consistent outward normals, decides it once, everywhere
  // (occupancy_start.h), and the loop goes on from there. Not in a tile: the winding number
  // needs the whole cloud.
  typename FrontEvolution<D>::Restart restart;
  if (o.evolution.two_sided && !tested) {
    restart = [&] {
      Eigen::VectorXd u = occupancy_start(mesh.vertices, data, sampling.normals, sampling.noise, point_scale, o.limits.threads);
      renormalize(mesh, f.neighbours, u, settings.schedule.band, o.limits.threads);
      return u;
    };
  }
  evolution.run(start.u, attract.d, r, progress, clock, settings.median_eps, box.scale(), restart);
  r.residual = evolution.best_residual() * settings.median_eps / box.scale();
  f.best = std::move(evolution.best());
  f.best_is_distance = evolution.best_is_distance();
  f.over_hole = std::move(attract.over_hole);
  return f;
}

template FrontOnMesh<2> front_on_mesh<2>(const SampledData<2>&, const std::vector<double>&, AdaptiveMesh<2>&, const ReconstructionOptions&,
                                         double, const SignedDistance<2>*, ReconstructionResult<2>&, const Progress&, StageClock&,
                                         const std::array<Vec<2>, 2>*);
template FrontOnMesh<3> front_on_mesh<3>(const SampledData<3>&, const std::vector<double>&, AdaptiveMesh<3>&, const ReconstructionOptions&,
                                         double, const SignedDistance<3>*, ReconstructionResult<3>&, const Progress&, StageClock&,
                                         const std::array<Vec<3>, 2>*);

}  // namespace lsr::detail
