// SPDX-License-Identifier: BSD-3-Clause
/// @file open_side_closure.cpp
#include "start/open_side_closure.h"

#include "graph/shortest_paths.h"

#include "mesh/vertices_near.h"
#include "start/outside_flood_fill.h"
#include "start/normal_propagation.h"
#include "start/winding_number.h"
#include "thread_count.h"

#include "sampling/local_sampling.h"

#include <omp.h>

#include <limits>
#include <memory>
#include <utility>

namespace lsr::detail {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr int kSideNeighbours = 16;
// The flood's edge: reached vertices up to kBandWidth local scales past its gap. A point looks
// for it within that radius, which sees across a sheet (and registration layers) thinner than
// kBandWidth scales but not across a closed thin wall (calibrated).
constexpr double kBandWidth = 1.5;
constexpr int kSidePasses = 16;
constexpr std::size_t kGateStride = 8;
// Path lengths from the walls to a point's two sides closer than this share of their sum say
// nothing of which side is out (calibrated, docs/calibration.md).
constexpr double kAmbiguousPaths = 0.2;
// At least this share of the two-sided points with ambiguous paths: the paths tell no side
// anywhere, as on a single view, whose sheet the flood reaches round its rim from both sides
// alike (calibrated).
constexpr double kSingleViewShare = 0.85;
// The pocket's median winding number above which the data are closed up to holes (calibrated).
constexpr double kClosedWinding = 0.95;
// The pocket's winding number on a single view. A view sees the half of a body that faces it,
// which covers less than half of the directions from the body's unseen half: {w > 1/2} ends at
// the disc spanning the view's rim, and gaps in the view cut it into pieces. From the far pole of a sphere seen from one side, the seen half covers the cone
// of 45 degrees round the axis, (1 - cos 45 deg) / 2 = 0.1464 of the directions, and more from
// every other point of the ball: {w > 0.1464} is the whole ball.
constexpr double kSingleViewWinding = 0.1464;

// Whether a two-sided point's path lengths from the walls say nothing of which side is out.
inline bool ambiguous_paths(double g_plus, double g_minus) {
  return std::abs(g_plus - g_minus) < kAmbiguousPaths * (g_plus + g_minus);
}

// Which side of its nearest point a band vertex lies on: +1 / -1 along the normal, 0 when it
// lies off the normal's axis (more than 60 degrees), where the side says nothing.
template <int D>
int side_of(const Vec<D>& x, const Vec<D>& p, const Vec<D>& n) {
  const Vec<D> e = x - p;
  const double c = e.dot(n), r = e.norm();
  if (r == 0.0 || std::abs(c) < 0.5 * r) return 0;
  return c > 0.0 ? 1 : -1;
}

// On a single view the paths tell no side, and the shorter one flips the senses at random along
// the sheet. There the senses follow the normals' smoothest paths instead
// (normal_propagation.h), each tree's
// overall sense the paths' vote, weighted by how much they differ.
template <int D>
void propagate_single_view_senses(const Points<D>& points, const Points<D>& normals, const LargeVector<Index>& knn, const std::vector<double>& g_plus,
                                  const std::vector<double>& g_minus, std::vector<signed char>& sense) {
  const PropagatedSenses tree = propagate_senses<D>(points, normals, knn, kSideNeighbours);
  std::vector<double> vote(std::size_t(tree.parts), 0.0);
  for (std::size_t p = 0; p < normals.size(); ++p) {
    const double a = g_plus[p], b = g_minus[p];
    if (a == kInf && b == kInf) continue;
    const double weight = a == kInf || b == kInf ? 1.0 : std::abs(a - b) / (a + b);
    vote[std::size_t(tree.part[p])] += weight * (a <= b ? 1.0 : -1.0) * tree.sense[p];
  }
  for (std::size_t p = 0; p < normals.size(); ++p) {
    sense[p] = static_cast<signed char>(vote[std::size_t(tree.part[p])] >= 0.0 ? tree.sense[p] : -tree.sense[p]);
  }
}

// Path length from the walls through the reached vertices, over the mesh's edges.
template <int D>
std::vector<double> distance_from_walls(const SimplexMesh<D>& mesh, const VertexNeighbours& n, const std::vector<char>& reached) {
  std::vector<char> walls(mesh.vertices.size(), 0);
  for (std::size_t v = 0; v < walls.size(); ++v) walls[v] = reached[v] && on_wall<D>(mesh.vertices[v]);
  return shortest_paths(mesh.vertices, n.offsets, n.neighbours, walls, reached);
}

// The flood's edge seen from the data: per point, the shortest path from the walls to the
// reached vertices within a band past the gap the flood keeps, on each side of the point
// (along its normal). A noisy or sparse sheet's two sides are nearest to different points, so
// each point looks for the edge within a radius, not among the vertices nearest to it.
template <int D>
class FloodSides {
 public:
  FloodSides(const SimplexMesh<D>& mesh, const NearestPointIndex<D>& data, const Points<D>& normals,
             const std::vector<double>& point_scale, const Eigen::VectorXd& vertex_scale, const std::vector<double>& dist,
             double gap_factor, const std::vector<char>& reached, int threads)
      : mesh_(mesh), data_(data), normals_(normals), point_scale_(point_scale), gap_factor_(gap_factor), threads_(threads) {
    Points<D> band;
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
      if (reached[v] && dist[v] <= (gap_factor + kBandWidth) * vertex_scale[Eigen::Index(v)]) {
        band.push_back(mesh.vertices[v]);
        band_vertex_.push_back(Index(v));
      }
    }
    if (!band.empty()) edge_ = std::make_unique<NearestPointIndex<D>>(std::move(band));
  }

