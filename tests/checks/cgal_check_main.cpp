// SPDX-License-Identifier: BSD-3-Clause
/// @file cgal_check_main.cpp
/// @brief lsrecon-cgal-check MESH...: for each mesh file (any format lsrecon writes or reads),
/// the pairs of triangles that intersect as CGAL counts them, beside lsrecon's own count: the
/// independent check of "embedded", for any reconstructor's output.
#include "checks/exact_self_intersections.h"
#include "geometry/self_intersections.h"
#include "lsrecon/adapters/openmesh_mesh.h"
#include "surface/surface_topology.h"

#include <cstdio>
#include <exception>
#include <limits>

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: lsrecon-cgal-check MESH...\n");
    return 2;
  }
  int status = 0;
  for (int i = 1; i < argc; ++i) {
    try {
      const lsr::LevelSetMesh<3> m = lsr::adapters::from_openmesh(lsr::adapters::read_mesh_file(argv[i]));
      const lsr::SurfaceTopology t = lsr::analyze_surface(m.vertices, m.facets);
      const std::size_t cgal = lsr::testing::cgal_self_intersections(m.vertices, m.facets);
      const std::size_t ours = lsr::detail::count_self_intersections(m.vertices, m.facets, 0);
      std::printf("%s: %zu triangles, watertight %d, CGAL %s intersecting pairs, lsrecon %zu\n", argv[i], m.facets.size(),
                  int(t.watertight), cgal == std::numeric_limits<std::size_t>::max() ? "(not a mesh CGAL builds)" : std::to_string(cgal).c_str(),
                  ours);
      // Where: the first pairs lsrecon finds, with what they share and the angle between them.
      const lsr::detail::SelfIntersections<3> search(m.facets, m.vertices);
      int shown = 0;
      for (const auto& [f, g] : search.pairs(m.vertices, {}, 0)) {
        if (shown++ == 5) break;
        const auto& F = m.facets[std::size_t(f)];
        const auto& G = m.facets[std::size_t(g)];
        int shared = 0;
        for (lsr::Index a : F) {
          for (lsr::Index b : G) shared += a == b ? 1 : 0;
        }
        const auto normal = [&](const std::array<lsr::Index, 3>& t) {
          const auto& x = m.vertices;
          return lsr::Vec<3>((x[std::size_t(t[1])] - x[std::size_t(t[0])]).cross(x[std::size_t(t[2])] - x[std::size_t(t[0])]));
        };
        const lsr::Vec<3> at = m.vertices[std::size_t(F[0])];
        std::printf("  triangles %d and %d: %d shared vertices, normals at cos %.4f, near (%g, %g, %g)\n", f, g, shared,
                    normal(F).normalized().dot(normal(G).normalized()), at[0], at[1], at[2]);
      }
    } catch (const std::exception& e) {
      std::fprintf(stderr, "%s: %s\n", argv[i], e.what());
      status = 1;
    }
  }
  return status;
}
