// SPDX-License-Identifier: BSD-3-Clause
/// @file exact_self_intersections.cpp
#include "checks/exact_self_intersections.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>

#include <limits>
#include <utility>

namespace lsr::testing {

std::size_t cgal_self_intersections(const Points<3>& vertices, const std::vector<std::array<Index, 3>>& triangles) {
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
  Mesh mesh;
  std::vector<Mesh::Vertex_index> at;
  at.reserve(vertices.size());
  for (const auto& p : vertices) at.push_back(mesh.add_vertex(Kernel::Point_3(p[0], p[1], p[2])));
  for (const auto& t : triangles) {
    const Mesh::Face_index f = mesh.add_face(at[std::size_t(t[0])], at[std::size_t(t[1])], at[std::size_t(t[2])]);
    if (f == Mesh::null_face()) return std::numeric_limits<std::size_t>::max();
  }
  std::vector<std::pair<Mesh::Face_index, Mesh::Face_index>> pairs;
  CGAL::Polygon_mesh_processing::self_intersections(mesh, std::back_inserter(pairs));
  return pairs.size();
}

std::size_t cgal_self_intersections(const Points<2>& vertices, const std::vector<std::array<Index, 2>>& segments) {
  using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
  using Box = CGAL::Box_intersection_d::Box_with_handle_d<double, 2, std::size_t, CGAL::Box_intersection_d::ID_EXPLICIT>;
  const auto point = [&](Index v) { return Kernel::Point_2(vertices[std::size_t(v)][0], vertices[std::size_t(v)][1]); };
  std::vector<Box> boxes;
  for (std::size_t s = 0; s < segments.size(); ++s) {
    const auto b = point(segments[s][0]).bbox() + point(segments[s][1]).bbox();
    boxes.emplace_back(b, s);
  }
  std::size_t count = 0;
  const auto check = [&](const Box& a, const Box& b) {
    const auto& f = segments[a.handle()];
    const auto& g = segments[b.handle()];
    const Kernel::Segment_2 sf(point(f[0]), point(f[1])), sg(point(g[0]), point(g[1]));
    const auto meet = CGAL::intersection(sf, sg);
    if (!meet) return;
    // Sharing an end, they may meet there and nowhere else.
    const Kernel::Point_2* p = boost::get<Kernel::Point_2>(&*meet);
    const bool shared_end = p != nullptr && (f[0] == g[0] || f[0] == g[1] || f[1] == g[0] || f[1] == g[1]) &&
                            ((f[0] == g[0] || f[0] == g[1]) ? *p == point(f[0]) : *p == point(f[1]));
    if (!shared_end) ++count;
  };
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), check);
  return count;
}

}  // namespace lsr::testing