  bool empty() const { return !edge_; }

  // Without path lengths (g empty) only whether each side was reached, on every stride-th point.
  void find(const std::vector<double>& g, std::size_t stride) {
    const Points<D>& points = data_.points();
    const std::size_t np = points.size();
    plus.assign(np, kInf);
    minus.assign(np, kInf);
#pragma omp parallel num_threads(thread_count(threads_))
    {
      std::vector<Index> found;
#pragma omp for schedule(dynamic, 256)
      for (std::ptrdiff_t i = 0; i < std::ptrdiff_t((np + stride - 1) / stride); ++i) {
        const auto p = std::size_t(i) * stride;
        edge_->within(points[p], (gap_factor_ + kBandWidth) * point_scale_[p], found);
        for (const Index k : found) {
          const auto v = std::size_t(band_vertex_[std::size_t(k)]);
          const int s = side_of<D>(mesh_.vertices[v], points[p], normals_[p]);
          const double length = g.empty() ? 0.0 : g[v];
          if (s > 0) plus[p] = std::min(plus[p], length);
          if (s < 0) minus[p] = std::min(minus[p], length);
        }
      }
    }
  }

  // Counts the points found on either side and on both, and says whether the data are open.
  bool count(std::size_t stride, OpenSides& out) const {
    out.seen_points = out.two_sided_points = 0;
    for (std::size_t p = 0; p < plus.size(); p += stride) {
      out.seen_points += plus[p] < kInf || minus[p] < kInf;
      out.two_sided_points += plus[p] < kInf && minus[p] < kInf;
    }
    return double(out.two_sided_points) >= kOpenSideShare * double(out.seen_points);
  }

  std::vector<double> plus, minus;  // #N path lengths to the edge on each side; infinite: not found

 private:
  const SimplexMesh<D>& mesh_;
  const NearestPointIndex<D>& data_;
  const Points<D>& normals_;
  const std::vector<double>& point_scale_;
  double gap_factor_;
  int threads_;
  std::vector<Index> band_vertex_;
  std::unique_ptr<NearestPointIndex<D>> edge_;
};

