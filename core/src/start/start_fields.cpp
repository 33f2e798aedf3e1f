// SPDX-License-Identifier: BSD-3-Clause
/// @file start_fields.cpp
#include "start/start_fields.h"

#include "mesh/vertices_near.h"
#include "start/nested_outsides.h"
#include "start/occupancy_start.h"
#include "start/open_side_closure.h"
#include "thread_count.h"

#include "evolution/renormalization.h"
#include "lsrecon/core/errors.h"
#include "start/outside_flood_fill.h"

#include <omp.h>

#include <algorithm>
#include <limits>

namespace lsr::detail {

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

template <int D>
Eigen::VectorXd flood_distance(const SimplexMesh<D>& mesh, const VertexNeighbours& neighbours, const std::vector<char>& flooded,
                               double band, int threads) {
  Eigen::VectorXd u(Eigen::Index(flooded.size()));
  for (std::size_t v = 0; v < flooded.size(); ++v) u[v] = flooded[v] ? 1.0 : -1.0;
  if (u.minCoeff() > 0.0 || u.maxCoeff() < 0.0) return {};
  renormalize(mesh, neighbours, u, band, threads);
  return u;
}

// Open sides are found on a flood the tangent discs do not stop. Discs that span an open side
// keep the flood out of it, and the front then crumples over them and tunnels between the scan
// lines from inside. Data closed up to holes the discs span are left to the
// discs (close_open_sides: the pocket's membrane is flat where the discs follow the surface).
template <int D>
void find_open_sides(const SimplexMesh<D>& mesh, const VertexNeighbours& neighbours, const Eigen::VectorXd& distance,
                     const Eigen::VectorXd& scale, double gap_factor, bool discs, const OpenSideInputs<D>& open,
                     std::vector<char>& reached, OpenSides& closed, int threads) {
  const auto close = [&](std::vector<char>& flood, const DiscSides& disc_sides) {
    return close_open_sides(mesh, neighbours, open.data, open.normals, open.point_scale, scale, open.dist, open.nearest, gap_factor,
                            flood, disc_sides, threads);
  };
  const std::size_t n = mesh.vertices.size();
  if (discs) {
    std::vector<char> passable(n);
    for (std::size_t v = 0; v < n; ++v) passable[v] = distance[Eigen::Index(v)] > gap_factor * scale[Eigen::Index(v)];
    std::vector<char> plain = flood_from_walls(mesh, passable);
    const std::vector<char> before = plain;
    closed = close(plain, [&] {
      return one_sided_points(mesh, open.data, open.normals, open.point_scale, scale, open.dist, gap_factor, reached, threads);
    });
    if (!closed.held.empty()) {
      for (std::size_t v = 0; v < n; ++v) {
        if (before[v] && !plain[v]) reached[v] = 0;
      }
      return;
    }
  }
  closed = close(reached, {});  // without discs, or closed without them or up to holes
}

template <int D>
Eigen::VectorXd tagged_start(const SimplexMesh<D>& mesh, const VertexNeighbours& neighbours, const Eigen::VectorXd& attraction,
                             const Eigen::VectorXd& distance, const Eigen::VectorXd& scale,
                             const std::vector<double>& edge_guard, double gap_factor, double band, double seal_radius,
                             SealedCavities& sealed, const OpenSideInputs<D>* open, OpenSides& closed, int threads) {
  const std::size_t n = mesh.vertices.size();
  std::vector<char> passable(n);
  for (std::size_t v = 0; v < n; ++v) {
    const double gap = gap_factor * scale[v];
    passable[v] = attraction[v] > gap &&
                  (edge_guard.empty() || attraction[v] > std::min(edge_guard[v], distance[v] - gap));
  }
  const std::vector<Index> free_region = vertex_components(mesh, passable);
  std::vector<char> reached = flood_from_walls(mesh, free_region);
  const std::vector<char> nested =
      open ? nested_outsides(mesh, neighbours, free_region, reached, open->data.points(), open->normals, open->nearest)
           : std::vector<char>(n, 0);
  sealed = seal_cavities(mesh, neighbours, attraction, seal_radius, reached);
  if constexpr (D == 3) {
    if (open) find_open_sides(mesh, neighbours, distance, scale, gap_factor, !edge_guard.empty(), *open, reached, closed, threads);
  }
  // Last: sealing would take them back, and the open sides' paths run from the walls.
  for (std::size_t v = 0; v < n; ++v) reached[v] = reached[v] || nested[v];
  return flood_distance(mesh, neighbours, reached, band, threads);
}

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

template <int D>
StartField<D> start_field(const SimplexMesh<D>& mesh, const VertexNeighbours& neighbours, const NearestPointIndex<D>& data,
                          const LocalSampling<D>& sampling, const Eigen::VectorXd& attraction, const Eigen::VectorXd& distance,
                          const std::vector<double>& dist, const Eigen::VectorXd& scale, const ReconstructionOptions& o,
                          double hole_radius, double band, double h_min, const SignedDistance<D>* custom_start,
                          const UnitBoxTransform<D>& box, const OpenSideInputs<D>* open) {
  StartField<D> s;
  Eigen::VectorXd& u = s.u;
  const std::size_t nv = mesh.vertices.size();
  u.resize(Eigen::Index(nv));
  if (custom_start) {
#pragma omp parallel for schedule(dynamic, 1024) num_threads(thread_count(o.limits.threads))
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
  } else if (o.start.initial_front == InitialFront::tagged) {
    const std::vector<double> guard =
        hole_radius > 0.0 ? half_longest_edges(mesh, neighbours, dist, ((o.sampling.gap_factor * scale).array() + hole_radius).matrix())
                            : std::vector<double>();
    SealedCavities sealed;
    OpenSides closed;
    u = tagged_start(mesh, neighbours, attraction, distance, scale, guard, o.sampling.gap_factor, band, hole_radius, sealed,
                     open, closed, o.limits.threads);
    s.open_side_points = closed.two_sided_points;
    s.held = std::move(closed.held);
    s.kept = std::move(closed.kept);
    s.sealed_cavities = sealed.count;
    if (sealed.count > 0) s.near_opening = near_any(mesh.vertices, sealed.mouth, hole_radius, o.limits.threads);
    s.tagged = u.size() > 0;
    const bool has_rims = std::find(sampling.rim.begin(), sampling.rim.end(), 1) != sampling.rim.end();
    if (D == 3 && s.tagged && !has_rims) u += o.start.start_offset * scale;
    if (!s.tagged) u = initial_field(mesh, data, InitialFront::enclosing, h_min);
  } else if (o.start.initial_front == InitialFront::occupancy) {
    // The points' scales raised to the mesh (OpenSideInputs) when given; the spacing is a lower bound.
    const std::vector<double>& point_scale = open ? open->point_scale : sampling.spacing;
    s.occupancy = occupancy_start(mesh.vertices, data, sampling.normals, sampling.noise, point_scale, o.limits.threads);
    u = s.occupancy;
    renormalize(mesh, neighbours, u, band, o.limits.threads);
  } else {
    u = initial_field(mesh, data, o.start.initial_front, h_min);
  }
  return s;
}

template <int D>
void close_pocket(const StartField<D>& start, Eigen::VectorXd& attraction, std::vector<char>& near_hole,
                  std::vector<char>& near_opening) {
  if (start.held.empty()) return;
  const auto add = [&](std::vector<char>& flags) {
    if (flags.empty()) flags.assign(start.kept.size(), 0);
    for (std::size_t v = 0; v < flags.size(); ++v) flags[v] = flags[v] || start.kept[v];
  };
  add(near_hole);
  add(near_opening);
  for (std::size_t v = 0; v < start.held.size(); ++v) {
    if (start.held[v]) attraction[Eigen::Index(v)] = 0.0;
  }
}

template void close_pocket<2>(const StartField<2>&, Eigen::VectorXd&, std::vector<char>&, std::vector<char>&);
template void close_pocket<3>(const StartField<3>&, Eigen::VectorXd&, std::vector<char>&, std::vector<char>&);
template StartField<2> start_field<2>(const SimplexMesh<2>&, const VertexNeighbours&, const NearestPointIndex<2>&,
                                      const LocalSampling<2>&, const Eigen::VectorXd&, const Eigen::VectorXd&,
                                      const std::vector<double>&, const Eigen::VectorXd&, const ReconstructionOptions&, double,
                                      double, double, const SignedDistance<2>*, const UnitBoxTransform<2>&, const OpenSideInputs<2>*);
template StartField<3> start_field<3>(const SimplexMesh<3>&, const VertexNeighbours&, const NearestPointIndex<3>&,
                                      const LocalSampling<3>&, const Eigen::VectorXd&, const Eigen::VectorXd&,
                                      const std::vector<double>&, const Eigen::VectorXd&, const ReconstructionOptions&, double,
                                      double, double, const SignedDistance<3>*, const UnitBoxTransform<3>&, const OpenSideInputs<3>*);
template Eigen::VectorXd initial_field<2>(const SimplexMesh<2>& mesh, const NearestPointIndex<2>& data,
                              InitialFront front, double h_min);
template Eigen::VectorXd initial_field<3>(const SimplexMesh<3>& mesh, const NearestPointIndex<3>& data,
                              InitialFront front, double h_min);
template Eigen::VectorXd flood_distance<2>(const SimplexMesh<2>& mesh, const VertexNeighbours& neighbours, const std::vector<char>& flooded,
                               double band, int threads);
template Eigen::VectorXd flood_distance<3>(const SimplexMesh<3>& mesh, const VertexNeighbours& neighbours, const std::vector<char>& flooded,
                               double band, int threads);
template Eigen::VectorXd tagged_start<2>(const SimplexMesh<2>& mesh, const VertexNeighbours& neighbours, const Eigen::VectorXd& attraction,
                             const Eigen::VectorXd& distance, const Eigen::VectorXd& scale,
                             const std::vector<double>& edge_guard, double gap_factor, double band, double seal_radius,
                             SealedCavities& sealed, const OpenSideInputs<2>* open, OpenSides& closed, int threads);
template Eigen::VectorXd tagged_start<3>(const SimplexMesh<3>& mesh, const VertexNeighbours& neighbours, const Eigen::VectorXd& attraction,
                             const Eigen::VectorXd& distance, const Eigen::VectorXd& scale,
                             const std::vector<double>& edge_guard, double gap_factor, double band, double seal_radius,
                             SealedCavities& sealed, const OpenSideInputs<3>* open, OpenSides& closed, int threads);
template std::vector<double> half_longest_edges<2>(const SimplexMesh<2>& mesh, const VertexNeighbours& n,
                                       const std::vector<double>& distance, const Eigen::VectorXd& near);
template std::vector<double> half_longest_edges<3>(const SimplexMesh<3>& mesh, const VertexNeighbours& n,
                                       const std::vector<double>& distance, const Eigen::VectorXd& near);

}  // namespace lsr::detail
