// SPDX-License-Identifier: BSD-3-Clause
/// @file reconstruction_options.h
/// @brief The parameters of reconstruct(), in the order of the pipeline's stages: the data,
/// the mesh, the start, the evolution, the stopping test, the output, the limits.
///
/// Lengths are relative to the unit box the data is mapped into (the data's bounding ball
/// becomes a ball of radius 0.4), or in the input's units (ReconstructionOptions::lengths); 0 (or a negative value where 0 has a meaning) means "choose
/// from the data". Local scales (docs/how-it-works.md): s_i is the sampling spacing at data
/// point i, and a mesh vertex takes the s of its nearest data point. From s: the mesh size near
/// the data (max(s, 1.5 noise)), the tagging distance and the front's tolerance between samples
/// (gap_factor s), the radius over which a reached point holds the front (pin_factor s), the
/// curvature weight (beta = |alpha| curvature_factor s^2) and the stopping tolerance
/// (tolerance_factor s). A front spanning a gap of radius r between samples is held there when
/// beta (D - 1) / r >= alpha d ~ alpha r, i.e. r <= sqrt((D - 1) curvature_factor) s; beyond,
/// only the pinned cells of radius pin_factor s hold it.
#pragma once

#include "lsrecon/core/types.h"
#include "lsrecon/core/tile_exchange.h"

#include <memory>