// Whether the pocket is the inside of data closed up to holes: seen from its typical point, the
// data cover nearly every direction (winding number 1; an open side leaves a solid angle
// uncovered). Where a hole lets the flood behind the data, both sides can lie at nearly the
// same distance from the walls; those points take the side a flood the discs stop reached.
template <int D>
bool closed_up_to_holes(const SimplexMesh<D>& mesh, const Points<D>& points, const Points<D>& normals, const Points<D>& outward,
                        const std::vector<double>& area, const std::vector<double>& g_plus, const std::vector<double>& g_minus,
                        const std::vector<signed char>& disc_sides, const std::vector<char>& reached, int threads) {
  Points<D> oriented = outward;
  for (std::size_t p = 0; p < points.size(); ++p) {
    const bool both = g_plus[p] < kInf && g_minus[p] < kInf;
    if (both && disc_sides[p] != 0 && ambiguous_paths(g_plus[p], g_minus[p])) {
      oriented[p] = double(disc_sides[p]) * normals[p];
    }
  }
  const WindingNumber<D> winding(points, oriented, area);
  const std::size_t nv = mesh.vertices.size();
  std::vector<double> w(nv, 0.0);
#pragma omp parallel for schedule(dynamic, 1024) num_threads(thread_count(threads))
  for (std::ptrdiff_t v = 0; v < std::ptrdiff_t(nv); ++v) {
    if (reached[std::size_t(v)]) w[std::size_t(v)] = winding.at(mesh.vertices[std::size_t(v)]);
  }
  std::vector<double> inside;
  for (const double x : w) {
    if (x > 0.5) inside.push_back(x);
  }
  return !inside.empty() && median(inside) >= kClosedWinding;
}

}  // namespace

template <int D>
std::vector<signed char> one_sided_points(const SimplexMesh<D>& mesh, const NearestPointIndex<D>& data, const Points<D>& normals,
                                          const std::vector<double>& point_scale, const Eigen::VectorXd& vertex_scale,
                                          const std::vector<double>& dist, double gap_factor, const std::vector<char>& reached,
                                          int threads) {
  std::vector<signed char> out(data.points().size(), 0);
  FloodSides<D> sides(mesh, data, normals, point_scale, vertex_scale, dist, gap_factor, reached, threads);
  if (sides.empty()) return out;
  sides.find({}, 1);
  for (std::size_t p = 0; p < out.size(); ++p) {
    const bool plus = sides.plus[p] < kInf, minus = sides.minus[p] < kInf;
    if (plus != minus) out[p] = plus ? 1 : -1;
  }
  return out;
}

