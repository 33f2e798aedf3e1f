// SPDX-License-Identifier: BSD-3-Clause
/// @file bench_geometry.cpp
/// @brief Times the geometric stages (kd-tree, adaptive mesh, distance field, extraction) on a
/// sampled sphere (r = 0.3) for 20k and 200k points at h_min = 1/128 and 1/256. Prints figures;
/// asserts nothing about speed.
#include "lsrecon/core/level_set_extraction.h"
#include "lsrecon/testdata/analytic_shapes.h"
#include "mesh/adaptive_refinement.h"
#include "stopwatch.h"

#include <sys/resource.h>

#include <cstdio>

namespace {

}  // namespace

int main() {
  const lsr::Sphere sphere{lsr::Vec<3>(0.5, 0.5, 0.5), 0.3};
  std::printf("%8s %6s %10s %10s %7s %8s %8s %8s %8s %9s %9s\n", "points", "R", "vertices",
              "tets", "%unif", "index_s", "mesh_s", "dist_s", "extr_s", "triangles", "peakMiB");
  for (int n : {20000, 200000}) {
    for (int r : {128, 256}) {
      lsr::demos::Stopwatch clock;
      const lsr::NearestPointIndex<3> data(sphere.sample(n));
      const double t_index = clock.lap();
      lsr::AdaptiveMeshOptions o;
      o.h_min = 1.0 / r;
      const lsr::AdaptiveMesh<3> m = lsr::build_adaptive_mesh(data, o);
      const double t_mesh = clock.lap();
      std::vector<double> d;
      data.query(m.mesh.vertices, d);
      const double t_dist = clock.lap();
      std::vector<double> u(m.mesh.vertices.size());
      for (std::size_t i = 0; i < u.size(); ++i) u[i] = sphere.signed_distance(m.mesh.vertices[i]);
      clock.lap();
      const lsr::LevelSetMesh<3> s = lsr::extract_zero_level_set(m.mesh, u);
      const double t_extract = clock.lap();
      std::printf("%8d %6d %10zu %10zu %7.2f %8.3f %8.3f %8.3f %8.3f %9zu %9.0f\n", n, r,
                  m.mesh.vertices.size(), m.mesh.simplices.size(),
                  100.0 * m.mesh.vertices.size() / m.stats.uniform_vertices, t_index, t_mesh,
                  t_dist, t_extract, s.facets.size(), lsr::demos::peak_memory_mib());
    }
  }
  return 0;
}
