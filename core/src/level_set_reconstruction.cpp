// SPDX-License-Identifier: BSD-3-Clause
/// @file level_set_reconstruction.cpp
/// @brief The pipeline: normalise -> distance -> adaptive mesh -> u0 -> time loop (step,
/// renormalise, stopping test) -> extraction of the best iterate -> back to input coordinates.
#include "lsrecon/core/level_set_reconstruction.h"

#include "lsrecon/core/cavity_sealing.h"
#include "lsrecon/core/level_set_volume_mesh.h"
#include "lsrecon/core/local_sampling.h"
#include "lsrecon/core/merge_without_joins.h"
#include "lsrecon/core/outside_flood_fill.h"
#include "lsrecon/core/point_location.h"
#include "lsrecon/core/quadric_implicit.h"
#include "lsrecon/core/point_validation.h"
#include "lsrecon/core/renormalization.h"
#include "lsrecon/core/residual_noise.h"
#include "lsrecon/core/sheet_gaps.h"
#include "lsrecon/core/stall_detection.h"
#include "lsrecon/core/tangent_discs.h"
#include "lsrecon/core/unit_box_transform.h"
#include "lsrecon/core/unsupported_parts.h"
#include "lsrecon/core/z_order.h"

#include <Eigen/Eigenvalues>
#include <omp.h>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>

namespace lsr {
namespace {

// The data's bounding ball is mapped to radius 0.4, the enclosing start is the sphere of
// radius 0.45: 0.05 from the data's outermost point and from the box walls.
constexpr double kDataRadius = 0.4;
constexpr double kEnclosingRadius = 0.45;
// Output vertices keep 1% of their mesh edge from its ends: moves them by at most that (the
// fit's projection then puts them back on the surface) and keeps any two of them apart.
constexpr double kOutputEdgeMargin = 0.01;

class StageClock {
 public:
  StageClock(std::map<std::string, double>& seconds, std::vector<std::string>& order) : seconds_(seconds), order_(order) {}
  void end(const std::string& stage) {
    const auto now = std::chrono::steady_clock::now();
    if (!seconds_.count(stage)) order_.push_back(stage);
    seconds_[stage] += std::chrono::duration<double>(now - start_).count();
    start_ = now;
  }

 private:
  std::map<std::string, double>& seconds_;
  std::vector<std::string>& order_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

// A closed curve needs points spanning the plane, a closed surface points spanning space.
template <int D>
void require_spanning(const Points<D>& points) {
  const char* shape = D == 2 ? "closed curve" : "closed surface";
  if (points.empty()) {
    throw InvalidInput("the point set is empty (no finite points)", "pass a cloud with points; NaN / infinite points are skipped");
  }
  Points<D> sorted = points;
  std::sort(sorted.begin(), sorted.end(), [](const Vec<D>& a, const Vec<D>& b) {
    return std::lexicographical_compare(a.data(), a.data() + D, b.data(), b.data() + D);
  });
  const std::size_t distinct = std::size_t(std::unique(sorted.begin(), sorted.end()) - sorted.begin());
  if (distinct < std::size_t(D + 1)) {
    throw InvalidInput(std::to_string(distinct) + " distinct point(s) cannot define a " + shape,
                       "pass at least " + std::to_string(D + 1) + " distinct points; a useful "
                       "reconstruction needs hundreds");
  }
  Vec<D> mean = Vec<D>::Zero();
  for (const auto& p : points) mean += p / double(points.size());
  double extent = 0.0;
  for (const auto& p : points) extent = std::max(extent, (p - mean).cwiseAbs().maxCoeff());
  if (!std::isfinite(extent) || !mean.allFinite()) {
    throw InvalidInput("the coordinates are too large for double precision arithmetic",
                       "rescale the points (coordinates below 1e150)");
  }
  // Scaled to the extent: squares of 1e300 would overflow.
  Eigen::Matrix<double, D, D> cov = Eigen::Matrix<double, D, D>::Zero();
  for (const auto& p : points) cov += ((p - mean) / extent) * ((p - mean) / extent).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, D, D>> eig(cov);
  const double largest = eig.eigenvalues()[D - 1];
  // Relative thickness below 1e-6: flat to double precision after any realistic noise.
  if (!(largest > 0.0) || eig.eigenvalues()[0] < 1e-12 * largest) {
    std::ostringstream why;
    why << "the points are " << (D == 2 ? "colinear" : "coplanar or colinear") << " (thinner than 1e-6 of their extent "
        << std::setprecision(3) << extent << "): they do not enclose a region";
    throw InvalidInput(why.str(),
                       D == 3 ? "planar points give closed curves: reconstruct them in 2D (reconstruct<2>; setDimension(2) in the "
                                "PCL class; an .svg or .txt output in the command line)"
                              : "a closed curve needs points that are not on one line");
  }
}

// Drops the isolated points (nearest distinct neighbour beyond `factor` local spacings) from
// points and kept; true if there were any.
template <int D>
bool drop_isolated(const LocalSampling<D>& s, double factor, Points<D>& points, std::vector<std::size_t>& kept) {
  if (factor <= 0.0) return false;
  std::size_t n = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (s.gap[i] > factor * s.spacing[i]) continue;
    points[n] = points[i];
    kept[n++] = kept[i];
  }
  if (n == points.size()) return false;
  points.resize(n);
  kept.resize(n);
  return true;
}

// The local scale l_i = max(s_i, 1.5 noise_i): what the sampling resolves, but not the noise
// (finer than the noise makes islands; measured: 5 loops on a noisy circle). Every length of
// the solver is a multiple of it.
template <int D>
std::vector<double> local_scales(const LocalSampling<D>& s) {
  std::vector<double> l(s.spacing.size());
  for (std::size_t i = 0; i < l.size(); ++i) l[i] = std::max({s.spacing[i], 1.5 * s.noise[i], 1e-9});
  return l;
}

// Mesh size near each point: its scale, clamped to [1 / max_resolution, 1/64 (2D) or 1/32
// (3D)], or the size asked for.
template <int D>
std::vector<double> local_mesh_sizes(const std::vector<double>& scale, double fixed, double max_resolution) {
  const double lo = 1.0 / (max_resolution > 0.0 ? max_resolution : D == 2 ? 4096.0 : 256.0);
  const double hi = std::max(lo, D == 2 ? 1.0 / 64 : 1.0 / 32);
  std::vector<double> h(scale.size());
  for (std::size_t i = 0; i < h.size(); ++i) h[i] = fixed > 0.0 ? fixed : std::clamp(scale[i], lo, hi);
  return h;
}

// Peak memory per input point and per mesh vertex, measured on random samples and rounded up:
// trefoil 200k and 1M points at the same 327k vertices peaked at 495 and 929 MiB (0.56 KB per
// point), and with that the 200k sphere, torus and trefoil at 0.99, 0.97 and 1.2 KB per 3D
// vertex. 2D: 2 KB per vertex, measured before G^T stopped being stored.
constexpr double kBytesPerPoint = 1000.0;
template <int D>
constexpr double kBytesPerVertex = D == 3 ? 1300.0 : 2000.0;

// max_memory, or min(4 GiB, half the physical memory).
double memory_budget(const ReconstructionOptions& o) {
  if (o.max_memory > 0.0) return o.max_memory;
  const double physical = double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGE_SIZE));
  return std::min(4.0 * (1 << 30), 0.5 * physical);
}

