// SPDX-License-Identifier: BSD-3-Clause
/// @file lsrecon_main.cpp
/// @brief The lsrecon command line: reconstructs a generated cloud (file input arrives with the
/// PCL/OpenMesh adapters, issue 4) and writes the result as .vtu, printing progress and timings.
#include "lsrecon/core/analytic_shapes.h"
#include "lsrecon/core/level_set_reconstruction.h"
#include "lsrecon/core/surface_topology.h"
#include "lsrecon/core/vtu_writer.h"
#include "stopwatch.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>

namespace {

const char* kUsage = R"(usage: lsrecon [options]

Reconstructs a closed surface (3D) or closed curves (2D) from a generated, unoriented point
cloud with the level-set method of Claisse & Frey (2011), and writes it as .vtu (ParaView).

options:
  --shape NAME          3D: torus | sphere | two-spheres; 2D: star | three-shapes
                                                              (default: torus)
  --points N            number of generated points, >= 4     (default: 20000)
  --resolution R        1/h_min in the unit box; 0 = from the data (default: 0)
  --alpha A             attraction weight; 0 = +2 enclosing, -2 inside (default: 0)
  --max-iterations N    time steps at most                    (default: 1000)
  --tolerance EPS       stopping tolerance in the unit box; 0 = h_min (default: 0)
  --init enclose|inside where the front starts                (default: enclose)
  --out DIR             output folder, created if missing     (default: lsrecon-out)
  --quiet               no progress on stderr
  --help                this text
)";

struct Options {
  std::string shape = "torus";
  int points = 20000;
  lsr::ReconstructionOptions solver;
  std::string out = "lsrecon-out";
  bool quiet = false;
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

bool is_2d(const std::string& shape) { return shape == "star" || shape == "three-shapes"; }

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--help" || a == "-h") {
      std::cout << kUsage;
      std::exit(0);
    }
    if (a == "--quiet") {
      o.quiet = true;
      continue;
    }
    if (i + 1 >= argc) fail("unknown option or missing value: " + a);
    const char* v = argv[++i];
    if (a == "--shape") {
      o.shape = v;
      if (!is_2d(o.shape) && o.shape != "sphere" && o.shape != "torus" && o.shape != "two-spheres") {
        fail("--shape must be torus, sphere, two-spheres, star or three-shapes, got '" + o.shape + "'");
      }
    } else if (a == "--points") {
      o.points = int(number(a, v, 4, 5e7));
    } else if (a == "--resolution") {
      const double r = number(a, v, 0, 8192);
      if (r > 0 && r < 4) fail("--resolution must be 0 (automatic) or at least 4");
      o.solver.h_min = r > 0 ? 1.0 / r : 0.0;
    } else if (a == "--alpha") {
      o.solver.alpha = number(a, v, -100, 100);
    } else if (a == "--max-iterations") {
      o.solver.max_iterations = int(number(a, v, 1, 1e6));
    } else if (a == "--tolerance") {
      o.solver.tolerance = number(a, v, 0, 0.5);
    } else if (a == "--init") {
      const std::string init = v;
      if (init != "enclose" && init != "inside") fail("--init must be enclose or inside, got '" + init + "'");
      o.solver.initial_front = init == "inside" ? lsr::InitialFront::inside : lsr::InitialFront::enclosing;
    } else if (a == "--out") {
      o.out = v;
    } else {
      fail("unknown option " + a);
    }
  }
  return o;
}

lsr::Points<3> generate_3d(const Options& o) {
  if (o.shape == "sphere") return lsr::Sphere{lsr::Vec<3>(0, 0, 0), 1.0}.sample(o.points);
  if (o.shape == "torus") return lsr::Torus{lsr::Vec<3>(0, 0, 0), 1.0, 0.4}.sample(o.points);
  lsr::Points<3> p = lsr::Sphere{lsr::Vec<3>(-1.3, 0, 0), 1.0}.sample(o.points / 2);
  for (const auto& q : lsr::Sphere{lsr::Vec<3>(1.3, 0, 0), 1.0}.sample(o.points - o.points / 2)) p.push_back(q);
  return p;
}

