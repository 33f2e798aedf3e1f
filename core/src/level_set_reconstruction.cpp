// SPDX-License-Identifier: BSD-3-Clause
/// @file level_set_reconstruction.cpp
/// @brief The pipeline: normalise -> distance -> adaptive mesh -> u0 -> time loop (step,
/// renormalise, stopping test) -> extraction of the best iterate -> back to input coordinates.
#include "lsrecon/core/level_set_reconstruction.h"

#include "lsrecon/core/point_location.h"
#include "lsrecon/core/point_validation.h"
#include "lsrecon/core/renormalization.h"
#include "lsrecon/core/unit_box_transform.h"

#include <Eigen/Eigenvalues>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>

namespace lsr {
namespace {

// The data's bounding ball is mapped to radius 0.4, the enclosing start is the sphere of
// radius 0.45: 0.05 from the data's outermost point and from the box walls.
constexpr double kDataRadius = 0.4;
constexpr double kEnclosingRadius = 0.45;

class StageClock {
 public:
  explicit StageClock(std::map<std::string, double>& seconds) : seconds_(seconds) {}
  void end(const std::string& stage) {
    const auto now = std::chrono::steady_clock::now();
    seconds_[stage] += std::chrono::duration<double>(now - start_).count();
    start_ = now;
  }

