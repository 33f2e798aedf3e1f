// SPDX-License-Identifier: BSD-3-Clause
/// @file lsrecon_main.cpp
/// @brief The lsrecon command line. With the solver still to come (issue 3), it runs the
/// geometric stages on a generated cloud: normalise, kd-tree, adaptive mesh, distance field,
/// and extraction of an offset surface {d = 2 h_min}; it writes them as .vtu for ParaView.
#include "lsrecon/core/adaptive_refinement.h"
#include "lsrecon/core/analytic_shapes.h"
#include "lsrecon/core/level_set_extraction.h"
#include "lsrecon/core/surface_topology.h"
#include "lsrecon/core/unit_box_transform.h"
#include "lsrecon/core/vtu_writer.h"
#include "stopwatch.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>

namespace {

const char* kUsage = R"(usage: lsrecon [options]

Runs the geometric stages of lsrecon on a generated point cloud and writes the results.

options:
  --shape NAME       sphere | torus | two-spheres            (default: torus)
  --points N         number of generated points, >= 4        (default: 20000)
  --resolution R     1/h_min in the unit box, 4 .. 4096      (default: 128)
  --out DIR          output folder, created if missing       (default: lsrecon-out)
  --help             this text
)";

struct Options {
  std::string shape = "torus";
  int points = 20000;
  double resolution = 128;
  std::string out = "lsrecon-out";
};

[[noreturn]] void fail(const std::string& message) {
  std::cerr << "lsrecon: " << message << "\n(run lsrecon --help for the options)\n";
  std::exit(2);
}

double number(const std::string& flag, const char* text, double lo, double hi) {
  char* end = nullptr;
  const double v = std::strtod(text, &end);
  if (end == text || *end != '\0' || !(v >= lo && v <= hi)) {
    fail(flag + " expects a number between " + std::to_string(lo) + " and " + std::to_string(hi) +
         ", got '" + text + "'");
  }
  return v;
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--help" || a == "-h") {
      std::cout << kUsage;
      std::exit(0);
    }
    if (i + 1 >= argc) fail("unknown option or missing value: " + a);
    const char* v = argv[++i];
    if (a == "--shape") {
      o.shape = v;
      if (o.shape != "sphere" && o.shape != "torus" && o.shape != "two-spheres") {
        fail("--shape must be sphere, torus or two-spheres, got '" + o.shape + "'");
      }
    } else if (a == "--points") {
      o.points = int(number(a, v, 4, 5e7));
    } else if (a == "--resolution") {
      o.resolution = number(a, v, 4, 4096);
    } else if (a == "--out") {
      o.out = v;
    } else {
      fail("unknown option " + a);
    }
  }
  return o;
}

lsr::Points<3> generate(const Options& o) {
  if (o.shape == "sphere") return lsr::Sphere{lsr::Vec<3>(0, 0, 0), 1.0}.sample(o.points);
  if (o.shape == "torus") return lsr::Torus{lsr::Vec<3>(0, 0, 0), 1.0, 0.4}.sample(o.points);
  lsr::Points<3> p = lsr::Sphere{lsr::Vec<3>(-1.2, 0, 0), 1.0}.sample(o.points / 2);
  const lsr::Points<3> q = lsr::Sphere{lsr::Vec<3>(1.2, 0, 0), 1.0}.sample(o.points - o.points / 2);
  p.insert(p.end(), q.begin(), q.end());
  return p;
}

void stage(const char* name, double seconds, const std::string& what) {
  std::fprintf(stderr, "[%-10s] %7.3f s  %s\n", name, seconds, what.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  try {
    lsr::demos::Stopwatch clock;
    lsr::demos::Stopwatch total;
    const lsr::Points<3> cloud = generate(o);
    const auto box = lsr::UnitBoxTransform<3>::fit(cloud, 0.1);
    lsr::NearestPointIndex<3> data(box.to_unit(cloud));
    stage("input", clock.lap(), std::to_string(cloud.size()) + " generated points on a " + o.shape);

    lsr::AdaptiveMeshOptions mo;
    mo.h_min = 1.0 / o.resolution;
    const lsr::Progress progress([](const std::string&, double) {
      std::fputc('.', stderr);
      return true;
    });
    const lsr::AdaptiveMesh<3> mesh = lsr::build_adaptive_mesh(data, mo, progress);
    std::fputc('\n', stderr);
    stage("mesh", clock.lap(),
          std::to_string(mesh.mesh.vertices.size()) + " vertices, " +
              std::to_string(mesh.mesh.simplices.size()) + " tetrahedra (" +
              std::to_string(int(100.0 * mesh.mesh.vertices.size() / mesh.stats.uniform_vertices)) +
              "% of the uniform mesh), finest size 1/" +
              std::to_string(int(1.0 / mesh.stats.finest_size + 0.5)));

    std::vector<double> d;
    data.query(mesh.mesh.vertices, d);
    stage("distance", clock.lap(), "d(x) at every mesh vertex");

    const double offset = 2.0 * mesh.stats.finest_size;
    std::vector<double> shell(d.size());
    for (std::size_t i = 0; i < d.size(); ++i) shell[i] = d[i] - offset;
    lsr::LevelSetMesh<3> surface = lsr::extract_zero_level_set(mesh.mesh, shell);
    const lsr::SurfaceTopology topo = lsr::analyze_surface(surface.vertices, surface.facets);
    stage("extract", clock.lap(),
          "offset surface {d = 2 h_min}: " + std::to_string(surface.facets.size()) + " triangles, " +
              std::to_string(topo.components) + " components, " +
              (topo.watertight ? "watertight" : "NOT watertight"));

    std::filesystem::create_directories(o.out);
    const std::string mesh_file = o.out + "/mesh.vtu";
    const std::string shell_file = o.out + "/offset.vtu";
    lsr::write_vtu<3, 4>(mesh_file, box.from_unit(mesh.mesh.vertices), mesh.mesh.simplices,
                         {{"distance_unit_box", &d}});
    lsr::write_vtu<3, 3>(shell_file, box.from_unit(surface.vertices), surface.facets);
    stage("write", clock.lap(), mesh_file + ", " + shell_file);
    std::fprintf(stderr, "done in %.2f s. The level-set solver itself arrives with issue 3.\n",
                 total.lap());
  } catch (const lsr::Error& e) {
    std::cerr << "lsrecon: " << e.what() << '\n';
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "lsrecon: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