namespace lsr {

/// @brief The unit of the lengths a user sets (ReconstructionOptions::lengths).
enum class LengthUnit {
  unit_box,  ///< the unit box the data's bounding ball is mapped into (radius 0.4)
  input,     ///< the input's coordinates, converted once the unit box is known
};

/// @brief Where the front starts.
enum class InitialFront {
  /// The boundary of the region reachable from the box walls without coming closer to the data
  /// than gap_factor local spacings; alpha > 0. It already has the topology the sampling
  /// resolves, and the front only closes the last gap (default).
  tagged,
  enclosing,  ///< a circle / sphere around all the data; alpha > 0 (the front shrinks)
  inside,     ///< a circle / sphere around the data's centroid, inside the shape; alpha < 0
  /// where the data's generalised winding number, with their normals oriented outwards, is
  /// above 1/2: at the data already, closed across gaps; alpha > 0 (experimental)
  occupancy,
};

/// @brief The linear solver of the semi-implicit step.
enum class LinearSolver {
  conjugate_gradient,  ///< SPD form, matrix-free, Jacobi preconditioner (default)
  gmres_reference,     ///< the paper's (I - dt beta D M), assembled, Eigen's GMRES
};

/// @brief How the sampling reads a 3D cloud: as scan lines (dense along lines, 3-10 times
/// sparser across them) or as scattered samples.
enum class ScanLines {
  automatic,  ///< from the cloud (median elongation, narrow and wide normals disagreeing)
  yes,
  no
};

/// @brief What the data is like.
struct SamplingOptions {
  /// A point whose nearest distinct neighbour is farther than outlier_factor local spacings
  /// (the median spacing of its neighbourhood) is an isolated outlier and left out; 0 keeps
  /// every point. A scanner outlier left in is wrapped in a small closed bubble of its own (10
  /// outliers among 20k torus points gave 11 components; with a factor of 4, one outlier
  /// 3-4 spacings off the surface still pinched off; measured), which the output then drops
  /// as a part fewer than D + 1 samples support; its time and memory are spent, and a cluster
  /// of D + 1 outliers stays. On the test corpus (9 shapes; clean, noisy, 10x density, holes;
  /// 2k-200k points) the largest ratio of a genuine point is 2.5.
  double outlier_factor = 3.0;
  /// The largest sampling gap, in local spacings: the tagged start keeps this far from the data,
  /// and the front may lie this far from the data between samples. A random surface sample's
  /// largest empty disc is about 1.45 s at 2e5 points; 2 leaves a margin.
  double gap_factor = 2.0;
  /// Span sampling holes up to this radius (unit box), as Poisson does; 0: off; negative
  /// (default): automatic_defaults(D).hole_radius. The points on the rim of a hole (or of an
  /// open scan) carry tangent discs of this radius (at most their radius of curvature), bent to
  /// the quadric fitted to their neighbours: they stop the tagged start and attract the front
  /// beyond the gap of the data, so the rim continues over the hole, while close sheets and
  /// creases, which have no rim, are left as the points say (docs/how-it-works.md).
  double hole_radius = -1.0;
  /// 3D: scan lines or not. automatic decides on the whole cloud (docs/how-it-works.md: Scan
  /// lines); yes or no for a cloud it misreads, such as a piece cut from a larger scan or a
  /// scan merged with many scattered points. Read as scan lines, a point's spacing is at least
  /// the gap to the next line (ReconstructionResult::scan_lines says how it was read).
  ScanLines scan_lines = ScanLines::automatic;
};

/// @brief The adapted mesh (graded, isotropic, by Kuhn bisection).
struct MeshOptions {
  /// Finest mesh size; 0: local, max(s_i, 1.5 noise_i) near each point, clamped to
  /// [1 / max_resolution, automatic_defaults(D).coarsest_finest_size]. > 0: this size
  /// everywhere near the data.
  double h_min = 0.0;
  /// Cap on the local mesh resolution; 0: automatic_defaults(D).max_resolution. Sheets closer
  /// than about 2.4 / max_resolution are no longer told apart.
  double max_resolution = 0.0;
  double h_max = 1.0 / 8;  ///< coarsest mesh size
  /// Grading c: a simplex is refined while its size exceeds max(h_local, c * its distance to
  /// the data). Smaller c widens the fine band around the data; the default 2 keeps simplices
  /// of size h_min within about 2.7 h_min of the data. In (0, 100].
  double grading = 2.0;
  /// Adapts the mesh to the data's metric (the paper's anisotropic meshes, section 6.2): the
  /// sizes across the data stay the isotropic mesh's, along it they grow where it is flat, to
  /// sqrt(8 anisotropic_error h / kappa) (h the local size, kappa the curvature).
  bool anisotropic = false;
  /// The chord error allowed along the data, in units of the local mesh size (the stopping
  /// test allows it as well); in (0, 100].
  double anisotropic_error = 0.25;
};

/// @brief Where the front starts.
struct StartOptions {
  InitialFront initial_front = InitialFront::tagged;
  /// The tagged start moved this many local spacings towards the data (its distance function
  /// raised by start_offset s), in 3D. The flood stops gap_factor s from the data; over a
  /// random sample's largest empty disc (radius about 1.45 s) it dips to sqrt(gap_factor^2 -
  /// 1.45^2) s = 1.38 s above the surface, and 0.5 keeps the start 0.88 s clear of it. The
  /// front closes in like exp(-alpha t), so the last 0.5 s of 2 cost ln(4/3) / (|alpha| dt) = 1.4
  /// of its steps (measured on the 20k corpus: 1-4 fewer on every cloud without holes, the
  /// same surfaces). Not where sampling holes have rims: a flood that slips into a thin part
  /// past a hole's discs leaves bubbles inside it, and a start closer to them kept one
  /// (measured: the holey limb, a void 1.5 spacings wide). 0: the flood's boundary itself; in
  /// [0, gap_factor), and below gap_factor - 1.45 to stay clear of the gaps.
  double start_offset = 0.5;
};

/// @brief The time loop: du/dt = |grad u| (beta kappa(u) + alpha d(x)).
struct EvolutionOptions {
  double alpha = 0.0;  ///< attraction weight; 0: automatic_defaults(D).alpha from outside, minus it inside
  /// beta >= 0 everywhere, the smoothness knob; negative: local, |alpha| curvature_factor s^2,
  /// growing to |alpha| (curvature_factor + 2) s^2 as the local noise approaches s.
  double curvature_weight = -1.0;
  double curvature_factor = 0.25;  ///< see curvature_weight
  /// dt; 0: automatic_defaults(D).time_step_factor / |alpha|. The front closes in on the data
  /// like exp(-alpha t), and the explicit data term's CFL limit on the graded mesh (sizes ~ c d)
  /// is about c / alpha, so dt is a fraction of 1/alpha, independent of h_min.
  double time_step = 0.0;
  double pin_factor = 2.0;  ///< radius (in local spacings) of the cell a reached point pins
  /// Pin the front at data points it has reached (d := 0 on the vertices of their simplices
  /// and of their cells of radius pin_factor s, and those vertices held still: curvature would
  /// otherwise go on shrinking thin parts). The unsigned d never stops a front that
  /// reaches the data, and its P1 interpolant is O(h) at the data points, so converged parts
  /// would pass through the data while slower parts (holes, concavities) still travel.
  bool pin_reached_data = true;
  /// No drive (d := 0) where the front has passed its nearest data point (faces away from it)
  /// farther than gap_factor s from the data, except within a hole's radius of a spanned hole;
  /// curvature still acts there. Without it the one-sided term pulls such a front on inward:
  /// on 2 of 40 clean 20k draws it sank about 2.4 spacings into one of the widest empty discs,
  /// past the pinned cells, and the run stopped "not converged" (docs/how-it-works.md,
  /// Stopping). Ignored with two_sided.
  bool rest_past_data = true;
  /// Attract the front onto the data from both sides: the data term alpha d |grad u| becomes
  /// alpha d grad d . grad u (the convection towards the data of Zhao, Osher and Fedkiw 2001),
  /// so that a start partly inside and partly outside the shape (reconstruct_from) converges.
  /// Needs alpha >= 0 (0: automatic). Nothing is pinned (pin_reached_data is ignored): where
  /// the start crosses the data the front is on it from the first step, and pins would freeze
  /// it across the data; attraction from both sides holds it instead. The one-sided term stays
  /// the default: from outside both agree, and it also pulls fronts that face away from the data.
  bool two_sided = false;
  /// Renormalise every k steps; 0: as rarely as keeps |alpha| dt k <= 0.4, which is 2 at the
  /// default dt (half the dominant cost, same accuracy on sphere, torus and star) and 1 for
  /// large steps (at |alpha| dt = 0.78, k = 2 left islands; measured). At most
  /// StoppingOptions::patience: the stopping test measures the front at renormalisations.
  int renormalization_interval = 0;
  LinearSolver solver = LinearSolver::conjugate_gradient;
  double solver_tolerance = 1e-6;  ///< relative residual of each linear solve
};

/// @brief When the time loop stops.
struct StoppingOptions {
  /// eps of the stopping test |u(x_i)| <= eps_i at every data point; 0: tolerance_factor s_i.
  double tolerance = 0.0;
  /// See tolerance. The fit places the surface; the front only has to come within its trust
  /// zone (gap_factor s) of every point, and 1 s is reachable in concave creases.
  double tolerance_factor = 1.0;
  int max_iterations = 1000;
  /// Stalled fronts: stop after `patience` steps without a better residual, or when over the
  /// last `patience` steps the front moved less than stall_stillness local spacings on average
  /// while its best residual, or that of all but the worst 0.1% of the points, fell by less
  /// than the fraction stall_gain, or the best was already within near_residual tolerances
  /// (negative: exp(|alpha| dt), one free step from converging).
  /// stall_stillness 0: only the first rule.
  int patience = 5;
  double stall_gain = 0.05;       ///< see patience
  double near_residual = -1.0;    ///< see patience
  double stall_stillness = 0.01;  ///< see patience
  /// A run whose front stalled (patience ran out) with at most this fraction of the points
  /// beyond their tolerance, and the front within its tolerance of the data everywhere,
  /// counts as converged; ReconstructionResult::unreached_points says how many.
  double unreached_fraction = 0.01;
  /// Stop as soon as that holds, not only once the front stalls. Measured at 20k random
  /// points: the double and triple tori, the cup and the limb stop after 6-12 steps instead of
  /// 16-44 with the same Chamfer and Hausdorff distances (half the time), but two spheres 2.4 l
  /// apart come out joined: the bridge between them looks like a crease tip (fewer than 1% of
  /// the points unreached) until it opens at step 23. Off by default for that reason.
  bool stop_when_few_unreached = false;
};

/// @brief What is returned.
struct OutputOptions {
  /// Place the surface by a fit through the data once the front has settled: PCA normals
  /// oriented by grad u, local quadrics blended on the band around the front, output vertices
  /// projected onto the fit. Off: the front itself.
  bool fit_surface = true;
  /// Without fit_surface: extract {u = median of u at the data points} instead of {u = 0}
  /// (the front stops up to eps off the data on the side it came from).
  bool level_through_data = true;
  /// Also return meshes of the inside and the outside within the box (ReconstructionResult::
  /// volume), sharing the output surface vertex for vertex.
  bool volume_mesh = false;
};

/// @brief What the run may take.
struct LimitOptions {
  /// Memory the run may take, in bytes; 0: half the physical memory. Clouds and
  /// meshes predicted to need more are refused before they are built (lsr::ResourceLimit,
  /// lsr::MeshTooLarge), at the measured peak rounded up: 1 KB per input point, 1.3 KB per 3D
  /// mesh vertex, 2 KB per 2D one (4 GiB: about 3.3 million 3D mesh vertices).
  double max_memory = 0.0;
  /// Refuse (lsr::MeshTooLarge) meshes predicted to need more vertices; 0: from max_memory.
  Index max_vertices = 0;
  int threads = 0;  ///< 0: all cores
  /// Split the sampling stage's per-point work into this many tiles: runs along the Z-order
  /// curve, computed one after another (each worker's run, when shared). The lists of each
  /// point's 32 nearest are held one tile at a time (4 bytes x 32 a point otherwise). 0: one
  /// tile per worker. The result does not depend on it.
  int tiles = 0;
  /// Experimental: solve the front in tiles, the unit box cut into solve_tiles^D boxes, each
  /// meshed finely in its box and a margin, coarsely beyond, solved alone and welded at the
  /// seams into one closed surface; one tile's mesh is held at a time. 1: one mesh. The
  /// surface is the front's, projected onto the fit through the data (OutputOptions::
  /// fit_surface); the fit's corrections of the front's topology and the removal of unsupported
  /// parts are one mesh's only (measured: the same topology as one mesh on random samples, not
  /// on half the scans), and so is the volume mesh. docs/how-it-works.md, "Tiles and MPI".
  int solve_tiles = 1;
  /// The workers that share the sampling (tile_exchange.h; lsrecon-mpi: MPI ranks), each
  /// passing reconstruct() its share of the cloud (3D); null: this process alone. The result
  /// does not depend on them.
  std::shared_ptr<const TileExchange> exchange;
};

/// @brief The parameters, one group per stage.
struct ReconstructionOptions {
  SamplingOptions sampling;
  MeshOptions mesh;
  StartOptions start;
  EvolutionOptions evolution;
  StoppingOptions stopping;
  OutputOptions output;
  LimitOptions limits;
  /// The unit of sampling.hole_radius, mesh.h_min, mesh.max_resolution (per length),
  /// evolution.curvature_weight (length^2) and stopping.tolerance. The other lengths stay in
  /// the unit box: their defaults are unit-box values. Time (alpha, time_step) has no length.
  /// reconstruct_levels() takes the unit box only.
  LengthUnit lengths = LengthUnit::unit_box;
};

/// @brief The automatic values that follow from the dimension alone, with their reasons; the
/// ones that follow the data (mesh sizes, curvature weights, tolerances) are resolved per run
/// and reported in ReconstructionResult.
struct AutomaticDefaults {
  /// MeshOptions::max_resolution: 4096 in 2D, 256 in 3D. 256 is the grid of Poisson depth 8:
  /// on 200k random torus points it took 12.6 s and 1.4 GiB against 27.8 s and 2.3 GiB at 512,
  /// and kept the Chamfer distance at 0.2x that of Poisson depth 8 with true normals (measured).
  double max_resolution;
  /// The local h_min is at most this: 1/64 in 2D, 1/32 in 3D (sparse data still gets a mesh
  /// that resolves the unit box's shapes).
  double coarsest_finest_size;
  /// SamplingOptions::hole_radius: 0.06 in 3D (the radius of the test corpus's holes, 4% of the
  /// diagonal, and a margin), off in 2D.
  double hole_radius;
  /// EvolutionOptions::alpha: 2 from outside (-2 from inside), in 2D and 3D.
  double alpha;
  /// EvolutionOptions::time_step = time_step_factor / |alpha| (0.2, in 2D and 3D; see time_step).
  double time_step_factor;
};

/// @brief The automatic defaults in dimension 2 or 3: the one place the core, the command line
/// and the PCL class read them from.
constexpr AutomaticDefaults automatic_defaults(int dimension) {
  return dimension == 2 ? AutomaticDefaults{4096.0, 1.0 / 64, 0.0, 2.0, 0.2} : AutomaticDefaults{256.0, 1.0 / 32, 0.06, 2.0, 0.2};
}

}  // namespace lsr