 private:
  std::map<std::string, double>& seconds_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

// A closed curve needs points spanning the plane, a closed surface points spanning space.
template <int D>
void require_spanning(const Points<D>& points) {
  const char* shape = D == 2 ? "closed curve" : "closed surface";
  if (points.empty()) {
    throw InvalidInput("the point set is empty (no finite points)", "pass a cloud with points; NaN / infinite points are skipped");
  }
  if (points.size() < std::size_t(D + 1)) {
    throw InvalidInput(std::to_string(points.size()) + " valid points cannot define a " + shape,
                       "pass at least " + std::to_string(D + 1) + " distinct points; a useful "
                       "reconstruction needs hundreds");
  }
  Vec<D> mean = Vec<D>::Zero();
  for (const auto& p : points) mean += p;
  mean /= double(points.size());
  Eigen::Matrix<double, D, D> cov = Eigen::Matrix<double, D, D>::Zero();
  for (const auto& p : points) cov += (p - mean) * (p - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, D, D>> eig(cov);
  const double largest = eig.eigenvalues()[D - 1];
  // Relative thickness below 1e-6: flat to double precision after any realistic noise.
  if (!(largest > 0.0) || eig.eigenvalues()[0] < 1e-12 * largest) {
    throw InvalidInput(std::string("the points are ") + (D == 2 ? "colinear" : "coplanar or colinear") +
                           ": they do not enclose a region",
                       D == 3 ? "for planar data reconstruct curves in 2D (dimension 2)"
                              : "a closed curve needs points that are not on one line");
  }
}

// Median distance from a point to its nearest other point (duplicates skipped).
template <int D>
double median_spacing(const NearestPointIndex<D>& index) {
  const Points<D>& p = index.points();
  const std::size_t stride = std::max<std::size_t>(1, p.size() / 20000);  // a sample suffices
  Points<D> queries;
  for (std::size_t i = 0; i < p.size(); i += stride) queries.push_back(p[i]);
  std::vector<Index> nearest;
  const int k = 8;
  index.query_k(queries, k, nearest);
  std::vector<double> spacing;
  for (std::size_t q = 0; q < queries.size(); ++q) {
    for (int j = 0; j < k; ++j) {
      const double s = (p[nearest[q * k + j]] - queries[q]).norm();
      if (s > 0.0) {
        spacing.push_back(s);
        break;
      }
    }
  }
  if (spacing.empty()) return 0.0;
  std::nth_element(spacing.begin(), spacing.begin() + spacing.size() / 2, spacing.end());
  return spacing[spacing.size() / 2];
}

// Median thickness of the data across the curve / surface: sqrt of the smallest eigenvalue
// of the covariance of each point's k nearest neighbours. Clean samples give their sagitta
// (tiny), Gaussian noise of deviation sigma gives about sigma.
template <int D>
double noise_level(const NearestPointIndex<D>& index) {
  const Points<D>& p = index.points();
  const std::size_t stride = std::max<std::size_t>(1, p.size() / 5000);
  Points<D> queries;
  for (std::size_t i = 0; i < p.size(); i += stride) queries.push_back(p[i]);
  const int k = 16;
  std::vector<Index> nearest;
  index.query_k(queries, k, nearest);
  std::vector<double> thickness;
  for (std::size_t q = 0; q < queries.size(); ++q) {
    Vec<D> mean = Vec<D>::Zero();
    for (int j = 0; j < k; ++j) mean += p[nearest[q * k + j]];
    mean /= double(k);
    Eigen::Matrix<double, D, D> cov = Eigen::Matrix<double, D, D>::Zero();
    for (int j = 0; j < k; ++j) {
      const Vec<D> e = p[nearest[q * k + j]] - mean;
      cov += e * e.transpose() / double(k);
    }
    thickness.push_back(std::sqrt(std::max(0.0, Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, D, D>>(cov).eigenvalues()[0])));
  }
  std::nth_element(thickness.begin(), thickness.begin() + thickness.size() / 2, thickness.end());
  return thickness[thickness.size() / 2];
}

// The mesh resolves what the sampling resolves, but not the noise: finer than the spacing only
// lets the front sag between samples, finer than the noise makes islands (measured: 5 loops
// on a noisy circle). Clamped to what 2 cores handle in seconds.
template <int D>
double automatic_h_min(double spacing, double noise) {
  const double lo = D == 2 ? 1.0 / 4096 : 1.0 / 512;
  const double hi = D == 2 ? 1.0 / 64 : 1.0 / 32;
  return std::clamp(std::max(spacing, 1.5 * noise), lo, hi);
}

// beta = 0.3 h^2 keeps concavities within 0.15 h of the data (DESIGN.md section 9). Noise makes
// bumps of height sigma and width ~2h; flattening them needs beta kappa >= alpha sigma, i.e.
// beta ~ 2 |alpha| h^2: the weight grows towards that as sigma approaches h.
double automatic_curvature_weight(double h_min, double noise) {
  return (0.3 + 4.0 * std::min(1.0, noise / h_min)) * h_min * h_min;
}

// Vertices whose solve fits in 70% of the physical memory (peak bytes per vertex measured by
// the solver benchmark, rounded up).
template <int D>
Index memory_limited_vertices() {
  const double bytes = double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGE_SIZE));
  const double per_vertex = D == 3 ? 3500.0 : 2000.0;
  return Index(std::clamp(0.7 * bytes / per_vertex, 1e5, 2e9));
}

void check_options(const ReconstructionOptions& o) {
  auto bad = [](const std::string& what, const std::string& hint) { throw InvalidInput(what, hint); };
  if (!(o.h_min >= 0.0 && o.h_min < 1.0)) bad("h_min must be in [0, 1)", "use 0 (automatic) or e.g. 1/128");
  if (!std::isfinite(o.alpha)) bad("alpha is not finite", "use 0 (automatic), 2 or -2");
  if (!std::isfinite(o.curvature_weight)) bad("curvature_weight is not finite", "use -1 (automatic)");
  if (!(o.time_step >= 0.0 && o.time_step < 1e3)) bad("time_step must be >= 0 and finite", "use 0 (10 h_min)");
  if (!(o.tolerance >= 0.0 && o.tolerance < 1.0)) bad("tolerance must be in [0, 1)", "use 0 (h_min)");
  if (o.max_iterations < 1) bad("max_iterations must be at least 1", "try 1000");
  if (o.renormalization_interval < 0) bad("renormalization_interval must be >= 0", "use 0 (automatic), 1 or 2");
  if (o.patience < 1) bad("patience must be at least 1", "use 5");
  if (o.max_vertices < 0) bad("max_vertices must be >= 0", "use 0 (from the machine's memory)");
  if (!(o.solver_tolerance > 0.0 && o.solver_tolerance < 1.0)) bad("solver_tolerance must be in (0, 1)", "use 1e-6");
  if (o.initial_front == InitialFront::enclosing && o.alpha < 0.0) {
    bad("alpha < 0 makes a front that encloses the data grow away from it",
        "use alpha > 0 (e.g. 2) with the enclosing start, or start inside");
  }
  if (o.initial_front == InitialFront::inside && o.alpha > 0.0) {
    bad("alpha > 0 makes a front that starts inside the data shrink away from it",
        "use alpha < 0 (e.g. -2) with the inside start");
  }
}

template <int D>
Eigen::VectorXd initial_field(const SimplexMesh<D>& mesh, const NearestPointIndex<D>& data,
                              InitialFront front, double h_min) {
  Vec<D> center = Vec<D>::Constant(0.5);
  double radius = kEnclosingRadius;
  if (front == InitialFront::inside) {
    center = Vec<D>::Zero();
    for (const auto& p : data.points()) center += p;
    center /= double(data.points().size());
    radius = 0.5 * data.distance(center);
    if (radius < 2.0 * h_min) {
      throw InvalidInput("the data's centroid lies on or near the data, so an inside start does not fit",
                         "start from the enclosing circle / sphere (the default)");
    }
  }
  Eigen::VectorXd u(mesh.vertices.size());
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) u[i] = (mesh.vertices[i] - center).norm() - radius;
  return u;
}

// Mesh vertices near each data point: those within `radius` whose nearest data point it is
// (its Voronoi cell, cut at the radius). CSR: vertices of point i at [offsets[i], offsets[i+1]).
struct VertexCells {
  std::vector<Index> offsets, vertices;
};

VertexCells near_vertex_cells(std::size_t points, const std::vector<double>& d,
                              const std::vector<Index>& nearest, double radius) {
  VertexCells c;
  c.offsets.assign(points + 1, 0);
  for (std::size_t v = 0; v < d.size(); ++v) {
    if (d[v] <= radius) ++c.offsets[nearest[v] + 1];
  }
  for (std::size_t i = 0; i < points; ++i) c.offsets[i + 1] += c.offsets[i];
  c.vertices.resize(c.offsets[points]);
  std::vector<Index> fill(c.offsets.begin(), c.offsets.end() - 1);
  for (std::size_t v = 0; v < d.size(); ++v) {
    if (d[v] <= radius) c.vertices[fill[nearest[v]]++] = Index(v);
  }
  return c;
}

// A data point counts as reached once the moving front is within `reach` of it (u rises to 0
// at the data when alpha > 0, falls to 0 when alpha < 0); its cell then stops moving.
template <int D>
void pin_reached_data(const std::vector<Location<D>>& at, const VertexCells& cells,
                      const Eigen::VectorXd& u, double alpha, double reach,
                      std::vector<char>& pinned, Eigen::VectorXd& d) {
  for (std::size_t i = 0; i < at.size(); ++i) {
    if (pinned[i]) continue;
    const double v = interpolate(at[i], u);
    if ((alpha > 0.0 ? v : -v) >= -reach) {
      pinned[i] = 1;
      for (Index vertex : at[i].vertices) d[vertex] = 0.0;
      for (Index k = cells.offsets[i]; k < cells.offsets[i + 1]; ++k) d[cells.vertices[k]] = 0.0;
    }
  }
}

template <int D>
double max_on_data(const std::vector<Location<D>>& at, const Eigen::VectorXd& u) {
  double worst = 0.0;
  for (const auto& loc : at) worst = std::max(worst, std::abs(interpolate(loc, u)));
  return worst;
}

// Largest distance from the front to the data (d interpolated along the front's source edges):
// the other side of the stopping test, which sees pieces of front far from every data point.
template <int D>
double max_front_distance(const LevelSetMesh<D>& front, const Eigen::VectorXd& d) {
  double worst = 0.0;
  for (const EdgePoint& e : front.sources) worst = std::max(worst, (1.0 - e.t) * d[e.a] + e.t * d[e.b]);
  return worst;
}

template <int D>
double median_on_data(const std::vector<Location<D>>& at, const Eigen::VectorXd& u) {
  std::vector<double> values;
  values.reserve(at.size());
  for (const auto& loc : at) values.push_back(interpolate(loc, u));
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

template <int D>
void attach_output(ReconstructionResult<D>& r, const SimplexMesh<D>& mesh, const P1Operators<D>& ops,
                   const Eigen::VectorXd& u, double level, const UnitBoxTransform<D>& box) {
  std::vector<double> values(u.data(), u.data() + u.size());
  for (double& v : values) v -= level;
  r.surface = extract_zero_level_set(mesh, values);
  const Eigen::VectorXd g = ops.gradient * u;
  r.normals.resize(r.surface.vertices.size());
  for (std::size_t i = 0; i < r.surface.vertices.size(); ++i) {
    const EdgePoint& e = r.surface.sources[i];
    const Vec<D> n = (1.0 - e.t) * g.template segment<D>(D * e.a) + e.t * g.template segment<D>(D * e.b);
    r.normals[i] = n.norm() > 0.0 ? Vec<D>(n.normalized()) : Vec<D>::Zero();
    r.surface.vertices[i] = box.from_unit(r.surface.vertices[i]);
  }
  if constexpr (D == 2) r.loops = closed_loops(r.surface);
}


template <int D>
ReconstructionResult<D> run_pipeline(const Points<D>& input, const ReconstructionOptions& o,
                                     const ProgressCallback& callback, const SignedDistance<D>* custom_start) {
  check_options(o);
  ReconstructionResult<D> r;
  StageClock clock(r.seconds);
  const Progress progress(callback);
  r.input_points = input.size();
  const Points<D> points = drop_non_finite(input);
  r.skipped_points = input.size() - points.size();
  require_spanning(points);
  const auto box = UnitBoxTransform<D>::fit_ball(points, kDataRadius);
  const NearestPointIndex<D> data(box.to_unit(points));
  clock.end("normalize");

  const double spacing = median_spacing(data);
  r.noise = noise_level(data);
  r.h_min = o.h_min > 0.0 ? o.h_min : automatic_h_min<D>(spacing, r.noise);
  AdaptiveMeshOptions mo;
  mo.h_min = r.h_min;
  mo.h_max = std::max(o.h_max, r.h_min);
  mo.grading = o.grading;
  mo.max_vertices = o.max_vertices > 0 ? o.max_vertices : memory_limited_vertices<D>();
  mo.threads = o.threads;
  AdaptiveMesh<D> adaptive;
  try {
    adaptive = build_adaptive_mesh(data, mo, progress);
  } catch (const Cancelled&) {
    r.status = ReconstructionStatus::cancelled;
    return r;
  }
  const SimplexMesh<D>& mesh = adaptive.mesh;
  r.mesh_vertices = Index(mesh.vertices.size());
  r.mesh_simplices = Index(mesh.simplices.size());
  clock.end("mesh");

  std::vector<double> dist;
  std::vector<Index> nearest;
  data.query(mesh.vertices, dist, &nearest, o.threads);
  const VertexCells cells = near_vertex_cells(data.points().size(), dist, nearest, 2.0 * r.h_min);
  const Eigen::VectorXd distance = Eigen::Map<const Eigen::VectorXd>(dist.data(), Eigen::Index(dist.size()));
  Eigen::VectorXd d = distance;  // what drives the front: zero where it is pinned
  const std::vector<Location<D>> at = locate_all(adaptive, data.points(), o.threads);
  clock.end("distance");

  const P1Operators<D> ops = assemble_p1_operators(mesh, compute_simplex_geometry(mesh),
                                                   o.solver == LinearSolver::gmres_reference);
  StepParameters step;
  step.alpha = o.alpha != 0.0 ? o.alpha : (o.initial_front == InitialFront::enclosing ? 2.0 : -2.0);
  step.time_step = o.time_step > 0.0 ? o.time_step : 0.2 / std::abs(step.alpha);
  step.curvature_weight =
      o.curvature_weight >= 0.0 ? o.curvature_weight : automatic_curvature_weight(r.h_min, r.noise);
  step.solver_tolerance = o.solver_tolerance;
  step.solver = o.solver;
  const int interval = o.renormalization_interval > 0
                           ? o.renormalization_interval
                           : std::max(1, int(0.4 / (std::abs(step.alpha) * step.time_step) + 1e-9));
  r.time_step = step.time_step;
  r.alpha = step.alpha;
  r.curvature_weight = step.curvature_weight;
  const double eps = o.tolerance > 0.0 ? o.tolerance : r.h_min;
  r.tolerance = eps / box.scale();
  Eigen::VectorXd u(mesh.vertices.size());
  if (custom_start) {
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
      u[i] = (*custom_start)(box.from_unit(mesh.vertices[i])) * box.scale();
    }
    if (!u.allFinite() || u.minCoeff() >= 0.0 || u.maxCoeff() < 0.0) {
      throw InvalidInput("the initial function has no zero set inside the box around the data, or is not finite",
                         "pass a signed distance that is negative inside a closed curve / surface near the data");
    }
  } else {
    u = initial_field(mesh, data, o.initial_front, r.h_min);
  }
  clock.end("setup");

  // Between samples the front may sit half a sample spacing away from the data.
  const double front_tolerance = eps + 0.5 * spacing;
  double front_distance = std::numeric_limits<double>::infinity();
  std::vector<char> pinned(at.size(), 0);
  double first_residual = std::numeric_limits<double>::infinity();
  double progress_fraction = 0.0;
  Eigen::VectorXd best = u;
  double best_residual = std::numeric_limits<double>::infinity();
  // Renormalise every vertex: a band of a few h_min is thinner than the coarse simplices the
  // front crosses early on, and clamping there flattens u over whole simplices and stalls the
  // front (measured). The exact distance everywhere costs one k-NN query per vertex.
  const double band = std::numeric_limits<double>::infinity();
  try {
    for (int n = 1; n <= o.max_iterations; ++n) {
      progress.update("solve", progress_fraction);
      SolverReport solve;
      u = semi_implicit_step(ops, d, u, step, &solve);
      r.solver_iterations += solve.iterations;
      clock.end("solve");
      if (o.pin_reached_data) pin_reached_data(at, cells, u, step.alpha, 0.5 * eps, pinned, d);
      if (n % interval == 0) {
        front_distance = max_front_distance(renormalize(mesh, u, ops.gradient_norms(u), band, o.threads).front, distance);
        clock.end("renormalize");
      }
      const double data_residual = max_on_data(at, u);
      // Converged when every data point is within eps of the front and the front within
      // front_tolerance of the data; the residual is the worse of the two, in units of eps.
      const double residual = std::max(data_residual, front_distance * eps / front_tolerance);
      r.residual_history.push_back(residual / box.scale());
      // The data side falls geometrically (the front side can drop at once when a bubble
      // vanishes): progress is the fraction of log(first / eps) it has covered, never receding.
      if (!std::isfinite(first_residual)) first_residual = data_residual;
      if (first_residual > eps) {
        progress_fraction = std::max(progress_fraction, std::clamp(std::log(first_residual / std::max(data_residual, eps)) /
                                                                       std::log(first_residual / eps), 0.0, 1.0));
      }
      r.iterations = n;
      if (residual < best_residual) {
        best_residual = residual;
        best = u;
        r.best_iteration = n;
      }
      clock.end("stopping test");
      if (best_residual <= eps) {
        r.status = ReconstructionStatus::converged;
        break;
      }
      if (n - r.best_iteration >= o.patience) break;
    }
  } catch (const Cancelled&) {
    r.status = ReconstructionStatus::cancelled;
  }
  r.residual = best_residual / box.scale();
  r.noise /= box.scale();
  r.output_level = o.level_through_data ? median_on_data(at, best) / box.scale() : 0.0;
  attach_output(r, mesh, ops, best, r.output_level * box.scale(), box);
  clock.end("extract");
  return r;
}

}  // namespace