std::string gib(double bytes) {
  std::ostringstream s;
  s << std::setprecision(3) << bytes / double(1 << 30) << " GiB";
  return s.str();
}

// The mesh vertices that fit in the budget beside the points; refuses a cloud that alone
// would not.
template <int D>
Index memory_limited_vertices(const ReconstructionOptions& o, std::size_t points) {
  const double budget = memory_budget(o);
  const double for_points = double(points) * kBytesPerPoint;
  const double vertices = (budget - for_points) / kBytesPerVertex<D>;
  if (vertices < 1e4) {
    throw ResourceLimit(std::to_string(points) + " points need about " + gib(for_points + 1e4 * kBytesPerVertex<D>) +
                            ", more than the memory limit of " + gib(budget),
                        "raise max_memory (lsrecon --max-memory GiB) or subsample the cloud");
  }
  return Index(std::min(vertices, 2e9));
}

void check_options(const ReconstructionOptions& o) {
  auto bad = [](const std::string& what, const std::string& hint) { throw InvalidInput(what, hint); };
  if (!(o.h_min >= 0.0 && o.h_min < 1.0)) bad("h_min must be in [0, 1)", "use 0 (automatic) or e.g. 1/128");
  if (!(o.max_resolution == 0.0 || (o.max_resolution >= 4.0 && o.max_resolution <= 1e5))) {
    bad("max_resolution must be 0 (automatic) or in [4, 1e5]", "use 0 (256 in 3D, 4096 in 2D) or e.g. 512");
  }
  if (!std::isfinite(o.alpha)) bad("alpha is not finite", "use 0 (automatic), 2 or -2");
  if (!std::isfinite(o.curvature_weight)) bad("curvature_weight is not finite", "use -1 (automatic)");
  if (!(o.time_step >= 0.0 && o.time_step < 1e3)) bad("time_step must be >= 0 and finite", "use 0 (automatic: 0.2 / |alpha|)");
  if (!(o.tolerance >= 0.0 && o.tolerance < 1.0)) bad("tolerance must be in [0, 1)", "use 0 (automatic: tolerance_factor local spacings)");
  auto factor = [&](double v, const char* name, double lo, double hi, const char* use) {
    if (!(v > lo && v <= hi)) bad(std::string(name) + " must be in (" + std::to_string(lo) + ", " + std::to_string(hi) + "]", use);
  };
  factor(o.gap_factor, "gap_factor", 0.0, 20.0, "use 2 (local scales)");
  factor(o.pin_factor, "pin_factor", 0.0, 20.0, "use 2 (local scales)");
  factor(o.tolerance_factor, "tolerance_factor", 0.0, 20.0, "use 1 (local scales)");
  factor(o.curvature_factor, "curvature_factor", -1e-300, 100.0, "use 0.25");
  if (!(o.start_offset >= 0.0 && o.start_offset < o.gap_factor)) {
    bad("start_offset must be in [0, gap_factor)", "use 0.5 (local spacings) or 0 (the flood's boundary)");
  }
  if (!(o.hole_radius < 0.5)) bad("hole_radius must be below 0.5 (unit box)", "use -1 (automatic), 0 (no closing) or e.g. 0.06");
  if (o.max_iterations < 1) bad("max_iterations must be at least 1", "try 1000");
  if (o.renormalization_interval < 0) bad("renormalization_interval must be >= 0", "use 0 (automatic), 1 or 2");
  if (o.patience < 1) bad("patience must be at least 1", "use 5");
  if (!(o.stall_gain >= 0.0 && o.stall_gain < 1.0)) bad("stall_gain must be in [0, 1)", "use 0.05");
  if (!(o.near_residual < 1e3)) bad("near_residual must be below 1000", "use a negative value (automatic)");
  if (!(o.stall_stillness >= 0.0 && o.stall_stillness < 1e3)) bad("stall_stillness must be in [0, 1000)", "use 0.01 (or 0: off)");
  if (!(o.unreached_fraction >= 0.0 && o.unreached_fraction < 1.0)) bad("unreached_fraction must be in [0, 1)", "use 0.01");
  if (!(o.outlier_factor == 0.0 || (o.outlier_factor >= 1.0 && o.outlier_factor <= 1e3))) {
    bad("outlier_factor must be 0 (keep every point) or in [1, 1000]", "use 3");
  }
  if (o.max_vertices < 0) bad("max_vertices must be >= 0", "use 0 (from max_memory)");
  if (!(o.max_memory >= 0.0 && o.max_memory < 1e15)) bad("max_memory must be >= 0 bytes and finite", "use 0 (min(4 GiB, half the memory))");
  if (!(o.solver_tolerance > 0.0 && o.solver_tolerance < 1.0)) bad("solver_tolerance must be in (0, 1)", "use 1e-6");
  if (o.initial_front != InitialFront::inside && o.alpha < 0.0) {
    bad("alpha < 0 makes a front that encloses the data grow away from it",
        "use alpha > 0 (e.g. 2) with the enclosing start, or start inside");
  }
  if (o.two_sided && o.alpha < 0.0) {
    bad("two-sided attraction moves the front towards the data from both sides with alpha > 0",
        "use alpha > 0 (e.g. 2) or 0 (automatic)");
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

// Mesh vertices each data point holds once reached: those whose nearest data point it is (its
// Voronoi cell), within pin_factor s of it. A vertex path that avoids every such ball crosses
// the surface only through an empty disc wider than pin_factor s, which a random sample of
// 2e5 points leaves with probability ~ N exp(-6 pin_factor^2) (local_sampling.h).
// CSR: vertices of point i at [offsets[i], offsets[i+1]).
struct VertexCells {
  std::vector<Index> offsets, vertices;
};

VertexCells pin_cells(const Eigen::VectorXd& scale, std::size_t points, const std::vector<double>& d,
                      const std::vector<Index>& nearest, double pin_factor) {
  std::vector<char> in(d.size(), 0);
  for (std::size_t v = 0; v < d.size(); ++v) in[v] = d[v] <= pin_factor * scale[v];
  VertexCells c;
  c.offsets.assign(points + 1, 0);
  for (std::size_t v = 0; v < d.size(); ++v) c.offsets[nearest[v] + 1] += in[v];
  for (std::size_t i = 0; i < points; ++i) c.offsets[i + 1] += c.offsets[i];
  c.vertices.resize(c.offsets[points]);
  std::vector<Index> fill(c.offsets.begin(), c.offsets.end() - 1);
  for (std::size_t v = 0; v < d.size(); ++v) {
    if (in[v]) c.vertices[fill[nearest[v]]++] = Index(v);
  }
  return c;
}

// A data point counts as reached once the moving front is within `reach` of it (u rises to 0
// at the data when alpha > 0, falls to 0 when alpha < 0); its cell then stops moving: d := 0
// there and the vertices are held.
template <int D>
void pin_reached_data(const std::vector<Location<D>>& at, const VertexCells& cells,
                      const Eigen::VectorXd& u, double alpha, const std::vector<double>& reach,
                      std::vector<char>& pinned, Eigen::VectorXd& d, std::vector<char>& held) {
  auto hold = [&](Index vertex) {
    d[vertex] = 0.0;
    held[vertex] = 1;
  };
  for (std::size_t i = 0; i < at.size(); ++i) {
    if (pinned[i]) continue;
    const double v = interpolate(at[i], u);
    if ((alpha > 0.0 ? v : -v) >= -reach[i]) {
      pinned[i] = 1;
      for (Index vertex : at[i].vertices) hold(vertex);
      for (Index k = cells.offsets[i]; k < cells.offsets[i + 1]; ++k) hold(cells.vertices[k]);
    }
  }
}

// Per point |u(x_i)| / eps_i: the data side of the stopping test, in units of the tolerance.
template <int D>
std::vector<double> data_residuals(const std::vector<Location<D>>& at, const Eigen::VectorXd& u, const std::vector<double>& eps) {
  std::vector<double> r(at.size());
  for (std::size_t i = 0; i < at.size(); ++i) r[i] = std::abs(interpolate(at[i], u)) / eps[i];
  return r;
}

// Largest distance from the front to the data relative to the local tolerance there (both
// interpolated along the front's source edges): the other side of the stopping test, which
// sees pieces of front far from every data point. d counts as 0 at `ignored` vertices (empty:
// none).
template <int D>
double max_front_distance(const LevelSetMesh<D>& front, const Eigen::VectorXd& d, const Eigen::VectorXd& tolerance,
                          const std::vector<char>& ignored) {
  const auto at = [&](Index v) { return ignored.empty() || !ignored[std::size_t(v)] ? d[v] : 0.0; };
  double worst = 0.0;
  for (const EdgePoint& e : front.sources) {
    worst = std::max(worst, ((1.0 - e.t) * at(e.a) + e.t * at(e.b)) / ((1.0 - e.t) * tolerance[e.a] + e.t * tolerance[e.b]));
  }
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

// The data term of Zhao, Osher and Fedkiw's convection towards the data, in the form the step
// takes: u_t = alpha d grad d . grad u = |grad u| alpha d cos(theta), theta between the normal
// and the direction away from the data. The front moves towards the data from either side at
// the speed alpha d of the one-sided term (same CFL), and stops on it.
template <int D>
Eigen::VectorXd two_sided_drive(const P1Operators<D>& ops, const Eigen::VectorXd& d, const Points<D>& away,
                                const Eigen::VectorXd& u) {
  const Eigen::VectorXd g = ops.gradient_times(u);
  Eigen::VectorXd drive(d.size());
  for (Eigen::Index v = 0; v < d.size(); ++v) {
    const Vec<D> gv = g.template segment<D>(D * v);
    const double norm = gv.norm();
    drive[v] = norm > 0.0 ? d[v] * away[std::size_t(v)].dot(gv) / norm : 0.0;
  }
  return drive;
}

// The one-sided drive, with d := 0 where the front has passed its nearest data point (faces
// away from it: alpha grad d . grad u < 0, alpha's sign the way it moves) by more than `gap`:
// the one-sided term would go on pulling it on, into a pit under one of the widest empty discs
// of a random sample, which the stopping test's front side then never accepts. Not `near_hole`
// (empty: nowhere): a front that crept past a hole's rim is the fit's to correct (attach_fit),
// and resting it there left handles (measured: the noisy holey trefoils of seeds 2 and 4).
template <int D>
Eigen::VectorXd drive_resting_past_data(const P1Operators<D>& ops, const Eigen::VectorXd& d, const Points<D>& away,
                                        const Eigen::VectorXd& u, const std::vector<double>& dist, const Eigen::VectorXd& gap,
                                        const std::vector<char>& near_hole, double alpha) {
  Eigen::VectorXd drive = two_sided_drive(ops, d, away, u);
  for (Eigen::Index v = 0; v < drive.size(); ++v) {
    const bool passed = alpha * drive[v] < 0.0 && dist[std::size_t(v)] > gap[v];
    drive[v] = passed && (near_hole.empty() || !near_hole[std::size_t(v)]) ? 0.0 : d[v];
  }
  return drive;
}

// The signed distance to the boundary of the flooded vertices (> 0 in the flood); empty when
// the flood is empty or everything.
template <int D>
Eigen::VectorXd flood_distance(const SimplexMesh<D>& mesh, const VertexNeighbours& neighbours, const std::vector<char>& flooded,
                               double band, int threads) {
  Eigen::VectorXd u(Eigen::Index(flooded.size()));
  for (std::size_t v = 0; v < flooded.size(); ++v) u[v] = flooded[v] ? 1.0 : -1.0;
  if (u.minCoeff() > 0.0 || u.maxCoeff() < 0.0) return {};
  renormalize(mesh, neighbours, u, band, threads);
  return u;
}

// u0 for the tagged start: the region reachable from the walls while staying farther than
// gap_factor local scales from the data (`attraction`: the distance to the points, or to their
// tangent discs when holes are spanned). Over a hole the mesh is coarser than the gap: there a
// vertex also blocks when the discs pass within half its longest edge (`edge_guard`, empty
// without discs), so that no edge jumps the discs' plane; "over a hole" meaning the discs are
// nearer than the points by more than the gap, so that a coarse mesh over sampled parts does not
// push the start out. Cavities entered through an opening narrower than `seal_radius` are given
// back (cavity_sealing.h; `sealed`). Empty when nothing is reachable (data against the walls).
template <int D>
Eigen::VectorXd tagged_start(const SimplexMesh<D>& mesh, const VertexNeighbours& neighbours, const Eigen::VectorXd& attraction,
                             const Eigen::VectorXd& distance, const Eigen::VectorXd& scale,
                             const std::vector<double>& edge_guard, double gap_factor, double band, double seal_radius,
                             SealedCavities& sealed, int threads) {
  const std::size_t n = mesh.vertices.size();
  std::vector<char> passable(n);
  for (std::size_t v = 0; v < n; ++v) {
    const double gap = gap_factor * scale[v];
    passable[v] = attraction[v] > gap &&
                  (edge_guard.empty() || attraction[v] > std::min(edge_guard[v], distance[v] - gap));
  }
  std::vector<char> reached = flood_from_walls(mesh, passable);
  sealed = seal_cavities(mesh, neighbours, attraction, seal_radius, reached);
  return flood_distance(mesh, neighbours, reached, band, threads);
}

// Flags the vertices within `radius` of a `seed` vertex (all false without seeds).
template <int D>
std::vector<char> near_any(const Points<D>& vertices, const std::vector<char>& seed, double radius, int threads) {
  Points<D> seeds;
  for (std::size_t v = 0; v < seed.size(); ++v) {
    if (seed[v]) seeds.push_back(vertices[v]);
  }
  std::vector<char> out(vertices.size(), 0);
  if (seeds.empty()) return out;
  const NearestPointIndex<D> index(std::move(seeds));
  std::vector<double> dist;
  index.query(vertices, dist, nullptr, threads);
  for (std::size_t v = 0; v < vertices.size(); ++v) out[v] = dist[v] <= radius;
  return out;
}

// Half the longest edge at each vertex within `near` of the data (0 elsewhere): see tagged_start.
template <int D>
std::vector<double> half_longest_edges(const SimplexMesh<D>& mesh, const VertexNeighbours& n,
                                       const std::vector<double>& distance, const Eigen::VectorXd& near) {
  std::vector<double> out(mesh.vertices.size(), 0.0);
  for (std::size_t v = 0; v < out.size(); ++v) {
    if (distance[v] > near[Eigen::Index(v)]) continue;
    for (Index k = n.offsets[v]; k < n.offsets[v + 1]; ++k) {
      out[v] = std::max(out[v], 0.5 * (mesh.vertices[n.neighbours[k]] - mesh.vertices[v]).norm());
    }
  }
  return out;
}

// The output surface of `values`, closed: a front or fit that reaches the box (a handful of
// points spanning the box, a fit extrapolated past the data) is capped just inside the walls.
// Parts that no data point is nearest to go (unsupported_parts.h; a void inside such a part
// becomes one in turn, hence the loop). The values are left as extracted in `values`: the
// volume split cuts along the same level set.
template <int D, class Values>
void cap_at_walls(const SimplexMesh<D>& mesh, Values& values) {
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (on_wall<D>(mesh.vertices[v])) values[v] = std::max(values[v], std::numeric_limits<double>::min());
  }
}

template <int D>
LevelSetMesh<D> extract_closed_surface(const SimplexMesh<D>& mesh, const Points<D>& points, std::vector<double>& values,
                                       int threads) {
  cap_at_walls<D>(mesh, values);
  LevelSetMesh<D> surface = extract_zero_level_set(mesh, values, kOutputEdgeMargin, threads);
  while (drop_unsupported_parts(mesh, surface, points, values, threads) > 0) {
    surface = extract_zero_level_set(mesh, values, kOutputEdgeMargin, threads);
  }
  return surface;
}

// The inside and outside meshes, sharing the output surface, when asked for.
template <int D>
void attach_volume(ReconstructionResult<D>& r, const SimplexMesh<D>& mesh, const std::vector<double>& values,
                   bool wanted) {
  if (!wanted) return;
  r.volume = split_along_level_set(mesh, values, r.surface);
  // Where the split had to pull a vertex back, the surface follows: it is the inside's boundary.
  for (std::size_t i = 0; i < r.surface.vertices.size(); ++i) {
    r.surface.vertices[i] = r.volume.vertices[std::size_t(r.volume.interface_offset) + i];
  }
}

// The front's own surface (no fit): the level `level` of u, normals from grad u.
template <int D>
void attach_front(ReconstructionResult<D>& r, const SimplexMesh<D>& mesh, const P1Operators<D>& ops,
                  const Eigen::VectorXd& u, double level, const Points<D>& points, bool volume, int threads) {
  std::vector<double> values(u.data(), u.data() + u.size());
  for (double& v : values) v -= level;
  r.surface = extract_closed_surface(mesh, points, values, threads);
  attach_volume(r, mesh, values, volume);
  const Eigen::VectorXd g = ops.gradient_times(u);
  r.normals.resize(r.surface.vertices.size());
  for (std::size_t i = 0; i < r.surface.vertices.size(); ++i) {
    const EdgePoint& e = r.surface.sources[i];
    const Vec<D> n = (1.0 - e.t) * g.template segment<D>(D * e.a) + e.t * g.template segment<D>(D * e.b);
    r.normals[i] = n.norm() > 0.0 ? Vec<D>(n.normalized()) : Vec<D>::Zero();
  }
}

// PCA normals turned to agree with grad u at each point: outward wherever the front found the
// right side, which the topology of the front decides, not a centroid or a viewpoint.
template <int D>
Points<D> oriented_normals(const LocalSampling<D>& s, const std::vector<Location<D>>& at, const Eigen::VectorXd& gradient) {
  Points<D> n = s.normals;
  for (std::size_t i = 0; i < n.size(); ++i) {
    Vec<D> g = Vec<D>::Zero();
    for (int k = 0; k <= D; ++k) g += at[i].weights[k] * gradient.template segment<D>(D * at[i].vertices[k]);
    if (n[i].dot(g) < 0.0) n[i] = -n[i];
  }
  return n;
}

// The fitted surface: F replaces u on the band of vertices within band_factor local spacings of
// the front (u is a signed distance there after renormalisation), u keeps the sign beyond, so
// the front's topology decides everything the fit does not reach. Output vertices are then
// projected onto F itself, which removes the P1 interpolation error of the extraction.
template <int D>
void attach_fit(ReconstructionResult<D>& r, const SimplexMesh<D>& mesh, const VertexNeighbours& neighbours,
                const QuadricImplicit<D>& fit, const Eigen::VectorXd& u, const Eigen::VectorXd& scale,
                const Eigen::VectorXd& distance, double trust_factor, const std::vector<char>& over_hole,
                const std::vector<char>& near_opening, const NearestPointIndex<D>& data, const Points<D>& normals,
                bool volume, int threads) {
  // kUnsupported: past the largest empty disc (below); kHandover: where unsupported solid starts
  // going to the front.
  constexpr double band_factor = 3.0, kUnsupported = 1.5, kHandover = 1.0;
  const auto is_over_hole = [&](std::size_t v) { return !over_hole.empty() && over_hole[v]; };
  std::vector<double> values(u.data(), u.data() + u.size());
  Points<D> band;
  std::vector<Index> band_vertices;
  for (Eigen::Index v = 0; v < u.size(); ++v) {
    if (std::abs(u[v]) < band_factor * scale[v]) {
      band.push_back(mesh.vertices[v]);
      band_vertices.push_back(Index(v));
    }
  }
  std::vector<double> f;
  fit.evaluate(band, f, nullptr, threads);
  // Near a sealed opening, the share of F in values: the output is projected onto F only that
  // far (below), as F extrapolates where the front took over (measured: projected in full, the
  // front's cap over a tube's open end turned facets inside out). Elsewhere in full (measured:
  // limited everywhere, the clean sphere's Hausdorff distance x3.9).
  std::vector<double> fit_share;
  if (!near_opening.empty()) {
    fit_share.resize(values.size());
    for (std::size_t v = 0; v < values.size(); ++v) fit_share[v] = near_opening[v] ? 0.0 : 1.0;
  }
  auto limit_share = [&](Index v, double share) {
    if (!fit_share.empty() && near_opening[std::size_t(v)]) fit_share[std::size_t(v)] *= share;
  };
  // The settled front lies within gap_factor spacings of the data: a fit that disagrees with its
  // sign farther away than that is a failed local fit (creases, sparse spots), not the surface.
  // But in a gap between two facing sheets (sheet_gaps.h) the pinned cells of both sides hold a
  // bridge of front as deep as half the gap, which the fit cuts at any depth (measured: a bridge
  // 2.09 spacings deep kept the noisy, holey two spheres of seed 3 in one piece).
  std::vector<std::size_t> disputed;  // band slots where the fit says outside, deep in the front
  Points<D> queries;
  std::vector<double> query_distance, query_scale;
  for (std::size_t k = 0; k < band.size(); ++k) {
    const Index v = band_vertices[k];
    if (!(u[v] < 0.0 && f[k] >= 0.0 && std::abs(u[v]) >= trust_factor * scale[v])) continue;
    disputed.push_back(k);
    queries.push_back(band[k]);
    query_distance.push_back(distance[v]);
    query_scale.push_back(scale[v]);
  }
  const std::vector<char> in_gap = between_facing_sheets(data, normals, queries, query_distance, query_scale, threads);
  std::vector<char> cuts_bridge(band.size(), 0);
  for (std::size_t i = 0; i < disputed.size(); ++i) cuts_bridge[disputed[i]] = in_gap[i];
  for (std::size_t k = 0; k < band.size(); ++k) {
    const Index v = band_vertices[k];
    const bool trusted = (f[k] < 0.0) == (u[v] < 0.0) || std::abs(u[v]) < trust_factor * scale[v] || cuts_bridge[k];
    values[v] = trusted ? f[k] : u[v];
    if (!fit_share.empty() && near_opening[std::size_t(v)]) fit_share[std::size_t(v)] = trusted ? 1.0 : 0.0;
    auto hand_over = [&](double start) {
      const double w = std::clamp((distance[v] - start * scale[v]) / scale[v], 0.0, 1.0);
      values[v] = (1.0 - w) * values[v] + w * u[v];
      limit_share(v, 1.0 - w);
    };
    // Over a spanned hole nothing pins the front, and on a mesh the vertices next to the discs
    // keep a distance up to half an edge, through which a long run lets it creep into the solid
    // (measured: 0.13 into a sphere by step 26 of the holey two spheres, with a small handle in
    // its zero set, on 5 of 80 draws of the holey clouds). Where the fit adds solid there and
    // the front near v (u away) lies beyond the data's gap, the fit's solid stays. Not where
    // the front is at the data: a knife edge's rim discs run on past its tip, and so do the
    // fit's tangent planes (measured: without that test, fins 2.8 spacings past the 5k bunny's
    // ear tips).
    const bool adds_solid = values[v] < 0.0 && u[v] > 0.0;
    const bool hole = is_over_hole(std::size_t(v));
    if (hole && adds_solid && distance[v] - u[v] > trust_factor * scale[v]) continue;
    // Solid the fit adds outside the front must be near the data: the surface between random
    // samples lies within about 1.45 spacings of one (the largest empty disc, local_sampling.h),
    // and farther than one spacing from every sample on exp(-6) = 0.25% of its area. Where the
    // fit's surface passes farther from the data (nearer to v than half v's distance to the
    // data), it extrapolates: the tangent planes of a knife edge's sides run on past its tip
    // (measured on the bunny's ear). From 1 to 2 spacings the front takes over (measured: from
    // 1.5 to 2.5, the noisy bunny kept fins on its ear tips, Hausdorff distance up to 1.9e-2 of
    // the diagonal, 2.8x Poisson's with the true normals). A pit of the front deep inside the
    // data is left to the fit (there |F| is v's distance to the data: measured, the noisy two
    // spheres got a void). Near a sealed opening (a tube's open end, where the front closes
    // what the fits continue) the fit's distance is not asked: on the tube's axis past its end
    // the fits' surface lies a tube radius away, nearer than half the distance to the rim
    // (measured: a notched end, the tube's wall run on past the front's cap).
    if (adds_solid && (-values[v] < 0.5 * distance[v] || (!near_opening.empty() && near_opening[std::size_t(v)]))) {
      hand_over(kHandover);
    }
    // Over a spanned hole (where the rims' discs are nearer than the points) the front lies on
    // the discs, where the fit only extrapolates: from the gap to one spacing beyond it the
    // front takes over, gradually, so that the two zero sets join without a step (measured:
    // switching opened small handles at holes). Elsewhere only unsupported solid (above) is
    // handed over (measured: a handover wherever the fit is far from the data left the noisy
    // two spheres a third component in their neck).
    if (hole) hand_over(trust_factor);
  }
  // The fit moves the surface and may remove what the front got wrong (bridges across a neck it
  // had not cut, handles of a noisy front), but not join what the front kept apart: where the two
  // sides of a thin part or a crease lie within a fit's neighbourhood, its rounding opens handles
  // (measured: the cup with the 10x density gradient and the holey double torus got one each).
  // Far from the data (past the largest empty disc, as above) the front is held by curvature
  // alone and a guess: there the fit may join too (measured: a coarse front spanned a torus's
  // hole). Not over a spanned hole, where the rims' discs hold the front where the samples say
  // the surface goes (measured: the fit opened a handle across a hole on the noisy, holey
  // limb's thin part, seed 2, where the front had none). A void the merge cut off the outside
  // bounds no data and is filled (measured: with the fit's solid kept over every hole the front
  // had crept through, one 2 spacings wide inside the holey limb). Bubbles and specks narrower
  // than a spacing go last (measured: a one-vertex void in the noisy, holey limb and one in the
  // cup's wall).
  Eigen::VectorXd front = u;
  cap_at_walls<D>(mesh, front);
  cap_at_walls<D>(mesh, values);
  std::vector<char> may_join(values.size());
  for (std::size_t v = 0; v < values.size(); ++v) {
    may_join[v] = !is_over_hole(v) && distance[Eigen::Index(v)] > kUnsupported * scale[Eigen::Index(v)];
  }
  merge_without_joins<D>(mesh, front, values, may_join);
  fill_cut_off_voids<D>(mesh, front, values);
  absorb_small_parts<D>(mesh, neighbours, scale, values);
  r.surface = extract_closed_surface(mesh, data.points(), values, threads);
  const Points<D> extracted = fit_share.empty() ? Points<D>() : r.surface.vertices;
  r.normals = fit.project(r.surface.vertices, threads);
  for (std::size_t i = 0; i < extracted.size(); ++i) {
    const EdgePoint& e = r.surface.sources[i];
    const double share = (1.0 - e.t) * fit_share[std::size_t(e.a)] + e.t * fit_share[std::size_t(e.b)];
    if (share < 1.0) r.surface.vertices[i] = extracted[i] + share * (r.surface.vertices[i] - extracted[i]);
  }
  attach_volume(r, mesh, values, volume);
}

// The points (and their input indices) along a Z-order curve: a point's neighbours then lie
// near it in memory. In scanner or i.i.d. order every neighbourhood query of the sampling, the
// fit and the point location misses the cache (measured on 1M random bunny points: kd-tree 0.5
// -> 0.15 s, sampling 2.0 -> 1.2 s, the fits' construction 4.8 -> 2.4 s). 3D only: 2D clouds are
// mostly pixel lattices, small, and full of equidistant neighbours among which the order decides
// (the all-black test image's outline came out as 3 loops in Z-order instead of 1).
template <int D>
void in_z_order(const UnitBoxTransform<D>& box, Points<D>& points, std::vector<std::size_t>& kept) {
  const std::vector<Index> order = z_order<D>(box.to_unit(points));
  Points<D> sorted(points.size());
  std::vector<std::size_t> sorted_kept(kept.size());
  for (std::size_t i = 0; i < order.size(); ++i) {
    sorted[i] = points[std::size_t(order[i])];
    sorted_kept[i] = kept[std::size_t(order[i])];
  }
  points = std::move(sorted);
  kept = std::move(sorted_kept);
}

template <int D>
ReconstructionResult<D> run_pipeline(const Points<D>& input, const ReconstructionOptions& o,
                                     const ProgressCallback& callback, const SignedDistance<D>* custom_start) {
  check_options(o);
  // Before anything is allocated for the points.
  const Index max_vertices = o.max_vertices > 0 ? o.max_vertices : memory_limited_vertices<D>(o, input.size());
  ReconstructionResult<D> r;
  StageClock clock(r.seconds, r.stages);
  const Progress progress(callback);
  r.input_points = input.size();
  std::vector<std::size_t> kept;  // input index of each valid point
  for (std::size_t i = 0; i < input.size(); ++i) {
    if (input[i].allFinite()) kept.push_back(i);
  }
  Points<D> points = drop_non_finite(input);
  r.skipped_points = input.size() - points.size();
  require_spanning(points);
  auto box = UnitBoxTransform<D>::fit_ball(points, kDataRadius);
  if constexpr (D == 3) in_z_order(box, points, kept);
  NearestPointIndex<D> data(box.to_unit(points));
  clock.end("unit box");

  progress.update("sampling", -1.0);
  const double hole_radius = o.hole_radius >= 0.0 ? o.hole_radius : D == 3 ? kAutomaticHoleRadius : 0.0;
  // In 3D only the rim points carry discs (LocalSampling::rim); in 2D, where spanning is off
  // unless asked for, every point does.
  const bool rims_only = D == 3;
  const HeightFieldsAt fields = hole_radius <= 0.0 ? HeightFieldsAt::none : rims_only ? HeightFieldsAt::rims : HeightFieldsAt::all;
  LocalSampling<D> sampling = estimate_local_sampling(data, o.threads, fields);
  if (drop_isolated(sampling, o.outlier_factor, points, kept)) {
    // The box and every scale follow the data without them.
    r.outlier_points = input.size() - r.skipped_points - points.size();
    require_spanning(points);
    box = UnitBoxTransform<D>::fit_ball(points, kDataRadius);
    data = NearestPointIndex<D>(box.to_unit(points));
    sampling = estimate_local_sampling(data, o.threads, fields);
  }
  r.noise = median(sampling.noise);
  r.spacing = median(sampling.spacing);
  std::vector<double> point_scale = local_scales(sampling);
  clock.end("sampling");

  AdaptiveMeshOptions mo;
  mo.point_size = local_mesh_sizes<D>(point_scale, o.h_min, o.max_resolution);
  // A mesh coarser than the sampling (a clamp or a resolution asked for) resolves no finer
  // than its own size: tolerances, pins and fits follow the coarser of the two.
  for (std::size_t i = 0; i < point_scale.size(); ++i) point_scale[i] = std::max(point_scale[i], mo.point_size[i]);
  mo.h_min = *std::min_element(mo.point_size.begin(), mo.point_size.end());
  mo.h_max = std::max(o.h_max, mo.h_min);
  mo.grading = o.grading;
  mo.max_vertices = max_vertices;
  mo.threads = o.threads;
  r.h_min = mo.h_min;
  AdaptiveMesh<D> adaptive = build_adaptive_mesh(data, mo, progress);
  const SimplexMesh<D>& mesh = adaptive.mesh;
  r.mesh_vertices = Index(mesh.vertices.size());
  r.mesh_simplices = Index(mesh.simplices.size());
  clock.end("mesh");

  progress.update("distance", -1.0);
  std::vector<double> dist;
  std::vector<Index> nearest;
  data.query(mesh.vertices, dist, &nearest, o.threads);
  const std::size_t nv = mesh.vertices.size();
  // Per-vertex scales l and noise: those of the nearest data point.
  Eigen::VectorXd scale(nv), noise(nv);
  for (std::size_t v = 0; v < nv; ++v) {
    scale[v] = point_scale[nearest[v]];
    noise[v] = sampling.noise[nearest[v]];
  }
  const Eigen::VectorXd distance = Eigen::Map<const Eigen::VectorXd>(dist.data(), Eigen::Index(dist.size()));
  const VertexCells cells = pin_cells(scale, data.points().size(), dist, nearest, o.pin_factor);
  Eigen::VectorXd d = distance;  // what drives the front: zero where it is pinned
  const std::vector<Location<D>> at = locate_all(adaptive, data.points(), o.threads);
  {
    // Point location was the last use of the bisection forest: a third of the peak at 200k.
    const KuhnBisectionForest<D> forest = std::move(adaptive.forest);
    const std::vector<Index> nodes = std::move(adaptive.simplex_of_node);
    const std::vector<Index> renumbered = std::move(adaptive.vertex_of_node_vertex);
  }
  clock.end("distance");

  progress.update("operators", -1.0);
  VertexNeighbours neighbours;
  P1Operators<D> ops;
  {
    const SimplexGeometry<D> geometry = compute_simplex_geometry(mesh, o.solver == LinearSolver::gmres_reference);
    neighbours = vertex_neighbours(mesh, geometry, o.threads);
    ops = assemble_p1_operators(mesh, geometry, o.solver == LinearSolver::gmres_reference, &neighbours, o.threads);
  }
  clock.end("operators");
  progress.update("setup", -1.0);
  StepParameters step;
  step.alpha = o.alpha != 0.0 ? o.alpha : (o.initial_front == InitialFront::inside ? -2.0 : 2.0);
  step.time_step = o.time_step > 0.0 ? o.time_step : 0.2 / std::abs(step.alpha);
  if (o.curvature_weight >= 0.0) {
    step.curvature_weight = o.curvature_weight;
  } else {
    // Noise makes bumps of height sigma and width ~2 l; flattening them needs beta kappa >=
    // alpha sigma, i.e. beta ~ 2 |alpha| l^2: the weight grows towards that as sigma nears l.
    step.curvature_weights = std::abs(step.alpha) * scale.cwiseProduct(scale).cwiseProduct(
        (o.curvature_factor + 2.0 * noise.cwiseQuotient(scale).cwiseMin(1.0).array()).matrix());
    step.curvature_weight = std::abs(step.alpha) * o.curvature_factor * r.spacing * r.spacing;
  }
  step.solver_tolerance = o.solver_tolerance;
  step.solver = o.solver;
  const int interval = o.renormalization_interval > 0
                           ? o.renormalization_interval
                           : std::max(1, int(0.4 / (std::abs(step.alpha) * step.time_step) + 1e-9));
  r.time_step = step.time_step;
  r.alpha = step.alpha;
  r.curvature_weight = step.curvature_weight;
  // Tolerances: eps_i at the data, and between samples eps + the largest gap (gap_factor s).
  std::vector<double> eps(data.points().size()), reach(eps.size());
  for (std::size_t i = 0; i < eps.size(); ++i) {
    eps[i] = o.tolerance > 0.0 ? o.tolerance : o.tolerance_factor * point_scale[i];
    reach[i] = 0.5 * eps[i];
  }
  const double median_eps = median(eps);
  r.tolerance = median_eps / box.scale();
  // Measured against the driving d: over a spanned hole, the distance to the discs.
  Eigen::VectorXd front_tolerance(nv);
  for (std::size_t v = 0; v < nv; ++v) {
    front_tolerance[v] = (o.tolerance > 0.0 ? o.tolerance : o.tolerance_factor * scale[v]) + o.gap_factor * scale[v];
  }
  // Renormalisation band. From the tagged start the front moves at most |alpha| dt interval d
  // <= 0.4 (gap + 1) l between two renormalisations and the fit reads 3 l: 4 l + gap covers
  // both (over a spanned hole the start lies the gap above the discs, as elsewhere above the
  // data). The sphere starts cross the whole box: there, every vertex.
  const double band = o.initial_front == InitialFront::tagged && !custom_start
                          ? (4.0 + o.gap_factor) * scale.maxCoeff()
                          : std::numeric_limits<double>::infinity();
  std::vector<char> over_hole;  // the discs nearer than the points; empty without discs
  std::vector<char> near_opening;  // within the hole radius of a sealed opening; empty without
  if (hole_radius > 0.0) {
    // Spanned holes: the front is attracted to the tangent discs (tangent_discs.h),
    // wherever a hole's discs can reach and the start's gap (plus a margin) beyond. Within the
    // gap of the data the points themselves attract: there the discs add nothing over a hole,
    // and at a concave crease the tilted PCA planes of the points next to it span the groove
    // less than a gap from its tip (measured: a lid that stalled the double torus's front).
    std::vector<double> cap(nv);
    for (std::size_t v = 0; v < nv; ++v) cap[v] = (2.0 * o.gap_factor + 1.0) * scale[v] + hole_radius;
    const std::vector<double> discs = tangent_disc_distance(data, sampling, hole_radius,
                                                            mesh.vertices, dist, cap, o.threads, rims_only);
    over_hole.resize(nv);
    for (std::size_t v = 0; v < nv; ++v) over_hole[v] = discs[v] < dist[v];
    for (std::size_t v = 0; v < nv; ++v) {
      d[v] = std::min(dist[v], discs[v] + std::max(0.0, o.gap_factor * scale[v] - dist[v]));
    }
  }
  Eigen::VectorXd u(nv);
  if (custom_start) {
#pragma omp parallel for schedule(dynamic, 1024) num_threads(o.threads > 0 ? o.threads : omp_get_max_threads())
    for (std::ptrdiff_t i = 0; i < std::ptrdiff_t(nv); ++i) {
      try {  // an exception must not leave an OpenMP region: NaN, refused just below
        u[i] = (*custom_start)(box.from_unit(mesh.vertices[std::size_t(i)])) * box.scale();
      } catch (...) {
        u[i] = std::numeric_limits<double>::quiet_NaN();
      }
    }
    if (!u.allFinite() || u.minCoeff() >= 0.0 || u.maxCoeff() < 0.0) {
      throw InvalidInput("the initial function has no zero set inside the box around the data, or is not finite",
                         "pass a signed distance that is negative inside a closed curve / surface near the data");
    }
  } else if (o.initial_front == InitialFront::tagged) {
    const std::vector<double> guard =
        hole_radius > 0.0 ? half_longest_edges(mesh, neighbours, dist, ((o.gap_factor * scale).array() + hole_radius).matrix())
                            : std::vector<double>();
    SealedCavities sealed;
    u = tagged_start(mesh, neighbours, d, distance, scale, guard, o.gap_factor, band, hole_radius, sealed, o.threads);
    r.sealed_cavities = sealed.count;
    if (sealed.count > 0) near_opening = near_any(mesh.vertices, sealed.mouth, hole_radius, o.threads);
    r.tagged_start = u.size() > 0;
    const bool has_rims = std::find(sampling.rim.begin(), sampling.rim.end(), 1) != sampling.rim.end();
    if (D == 3 && r.tagged_start && !has_rims) u += o.start_offset * scale;
    if (!r.tagged_start) u = initial_field(mesh, data, InitialFront::enclosing, r.h_min);
  } else {
    u = initial_field(mesh, data, o.initial_front, r.h_min);
  }
  clock.end("setup");

  // For the two-sided drive and the rest past the data: the unit direction away from the
  // nearest data point per vertex.
  Points<D> away_from_data;
  const bool rest_past_data = o.rest_past_data && !o.two_sided;
  std::vector<char> near_hole;  // within a hole's radius of a vertex over it; empty without
  if (!over_hole.empty()) near_hole = near_any(mesh.vertices, over_hole, hole_radius, o.threads);
  if (o.two_sided || rest_past_data) {
    away_from_data.resize(nv, Vec<D>::Zero());
    for (std::size_t v = 0; v < nv; ++v) {
      if (dist[v] > 0.0) away_from_data[v] = (mesh.vertices[v] - data.points()[std::size_t(nearest[v])]) / dist[v];
    }
  }
  double front_distance = std::numeric_limits<double>::infinity();
  std::vector<char> pinned(at.size(), 0), held(nv, 0);
  step.held = &held;
  double first_residual = std::numeric_limits<double>::infinity();
  StallDetector stall({o.patience, o.stall_gain,
                       o.near_residual >= 0.0 ? o.near_residual : std::exp(std::abs(step.alpha) * step.time_step),
                       o.stall_stillness});
  double front_area = 0.0;  // of the last renormalised front: the displacement's denominator
  double progress_fraction = 0.0;
  Eigen::VectorXd best = u;
  double best_residual = std::numeric_limits<double>::infinity();
  bool best_front_ok = false;
  bool best_is_distance = false;
  try {
    // Its vectors are kept from step to step, released before each renormalisation (the
    // loop's peak) and freed before the fit.
    SemiImplicitStepper<D> stepper(ops);
    Eigen::VectorXd before;
    for (int n = 1; n <= o.max_iterations; ++n) {
      progress.update("solve", progress_fraction);
      SolverReport solve;
      before = u;
      if (o.two_sided) {
        stepper.advance(two_sided_drive(ops, d, away_from_data, u), u, step, &solve);
      } else if (rest_past_data) {
        const Eigen::VectorXd gap = o.gap_factor * scale;
        stepper.advance(drive_resting_past_data(ops, d, away_from_data, u, dist, gap, near_hole, step.alpha), u, step,
                        &solve);
      } else {
        stepper.advance(d, u, step, &solve);
      }
      const double displacement = front_displacement(before, u, ops.ball_measure, scale, D, front_area);
      r.solver_iterations += solve.iterations;
      clock.end("solve");
      if (o.pin_reached_data && !o.two_sided) pin_reached_data(at, cells, u, step.alpha, reach, pinned, d, held);
      if (n % interval == 0) {
        // Against the driving d: a piece of front held by pinned cells has settled, and what
        // it spans is the resolution limit, not a reason to go on. Not near spanned holes: a
        // front that crept past a hole's rim is the fit's to correct (attach_fit), and held 4
        // of 80 holey draws "not converged" (measured).
        stepper.release();  // the renormalisation is the loop's memory peak
        const RenormalizationReport<D> renormalized = renormalize(mesh, neighbours, u, band, o.threads);
        front_distance = max_front_distance(renormalized.front, d, front_tolerance, near_hole);
        front_area = front_measure(renormalized.front);
        clock.end("renormalize");
      }
      const std::vector<double> per_point = data_residuals(at, u, eps);
      const double data_residual = *std::max_element(per_point.begin(), per_point.end());
      // Converged when every data point is within its eps of the front and the front within
      // its tolerance of the data; the residual is the worse of the two, in tolerances.
      const double residual = std::max(data_residual, front_distance);
      r.residual_history.push_back(residual * median_eps / box.scale());
      // The data side falls geometrically (the front side can drop at once when a bubble
      // vanishes): progress is the fraction of log(first) it has covered, never receding.
      if (!std::isfinite(first_residual)) first_residual = data_residual;
      if (first_residual > 1.0) {
        progress_fraction = std::max(progress_fraction, std::clamp(std::log(first_residual / std::max(data_residual, 1.0)) /
                                                                       std::log(first_residual), 0.0, 1.0));
      }
      r.iterations = n;
      if (residual < best_residual) {
        best_residual = residual;
        best = u;
        best_is_distance = n % interval == 0;
        r.best_iteration = n;
        r.unreached_points = std::size_t(std::count_if(per_point.begin(), per_point.end(), [](double x) { return x > 1.0; }));
        best_front_ok = front_distance <= 1.0;
      }
      clock.end("stopping test");
      // Within tolerance; or, if asked, as good as a stall would leave it (below) without
      // waiting for the stall.
      const bool few_unreached = best_front_ok && double(r.unreached_points) <= o.unreached_fraction * double(at.size());
      if (best_residual <= 1.0 || (o.stop_when_few_unreached && r.best_iteration == n && few_unreached)) {
        r.status = ReconstructionStatus::converged;
        break;
      }
      r.stalled = stall.stalled(best_residual, r.best_iteration == n, displacement);
      if (r.stalled) {
        // Stalled: the front no longer gets closer to the last points. Curvature holds it short
        // of the tip of a sharp concave crease, pinned cells short of a slit between close
        // sheets; the fit places the surface there. A few such points do not make the run fail.
        if (few_unreached) r.status = ReconstructionStatus::converged;
        break;
      }
    }
  } catch (const Cancelled&) {
    r.status = ReconstructionStatus::cancelled;
  }
  r.residual = best_residual * median_eps / box.scale();
  r.noise /= box.scale();
  r.spacing /= box.scale();
  const Points<D> normals = oriented_normals(sampling, at, ops.gradient_times(best));
  r.point_normals.assign(input.size(), Vec<D>::Constant(std::numeric_limits<double>::quiet_NaN()));
  for (std::size_t i = 0; i < kept.size(); ++i) r.point_normals[kept[i]] = normals[i];
  progress.update(o.fit_surface ? "fit" : "extract", -1.0);
  if (o.fit_surface) {
    // The fit's band is measured in distances to the front: the best iterate as one.
    if (!best_is_distance) renormalize(mesh, neighbours, best, band, o.threads);
    ops = P1Operators<D>();  // done with G: the fit's index and blends reuse its memory (the peak)
    // The fits widen with the noise, not with the bend that PCA's thickness also counts; both
    // read the same neighbours (freed before the blends).
    const QuadricImplicit<D> fit = [&] {
      const int k = std::min<int>(QuadricImplicit<D>::kFitNeighbours, int(data.points().size()));
      LargeVector<Index> nearest;
      data.query_k(data.points(), k, nearest, o.threads);
      const std::vector<double> fit_noise = residual_noise(data.points(), normals, nearest, k, o.threads);
      return QuadricImplicit<D>(data, normals, point_scale, fit_noise, o.threads, &nearest);
    }();
    attach_fit(r, mesh, neighbours, fit, best, scale, distance, o.gap_factor, over_hole, near_opening, data, normals,
               o.volume_mesh, o.threads);
    clock.end("fit");
  } else {
    r.output_level = o.level_through_data ? median_on_data(at, best) / box.scale() : 0.0;
    attach_front(r, mesh, ops, best, r.output_level * box.scale(), data.points(), o.volume_mesh, o.threads);
    clock.end("extract");
  }
  for (auto& x : r.surface.vertices) x = box.from_unit(x);
  for (auto& x : r.volume.vertices) x = box.from_unit(x);
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
  if (options.alpha == 0.0 && !options.two_sided) {
    throw InvalidInput("a custom start needs an explicit alpha, or two-sided attraction",
                       "set alpha > 0 (e.g. 2) if the start encloses the data, < 0 (e.g. -2) if it lies inside, "
                       "or two_sided if it crosses the data");
  }
  ReconstructionOptions o = options;
  o.initial_front = options.alpha >= 0.0 ? InitialFront::enclosing : InitialFront::inside;
  return cancellable_pipeline<D>(points, o, progress, &initial);
}

template ReconstructionResult<2> reconstruct_from<2>(const Points<2>&, const SignedDistance<2>&,
                                                     const ReconstructionOptions&, const ProgressCallback&);
template ReconstructionResult<3> reconstruct_from<3>(const Points<3>&, const SignedDistance<3>&,
                                                     const ReconstructionOptions&, const ProgressCallback&);
template ReconstructionResult<2> reconstruct<2>(const Points<2>&, const ReconstructionOptions&, const ProgressCallback&);
template ReconstructionResult<3> reconstruct<3>(const Points<3>&, const ReconstructionOptions&, const ProgressCallback&);

}  // namespace lsr