lsr::Points<2> star(int n, lsr::Vec<2> center, double radius) {
  const double pi = std::acos(-1.0);
  lsr::Points<2> p;
  for (int i = 0; i < n; ++i) {
    const double t = 2 * pi * i / n;
    p.push_back(center + radius * (1 + 0.3 * std::cos(5 * t)) * lsr::Vec<2>(std::cos(t), std::sin(t)));
  }
  return p;
}

lsr::Points<2> generate_2d(const Options& o) {
  if (o.shape == "star") return star(o.points, lsr::Vec<2>(0, 0), 1.0);
  lsr::Points<2> p = lsr::Circle{lsr::Vec<2>(-1.2, 0), 0.5}.sample(o.points / 3);
  for (const auto& q : lsr::Circle{lsr::Vec<2>(0.6, 0.8), 0.5}.sample(o.points / 3)) p.push_back(q);
  for (const auto& q : star(o.points - 2 * (o.points / 3), lsr::Vec<2>(0.6, -0.9), 0.5)) p.push_back(q);
  return p;
}

lsr::ProgressCallback printer(bool quiet) {
  if (quiet) return {};
  return [last = std::string()](const std::string& stage, double fraction) mutable {
    if (stage != last && !last.empty()) std::fprintf(stderr, "\n");
    last = stage;
    std::fprintf(stderr, "\r[%-5s] %3.0f%%", stage.c_str(), 100 * std::max(0.0, fraction));
    return true;
  };
}

template <int D>
void summarize(const lsr::ReconstructionResult<D>& r, bool quiet) {
  if (!quiet) {
    std::fprintf(stderr, "\n");
    for (const auto& [stage, seconds] : r.seconds) std::fprintf(stderr, "  %-14s %8.3f s\n", stage.c_str(), seconds);
  }
  const char* status = r.status == lsr::ReconstructionStatus::converged       ? "converged"
                       : r.status == lsr::ReconstructionStatus::not_converged ? "NOT converged (best iterate)"
                                                                              : "cancelled";
  std::printf("%s after %d steps (best %d): max |u| on the data %.3g (tolerance %.3g); mesh %d vertices, "
              "h_min = 1/%.0f\n",
              status, r.iterations, r.best_iteration, r.residual, r.tolerance, r.mesh_vertices, 1.0 / r.h_min);
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  try {
    std::filesystem::create_directories(o.out);
    if (is_2d(o.shape)) {
      const auto r = lsr::reconstruct<2>(generate_2d(o), o.solver, printer(o.quiet));
      summarize(r, o.quiet);
      const std::string file = o.out + "/curves.vtu";
      lsr::write_vtu<2, 2>(file, r.surface.vertices, r.surface.facets);
      std::printf("%zu closed curves, %zu vertices -> %s\n", r.loops.size(), r.surface.vertices.size(), file.c_str());
      return r.status == lsr::ReconstructionStatus::cancelled ? 1 : 0;
    }
    const auto r = lsr::reconstruct<3>(generate_3d(o), o.solver, printer(o.quiet));
    summarize(r, o.quiet);
    const lsr::SurfaceTopology t = lsr::analyze_surface(r.surface.vertices, r.surface.facets);
    const std::string file = o.out + "/surface.vtu";
    lsr::write_vtu<3, 3>(file, r.surface.vertices, r.surface.facets);
    std::printf("%zu triangles, %d component(s), genus", r.surface.facets.size(), t.components);
    for (int g : t.genus) std::printf(" %d", g);
    std::printf(", %s -> %s\n", t.watertight ? "watertight" : "NOT watertight", file.c_str());
    return r.status == lsr::ReconstructionStatus::cancelled ? 1 : 0;
  } catch (const lsr::Error& e) {
    std::cerr << "lsrecon: " << e.what() << '\n';
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "lsrecon: " << e.what() << '\n';
    return 1;
  }
}