template <int D>
ReconstructionResult<D> reconstruct(const Points<D>& points, const ReconstructionOptions& options,
                                    const ProgressCallback& progress) {
  return run_pipeline<D>(points, options, progress, nullptr);
}

template <int D>
ReconstructionResult<D> reconstruct_from(const Points<D>& points, const SignedDistance<D>& initial,
                                         const ReconstructionOptions& options, const ProgressCallback& progress) {
  if (options.alpha == 0.0) {
    throw InvalidInput("a custom start needs an explicit alpha",
                       "set alpha > 0 (e.g. 2) if the start encloses the data, < 0 (e.g. -2) if it lies inside");
  }
  ReconstructionOptions o = options;
  o.initial_front = options.alpha > 0.0 ? InitialFront::enclosing : InitialFront::inside;
  return run_pipeline<D>(points, o, progress, &initial);
}

template ReconstructionResult<2> reconstruct_from<2>(const Points<2>&, const SignedDistance<2>&,
                                                     const ReconstructionOptions&, const ProgressCallback&);
template ReconstructionResult<3> reconstruct_from<3>(const Points<3>&, const SignedDistance<3>&,
                                                     const ReconstructionOptions&, const ProgressCallback&);
template ReconstructionResult<2> reconstruct<2>(const Points<2>&, const ReconstructionOptions&, const ProgressCallback&);
template ReconstructionResult<3> reconstruct<3>(const Points<3>&, const ReconstructionOptions&, const ProgressCallback&);

}  // namespace lsr