template <int D>
OpenSides close_open_sides(const SimplexMesh<D>& mesh, const VertexNeighbours& neighbours, const NearestPointIndex<D>& data,
                           const Points<D>& normals, const std::vector<double>& point_scale, const Eigen::VectorXd& vertex_scale,
                           const std::vector<double>& dist, const std::vector<Index>& nearest, double gap_factor,
                           std::vector<char>& reached, const DiscSides& disc_sides, int threads) {
  OpenSides out;
  const Points<D>& points = data.points();
  const std::size_t nv = mesh.vertices.size(), np = points.size();
  FloodSides<D> sides(mesh, data, normals, point_scale, vertex_scale, dist, gap_factor, reached, threads);
  if (sides.empty()) return out;
  // The gate on every kGateStride-th point: enough to tell closed data (a share of 5% from 1/8
  // of 20k points has a standard error of 0.4%), at an eighth of the cost (0.18 s of every
  // 200k-point run when all points looked).
  sides.find({}, kGateStride);
  if (!sides.count(kGateStride, out)) {
    out.seen_points = out.two_sided_points = 0;
    return out;
  }
  sides.find(distance_from_walls(mesh, neighbours, reached), 1);
  sides.count(1, out);
  const std::vector<double>& g_plus = sides.plus;
  const std::vector<double>& g_minus = sides.minus;

  // Every point oriented: away from the data towards the side the flood reached, the nearer
  // one to the walls if it reached both; points it reached on neither side take the sense of
  // their oriented neighbours.
  LargeVector<Index> knn;
  data.query_k(points, kSideNeighbours, knn);
  std::vector<signed char> sense(np, 0);
  for (std::size_t p = 0; p < np; ++p) {
    if (g_plus[p] < kInf || g_minus[p] < kInf) sense[p] = g_plus[p] <= g_minus[p] ? 1 : -1;
  }
  for (int pass = 0; pass < kSidePasses; ++pass) {
    bool changed = false;
    for (std::size_t p = 0; p < np; ++p) {
      if (sense[p] != 0) continue;
      double vote = 0.0;
      for (int j = 0; j < kSideNeighbours; ++j) {
        const auto q = std::size_t(knn[p * kSideNeighbours + std::size_t(j)]);
        vote += sense[q] * (normals[q].dot(normals[p]) >= 0.0 ? 1.0 : -1.0);
      }
      if (vote != 0.0) {
        sense[p] = vote > 0.0 ? 1 : -1;
        changed = true;
      }
    }
    if (!changed) break;
  }
  std::size_t guesses = 0;
  for (std::size_t p = 0; p < np; ++p) guesses += g_plus[p] < kInf && g_minus[p] < kInf && ambiguous_paths(g_plus[p], g_minus[p]);
  const bool single_view = double(guesses) >= kSingleViewShare * double(out.two_sided_points);
  if (single_view) propagate_single_view_senses(points, normals, knn, g_plus, g_minus, sense);
  Points<D> outward(np);
  std::vector<double> area(np);
  for (std::size_t p = 0; p < np; ++p) {
    outward[p] = double(sense[p]) * normals[p];
    const auto last = std::size_t(knn[p * kSideNeighbours + kSideNeighbours - 1]);
    area[p] = kPi * (points[last] - points[p]).squaredNorm() / double(kSideNeighbours - 1);
  }
  if (disc_sides && closed_up_to_holes(mesh, points, normals, outward, area, g_plus, g_minus, disc_sides(), reached, threads)) {
    out.seen_points = out.two_sided_points = 0;
    return out;
  }
  // The pocket: what the flood reached where the oriented data wind around it more than half
  // (on a single view, more than the far side of a ball seen from one side).
  const WindingNumber<D> winding(points, outward, area);
  const double pocket_winding = single_view ? kSingleViewWinding : 0.5;
  std::vector<char> pocket(nv, 0);
#pragma omp parallel for schedule(dynamic, 1024) num_threads(thread_count(threads))
  for (std::ptrdiff_t v = 0; v < std::ptrdiff_t(nv); ++v) {
    if (reached[std::size_t(v)]) pocket[std::size_t(v)] = winding.at(mesh.vertices[std::size_t(v)]) > pocket_winding;
  }
  for (std::size_t v = 0; v < nv; ++v) {
    if (pocket[v]) reached[v] = 0;
  }
  // Behind a two-sided sheet the front is held too: where no pocket closed (a thin part seen
  // from one side), the sheet stays a thin closed body instead of a shell the front pinches.
  // Not behind points whose paths are ambiguous, unless nearly all are (a single view): their
  // side is a guess, wrong on grazing walls next to an unseen side (the inner wall of a ring's
  // hole), where the held band becomes a web across the hole.
  // The front is kept (not fitted) there and over the membrane: the pocket's surroundings
  // farther from the data than the band, and its vertices' neighbours (far from the data the
  // mesh's edges outgrow that radius, and a front crossing one out of the pocket lay beyond it:
  // the stopping test counted it as front far from the data, "not converged").
  out.held = pocket;
  std::vector<char> near_pocket = near_any(mesh.vertices, pocket, (gap_factor + kBandWidth) * median(point_scale), threads);
  for (std::size_t v = 0; v < nv; ++v) {
    if (!pocket[v]) continue;
    for (Index k = neighbours.offsets[v]; k < neighbours.offsets[v + 1]; ++k) near_pocket[std::size_t(neighbours.neighbours[std::size_t(k)])] = 1;
  }
  out.kept.assign(nv, 0);
  for (std::size_t v = 0; v < nv; ++v) {
    const auto p = std::size_t(nearest[v]);
    const bool in_band = dist[v] <= (gap_factor + kBandWidth) * vertex_scale[Eigen::Index(v)];
    const bool sided = g_plus[p] < kInf && g_minus[p] < kInf && (single_view || !ambiguous_paths(g_plus[p], g_minus[p]));
    if (in_band && sided && (mesh.vertices[v] - points[p]).dot(outward[p]) < 0.0) out.held[v] = 1;
    out.kept[v] = out.held[v] || (near_pocket[v] && !in_band);
  }
  return out;
}

template OpenSides close_open_sides<3>(const SimplexMesh<3>&, const VertexNeighbours&,
                                       const NearestPointIndex<3>&, const Points<3>&, const std::vector<double>&,
                                       const Eigen::VectorXd&, const std::vector<double>&, const std::vector<Index>&, double,
                                       std::vector<char>&, const DiscSides&, int);
template std::vector<signed char> one_sided_points<3>(const SimplexMesh<3>&, const NearestPointIndex<3>&, const Points<3>&,
                                                      const std::vector<double>&, const Eigen::VectorXd&,
                                                      const std::vector<double>&, double, const std::vector<char>&, int);

}  // namespace lsr::detail
