// SPDX-License-Identifier: BSD-3-Clause
/// @file bench_solver.cpp
/// @brief End-to-end solver benchmark: the 3D sphere and torus at 20k / 200k points and
/// h_min = 1/128, 1/256, and the paper's 2D cases. Each case runs in its own process so that
/// its peak memory is its own. Prints figures; asserts nothing about speed.
///   lsrecon-bench-solver            all cases
///   lsrecon-bench-solver CASE       one case (0-based)
#include "command_line.h"
#include "geometry/nearest_point_index.h"
#include "lsrecon/core/level_set_reconstruction.h"
#include "lsrecon/testdata/analytic_shapes.h"
#include "stopwatch.h"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

namespace {

struct Case {
  std::string name;
  int dim;
  int points;
  double resolution;  // 0: automatic
};

const std::vector<Case>& cases() {
  static const std::vector<Case> all = {
      {"sphere", 3, 20000, 128},   {"sphere", 3, 20000, 256},   {"sphere", 3, 200000, 128},
      {"sphere", 3, 200000, 256},  {"torus", 3, 20000, 128},    {"torus", 3, 20000, 256},
      {"torus", 3, 200000, 128},   {"torus", 3, 200000, 256},   {"star-2d", 2, 4000, 0},
      {"three-shapes-2d", 2, 6000, 0}, {"noisy-circle-2d", 2, 2000, 0},
  };
  return all;
}


template <int D>
void print(const Case& c, const lsr::ReconstructionResult<D>& r, double total, double error) {
  auto s = [&](const char* k) { return r.seconds.count(k) ? r.seconds.at(k) : 0.0; };
  std::printf("%-16s %7d %5.0f %9d %9d %5d %4s %6.1f %7.2f %7.2f %7.2f %7.2f %7.2f %7.2f %7.2f %7.2f %7.0f %6.2f\n",
              c.name.c_str(), c.points, 1.0 / r.h_min, r.mesh_vertices, r.mesh_simplices, r.iterations,
              r.status == lsr::ReconstructionStatus::converged ? "yes" : "no",
              double(r.solver_iterations) / std::max(1, r.iterations), s("mesh"), s("distance"), s("operators"),
              s("setup"), s("solve"), s("renormalize"), s("fit") + s("extract"), total, lsr::demos::peak_memory_mib(), error / r.tolerance);
  std::fflush(stdout);
}

template <int D, class Sdf>
void run(const Case& c, const lsr::Points<D>& points, const Sdf& sdf) {
  lsr::ReconstructionOptions o;
  o.mesh.h_min = c.resolution > 0 ? 1.0 / c.resolution : 0.0;
  lsr::demos::Stopwatch clock;
  const auto r = lsr::reconstruct<D>(points, o);
  const double total = clock.lap();
  double worst = 0.0;
  for (const auto& v : r.surface.vertices) worst = std::max(worst, std::abs(sdf(v)));
  print(c, r, total, worst);
}

void run_case(const Case& c) {
  if (c.name == "sphere") {
    const lsr::Sphere s{lsr::Vec<3>(0, 0, 0), 1.0};
    run<3>(c, s.sample(c.points), [&](const lsr::Vec<3>& p) { return s.signed_distance(p); });
  } else if (c.name == "torus") {
    const lsr::Torus t{lsr::Vec<3>(0, 0, 0), 1.0, 0.4};
    run<3>(c, t.sample(c.points), [&](const lsr::Vec<3>& p) { return t.signed_distance(p); });
  } else if (c.name == "star-2d") {
    const lsr::Points<2> truth = lsr::sample_star(200000, lsr::Vec<2>(0, 0), 1.0);
    const lsr::NearestPointIndex<2> index(truth);
    run<2>(c, lsr::sample_star(c.points, lsr::Vec<2>(0, 0), 1.0), [&](const lsr::Vec<2>& p) { return index.distance(p); });
  } else if (c.name == "three-shapes-2d") {
    lsr::Points<2> data = lsr::Circle{lsr::Vec<2>(-1.2, 0), 0.5}.sample(c.points / 3);
    for (const auto& p : lsr::Circle{lsr::Vec<2>(0.6, 0.8), 0.5}.sample(c.points / 3)) data.push_back(p);
    lsr::Points<2> s = lsr::sample_star(c.points / 3, lsr::Vec<2>(0.6, -0.9), 0.5);
    data.insert(data.end(), s.begin(), s.end());
    lsr::Points<2> truth = lsr::Circle{lsr::Vec<2>(-1.2, 0), 0.5}.sample(100000);
    for (const auto& p : lsr::Circle{lsr::Vec<2>(0.6, 0.8), 0.5}.sample(100000)) truth.push_back(p);
    for (const auto& p : lsr::sample_star(100000, lsr::Vec<2>(0.6, -0.9), 0.5)) truth.push_back(p);
    const lsr::NearestPointIndex<2> index(truth);
    run<2>(c, data, [&](const lsr::Vec<2>& p) { return index.distance(p); });
  } else {
    // Section 6.4.2: Box-Muller noise, sigma = 2 d_min; the error column is against the clean circle.
    const lsr::Points<2> clean = lsr::Circle{lsr::Vec<2>(0, 0), 1.0}.sample(c.points);
    const double sigma = 2 * 2 * std::sin(lsr::kPi / c.points);
    lsr::Points<2> noisy;
    unsigned state = 12345;
    auto uniform = [&] { state = state * 1664525u + 1013904223u; return (state + 1.0) / 4294967297.0; };
    for (const auto& p : clean) {
      const double r = std::sqrt(-2 * std::log(uniform())), a = 2 * lsr::kPi * uniform();
      noisy.push_back(p + sigma * r * lsr::Vec<2>(std::cos(a), std::sin(a)));
    }
    run<2>(c, noisy, [](const lsr::Vec<2>& p) { return p.norm() - 1.0; });
  }
}

}  // namespace

int main(int argc, char** argv) {
  int only = -1;
  lsr::demos::CommandLine line("lsrecon-bench-solver", LSRECON_VERSION,
                               "usage: lsrecon-bench-solver [--case K]\n\n"
                               "The solver on each case, each in its own process (peak memory per case).\n");
  line.group("cases").number("case", "K", only, 0, double(cases().size() - 1), "run only case K, in this process");
  line.parse(argc, argv, 0, 0, "no positional argument");
  if (only >= 0) {
    run_case(cases()[std::size_t(only)]);
    return 0;
  }
  std::printf("%-16s %7s %5s %9s %9s %5s %4s %6s %7s %7s %7s %7s %7s %7s %7s %7s %7s %6s\n", "case", "points", "R",
              "vertices", "simplices", "steps", "conv", "cg/st", "mesh_s", "dist_s", "oper_s", "setup_s", "solve_s",
              "renorm_s", "fit_s", "total_s", "peakMiB", "err/h");
  std::fflush(stdout);
  for (std::size_t k = 0; k < cases().size(); ++k) {
    const pid_t child = fork();
    if (child == 0) {
      execl(argv[0], argv[0], "--case", std::to_string(k).c_str(), static_cast<char*>(nullptr));
      std::_Exit(127);
    }
    int status = 0;
    waitpid(child, &status, 0);
  }
  return 0;
}
