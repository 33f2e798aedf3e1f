// SPDX-License-Identifier: BSD-3-Clause
/// @file lsrecon_main.cpp
/// @brief The lsrecon command line: a point cloud file (or a generated demo cloud) in, a closed
/// surface (3D) or closed curves (2D) out. Progress and timings on stderr, an optional JSON
/// report, outputs written atomically, non-zero exit with a message that says what to change.
#include "command_line.h"
#include "curve_files.h"
#include "image_points.h"
#include "lsrecon/adapters/openmesh_mesh.h"
#include "lsrecon/adapters/point_files.h"
#include "lsrecon/adapters/statistical_outliers.h"
#include "lsrecon/adapters/volume_mesh_files.h"
#include "lsrecon/testdata/analytic_shapes.h"
#include "lsrecon/testdata/shape_corpus.h"
#include "lsrecon/core/atomic_file.h"
#include "lsrecon/core/level_set_reconstruction.h"
#include "lsrecon/core/resolution_hierarchy.h"
#include "lsrecon/core/surface_topology.h"
#include "lsrecon/core/facet_mesh_distance.h"
#include "staged_outputs.h"
#include "stopwatch.h"

#include <nlohmann/json.hpp>

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>

namespace {

const char* kUsage = R"(usage: lsrecon INPUT OUTPUT [options]
       lsrecon --demo SHAPE OUTPUT [options]

Reconstructs a closed surface (3D) or closed curves (2D) from unoriented points with the
level-set method of Claisse & Frey (2011). No normals needed.

INPUT   .pcd .ply (point clouds), .xyz .txt (x y [z] or x,y,z per line), .obj .off .stl (vertices),
        .pgm .ppm .pbm .png (2D: every dark pixel is a point)
OUTPUT  3D: .ply .obj .off (double precision) .stl .vtk (float)
        2D: .svg (drawing) or .txt (one closed polyline per loop)
SHAPE   generated clouds: i.i.d. random samples of sphere torus double-torus triple-torus
        trefoil linked-rings cup limb two-spheres (3D); star three-shapes (2D)

Options take their value as --opt VALUE or --opt=VALUE; (=X) is the default. Lengths are in the
unit box the data is mapped into (its bounding ball has radius 0.4); 0 means "from the data".
)";

const char* kExitStatus = R"(exit status: 0 written (see the summary for convergence), 1 bad input or file error,
             2 bad command line, 130 interrupted (nothing written)
)";

std::atomic<bool> g_interrupted{false};
extern "C" void on_interrupt(int) { g_interrupted = true; }

struct Cli {
  std::string input, output, demo, report, save_points, volume_mesh, init_mesh;
  lsr::ReconstructionOptions solver;
  lsr::adapters::StatisticalOutlierFilter statistical;
  int dim = 0;
  long decimate = 0;
  unsigned smooth = 0;
  int points = 20000;
  int levels = 1;
  bool quiet = false;
};

bool is_2d_shape(const std::string& s) { return s == "star" || s == "three-shapes"; }
bool is_curve_output(const std::string& ext) { return lsr::adapters::has_role(ext, lsr::adapters::FileRole::curve_output); }
bool is_mesh_output(const std::string& ext) { return lsr::adapters::has_role(ext, lsr::adapters::FileRole::mesh_output); }

std::string format_number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

const char* initial_front_name(lsr::InitialFront f) {
  return f == lsr::InitialFront::tagged ? "tagged" : f == lsr::InitialFront::enclosing ? "enclose" : "inside";
}

// Every option once: its default is the value Cli (and so lsr::ReconstructionOptions) starts with.
Cli parse(int argc, char** argv) {
  Cli c;
  auto& s = c.solver;
  lsr::demos::CommandLine line("lsrecon", LSRECON_VERSION, kUsage, kExitStatus);
  std::string init = initial_front_name(s.initial_front);
  bool no_fit = false, keep_outliers = false;
  auto resolution = [&line](const std::string& flag, double r) {
    if (r > 0 && r < 4) line.fail(flag + " must be 0 (automatic) or at least 4");
    return r;
  };
  line.group("input and output")
      .text("demo", "SHAPE", c.demo, "reconstruct a generated cloud (SHAPE above) instead of INPUT")
      .number("points", "N", c.points, 4, 5e7, "points of a --demo cloud")
      .number("dim", "D", c.dim, 2, 3, "2 or 3; 0 = 2 if the input is planar, else 3")
      .text("report", "FILE.json", c.report, "write the figures of the run as JSON")
      .text("save-points", "FILE.xyz", c.save_points, "also write the input points (a --demo cloud) as text")
      .text("volume-mesh", "FILE", c.volume_mesh,
            "also write meshes of the inside (label 1) and the outside (2) of the result within the box, "
            "sharing its surface (label 10; box walls 20): .mesh (Medit), .msh (Gmsh 2.2), .vtu")
      .flag("quiet", c.quiet, "no progress on stderr");
  line.group("mesh")
      .number("resolution", "R", s.h_min > 0 ? 1 / s.h_min : 0.0, 0, 1e5, false,
              "1/h_min, the same mesh size everywhere near the data; 0 = follow the local sampling spacing",
              [&](double r) { s.h_min = resolution("--resolution", r) > 0 ? 1.0 / r : 0.0; })
      .number("max-resolution", "R", s.max_resolution, 0, 1e5, false,
              "cap on the local resolution (finer = more time and memory, closer sheets told apart); "
              "0 = 256 in 3D, 4096 in 2D",
              [&](double r) { s.max_resolution = resolution("--max-resolution", r); })
      .number("max-size", "H", s.h_max, 1e-4, 1, "coarsest mesh size")
      .number("grading", "C", s.grading, 1e-3, 100, "mesh grading; smaller = wider fine band");
  line.group("front")
      .text("init", "START", init, "tagged: hug the data from outside (flood from the box walls); "
            "enclose: a sphere around it; inside: a sphere inside it", {"tagged", "enclose", "inside"})
      .text("init-mesh", "FILE", c.init_mesh,
            "start from this closed surface (.ply .obj .off .stl .vtk; a previous scan, a rough model) or, "
            "in 2D, closed curves (.txt as lsrecon writes them), which may cross the data: the front is "
            "then attracted from both sides")
      .number("alpha", "A", s.alpha, -1e3, 1e3, "attraction to the data; 0 = +2 (from outside), -2 (inside)")
      .number("curvature-weight", "B", s.curvature_weight, -1, 1e3, "smoothness; < 0 = local, from spacing and noise")
      .number("time-step", "DT", s.time_step, 0, 100, "0 = 0.2 / |alpha|")
      .number("max-iterations", "N", s.max_iterations, 1, 1e7, "time steps at most")
      .number("tolerance", "EPS", s.tolerance, 0, 0.5, "stop when data and front are this close; 0 = one local sampling spacing")
      .number("renormalization-interval", "K", s.renormalization_interval, 0, s.patience,
              "renormalise every K steps (the stopping test measures the front then); 0 = automatic")
      .number("hole-radius", "H", s.hole_radius, -1, 0.49, "span sampling holes up to radius H with tangent discs on their rims (docs/how-it-works.md: Sampling holes); -1 = 0.06 in 3D, off in 2D; 0 = off");
  line.group("data and result")
      .flag("keep-outliers", keep_outliers, "keep isolated points (nearest neighbour farther than " +
            format_number(s.outlier_factor) + " local spacings); by default they are left out")
      .number("sor-mean-k", "K", c.statistical.mean_k, 0, 1000,
              "pcl::StatisticalOutlierRemoval first: K neighbours (e.g. 16) for clusters of outliers; 0 = off")
      .number("sor-stddev", "S", c.statistical.stddev_mul, 1e-3, 1e3,
              "... leaving out points whose mean neighbour distance is S deviations above the mean")
      .flag("no-fit", no_fit, "output the front itself, not the fit through the data")
      .number("levels", "N", c.levels, 1, 8,
              "N reconstructions, each at twice the resolution of the one before, written as OUT with .l0 (coarsest) "
              "to .l<N-1> before its extension; 1 = just OUT")
      .number("decimate", "FACES", c.decimate, 4, 1e9, "simplify the 3D result to at most FACES faces; 0 = off")
      .number("smooth", "N", c.smooth, 0, 1000, "N rounds of Laplace smoothing of the 3D result");
  line.group("resources")
      .number("threads", "N", s.threads, 0, 1024, "0 = all cores")
      .number("max-memory", "GIB", s.max_memory / double(1 << 30), 0, 1e5, false,
              "refuse clouds and meshes predicted to need more; 0 = min(4, half the machine's memory)",
              [&](double gib) { s.max_memory = gib * double(1 << 30); })
      .number("max-mesh-vertices", "N", s.max_vertices, 0, 2e9, "refuse larger meshes; 0 = from --max-memory");
  const std::vector<std::string> positional = line.parse(argc, argv, 1, 2, "INPUT OUTPUT (or --demo SHAPE OUTPUT)");
  if (no_fit) s.fit_surface = false;
  if (keep_outliers) s.outlier_factor = 0.0;
  s.initial_front = init == "inside" ? lsr::InitialFront::inside
                    : init == "enclose" ? lsr::InitialFront::enclosing
                                        : lsr::InitialFront::tagged;
  const std::size_t expected = c.demo.empty() ? 2 : 1;
  if (positional.size() != expected) {
    line.fail(c.demo.empty() ? "expected INPUT and OUTPUT" : "with --demo, expected only OUTPUT");
  }
  if (c.demo.empty()) c.input = positional[0];
  c.output = positional.back();
  const auto shapes = lsr::test_shape_names();
  if (!c.demo.empty() && std::find(shapes.begin(), shapes.end(), c.demo) == shapes.end() && !is_2d_shape(c.demo)) {
    line.fail("--demo must be one of the SHAPE names in --help, got '" + c.demo + "'");
  }
  const std::string out = lsr::adapters::file_extension(c.output);
  if (!is_curve_output(out) && !is_mesh_output(out)) {
    line.fail("cannot write '" + c.output + "': use " + lsr::adapters::extensions(lsr::adapters::FileRole::mesh_output) +
              " (3D) or " + lsr::adapters::extensions(lsr::adapters::FileRole::curve_output) + " (2D)");
  }
  if ((c.decimate > 0 || c.smooth > 0) && is_curve_output(out)) line.fail("--decimate and --smooth apply to 3D meshes only");
  if (c.levels > 1 && !c.init_mesh.empty()) line.fail("--levels starts each level from the data; drop --init-mesh");
  if (!c.init_mesh.empty()) {
    const std::string start = lsr::adapters::file_extension(c.init_mesh);
    if (is_curve_output(out) && start != "txt") line.fail("for 2D curves, --init-mesh takes closed curves as .txt");
    if (is_mesh_output(out) && !is_mesh_output(start)) {
      line.fail("for a surface, --init-mesh takes a closed mesh: " + lsr::adapters::extensions(lsr::adapters::FileRole::mesh_output));
    }
    s.two_sided = true;
  }
  if (!c.volume_mesh.empty()) {
    if (!lsr::adapters::has_role(lsr::adapters::file_extension(c.volume_mesh), lsr::adapters::FileRole::volume_output)) {
      line.fail("cannot write the volume mesh '" + c.volume_mesh + "': use " +
                lsr::adapters::extensions(lsr::adapters::FileRole::volume_output));
    }
    if (c.decimate > 0 || c.smooth > 0) line.fail("--decimate and --smooth would detach the surface from --volume-mesh");
    s.volume_mesh = true;
  }
  return c;
}

// The input as 3D points and its dimension.
struct Input {
  lsr::Points<3> points;
  int dim = 3;
  std::size_t skipped = 0;
  std::size_t statistical_outliers = 0;  ///< left out by pcl::StatisticalOutlierRemoval
};

Input generate(const Cli& c) {
  Input in;
  if (is_2d_shape(c.demo)) {
    lsr::Points<2> p;
    if (c.demo == "star") {
      p = lsr::sample_star(c.points, lsr::Vec<2>(0, 0), 1.0);
    } else {
      p = lsr::Circle{lsr::Vec<2>(-1.2, 0), 0.5}.sample(c.points / 3);
      for (const auto& q : lsr::Circle{lsr::Vec<2>(0.6, 0.8), 0.5}.sample(c.points / 3)) p.push_back(q);
      for (const auto& q : lsr::sample_star(c.points - 2 * (c.points / 3), lsr::Vec<2>(0.6, -0.9), 0.5)) p.push_back(q);
    }
    for (const auto& q : p) in.points.emplace_back(q.x(), q.y(), 0.0);
    in.dim = 2;
    return in;
  }
  // Irregular, as a scanner's points are.
  in.points = lsr::sample_test_shape(lsr::make_test_shape(c.demo), c.points).points;
  return in;
}

Input read_input(const Cli& c) {
  Input in;
  const std::string ext = lsr::adapters::file_extension(c.input);
  if (lsr::adapters::has_role(ext, lsr::adapters::FileRole::image_input)) {
    for (const auto& p : lsr::demos::read_image_points(c.input)) in.points.emplace_back(p.x(), p.y(), 0.0);
    in.dim = 2;
    return in;
  }
  lsr::adapters::PointFile file = lsr::adapters::read_point_file(c.input);
  in.points = std::move(file.points);
  in.skipped = file.skipped;
  in.dim = file.planar_text ? 2 : lsr::adapters::detect_dimension(in.points);
  return in;
}

lsr::ProgressCallback printer(bool quiet) {
  return [quiet, last = std::string(), clock = lsr::demos::Stopwatch(), elapsed = 0.0, stage_seconds = 0.0](
             const std::string& stage, double fraction) mutable {
    if (g_interrupted) return false;
    if (quiet) return true;
    if (stage != last) {
      if (!last.empty()) std::fputc('\n', stderr);
      stage_seconds = 0.0;
    }
    last = stage;
    const double lap = clock.lap();
    elapsed += lap;
    stage_seconds += lap;
    if (fraction < 0.0) {  // a stage that cannot say how far it is
      std::fprintf(stderr, "\r[%-5s]       %6.1f s", stage.c_str(), elapsed);
    } else {
      std::fprintf(stderr, "\r[%-5s] %3.0f%%  %6.1f s", stage.c_str(), 100 * fraction, elapsed);
    }
    if (fraction > 0.05) std::fprintf(stderr, "  ETA %5.1f s ", stage_seconds * (1 - fraction) / fraction);
    return true;
  };
}

// What was written: for the report and the summary line.
struct Outcome {
  std::size_t vertices = 0, faces = 0, curves = 0;
  int components = 0;
  bool watertight = false;
  std::string summary;  ///< e.g. "3 closed curve(s), 812 vertices"
  lsr::VolumeMeshQuality volume;  ///< with --volume-mesh
};

// Seconds of the stages outside the solver (read, postprocess, write), in pipeline order.
using OuterStages = std::vector<std::pair<std::string, double>>;

template <int D>
void write_report(const Cli& c, const Input& in, const lsr::ReconstructionResult<D>& r, const Outcome& out,
                  const std::string& output, double total, const OuterStages& extra_seconds, const std::string& file) {
  using nlohmann::json;
  const lsr::ReconstructionOptions& o = c.solver;
  // The options as given (0 = automatic); lengths in the unit box the data is mapped into.
  const json options = {{"resolution", o.h_min > 0.0 ? 1.0 / o.h_min : 0.0},
                        {"max_resolution", o.max_resolution},
                        {"max_size_unit_box", o.h_max},
                        {"grading", o.grading},
                        {"alpha", o.alpha},
                        {"curvature_weight", o.curvature_weight},
                        {"time_step", o.time_step},
                        {"max_iterations", o.max_iterations},
                        {"tolerance_unit_box", o.tolerance},
                        {"hole_radius_unit_box", o.hole_radius},
                        {"fit_surface", o.fit_surface},
                        {"outlier_factor", o.outlier_factor},
                        {"renormalization_interval", o.renormalization_interval},
                        {"initial_front", initial_front_name(o.initial_front)},
                        {"max_memory_bytes", o.max_memory},
                        {"max_mesh_vertices", o.max_vertices},
                        {"threads", o.threads},
                        {"two_sided", o.two_sided},
                        {"levels", c.levels},
                        {"init_mesh", c.init_mesh},
                        {"sor_mean_k", c.statistical.mean_k},
                        {"sor_stddev", c.statistical.stddev_mul}};
  // Stage times in pipeline order: read, the solver's stages, then what follows them.
  json stages = json::array();
  stages.push_back({{"stage", "read"}, {"seconds", extra_seconds.front().second}});
  for (const auto& stage : r.stages) stages.push_back({{"stage", stage}, {"seconds", r.seconds.at(stage)}});
  for (std::size_t k = 1; k < extra_seconds.size(); ++k) {
    stages.push_back({{"stage", extra_seconds[k].first}, {"seconds", extra_seconds[k].second}});
  }
  const char* status = r.status == lsr::ReconstructionStatus::converged       ? "converged"
                       : r.status == lsr::ReconstructionStatus::not_converged ? "not_converged"
                                                                              : "cancelled";
  json report = {{"lsrecon_version", LSRECON_VERSION},
                 {"input", c.demo.empty() ? c.input : "demo:" + c.demo},
                 {"input_points", in.points.size() + in.skipped},
                 {"skipped_points", in.skipped + r.skipped_points},
                 {"outlier_points", r.outlier_points},
                 {"duplicate_points", r.duplicate_points},
                 {"statistical_outlier_points", in.statistical_outliers},
                 {"dimension", D},
                 {"options", options},
                 {"h_min_unit_box", r.h_min},
                 {"mesh_vertices", r.mesh_vertices},
                 {"mesh_simplices", r.mesh_simplices},
                 {"time_steps", r.iterations},
                 {"best_step", r.best_iteration},
                 {"status", status},
                 {"converged", r.status == lsr::ReconstructionStatus::converged},
                 {"residual_input_units", r.residual},
                 {"residual_history_input_units", r.residual_history},
                 {"tolerance_input_units", r.tolerance},
                 {"unreached_points", r.unreached_points},
                 {"spacing_input_units", r.spacing},
                 {"noise_input_units", r.noise},
                 {"tagged_start", r.tagged_start},
                 {"sealed_cavities", r.sealed_cavities},
                 {"stage_seconds", stages},
                 {"total_seconds", total},
                 {"peak_memory_mib", lsr::demos::peak_memory_mib()},
                 {"output", output},
                 {"output_vertices", out.vertices},
                 {D == 2 ? "curves" : "output_faces", D == 2 ? out.curves : out.faces},
                 {"components", out.components},
                 {"watertight", out.watertight}};
  if (!c.volume_mesh.empty()) {
    const lsr::VolumeMeshQuality& q = out.volume;
    report["volume_mesh"] = {{"file", c.volume_mesh},
                             {"inside_simplices", q.inside_simplices},
                             {"outside_simplices", q.outside_simplices},
                             {"inverted", q.inverted},
                             {"surface_vertices_pulled_back", r.volume.pulled_back},
                             {"min_angle_degrees", q.min_angle_degrees},
                             {"median_angle_degrees", q.median_angle_degrees},
                             {"small_angle_fraction", q.small_angle_fraction},
                             {"inside_measure_input_units", q.inside_measure},
                             {"outside_measure_input_units", q.outside_measure}};
  }
  std::ofstream j(file);
  if (!j) throw lsr::Error("cannot write the report " + c.report, "check that the folder exists");
  j << report.dump(2) << '\n';
  if (!j.flush()) throw lsr::Error("writing " + c.report + " failed", "check free disk space");
}

// Why a run stopped short, from what it measured: the step limit, noise, or points never reached.
template <int D>
std::string not_converged_hint(const lsr::ReconstructionResult<D>& r) {
  std::ostringstream s;
  s.precision(3);
  if (!r.stalled) {
    s << "it was still improving at the last step: raise --max-iterations";
  } else if (r.noise > 0.25 * r.spacing) {  // 4 sigma beyond the tolerance: thousands of points
    s << "the points are noisy or fill a volume (noise " << r.noise << " against a spacing of " << r.spacing
      << "): raise --tolerance or --curvature-weight";
  } else {
    s << r.unreached_points << " point(s) stay beyond the tolerance (a cluster inside the surface?): check "
      << "them, or raise --tolerance";
  }
  return s.str();
}

template <int D>
void summarize(const lsr::ReconstructionResult<D>& r, double outlier_factor, bool quiet) {
  if (!quiet) {
    std::fputc('\n', stderr);
    for (const auto& stage : r.stages) std::fprintf(stderr, "  %-14s %8.3f s\n", stage.c_str(), r.seconds.at(stage));
  }
  if (r.duplicate_points > 0 && !quiet) {
    std::fprintf(stderr, "lsrecon: merged %zu copies of points given more than once (equal coordinates)\n", r.duplicate_points);
  }
  if (r.outlier_points > 0) {
    std::fprintf(stderr, "lsrecon: left out %zu isolated point(s) (nearest neighbour farther than %g local spacings); "
                         "--keep-outliers keeps them\n", r.outlier_points, outlier_factor);
  }
  if (r.sealed_cavities > 0) {
    std::fprintf(stderr, "lsrecon: closed %d opening(s) narrower than the hole radius through which the outside "
                         "reached an inside (an open end a sampling hole made); --hole-radius 0 leaves them open\n",
                 r.sealed_cavities);
  }
  if (r.status == lsr::ReconstructionStatus::converged && r.unreached_points > 0) {
    std::fprintf(stderr, "lsrecon: converged; the front stalled short of %zu points (sharp concave creases or "
                         "slits between close sheets), where the fit places the surface\n", r.unreached_points);
  }
  if (r.status == lsr::ReconstructionStatus::not_converged) {
    std::fprintf(stderr, "lsrecon: not converged: the best iterate (step %d, residual %.3g > tolerance %.3g) is "
                         "written [hint: %s]\n",
                 r.best_iteration, r.residual, r.tolerance, not_converged_hint(r).c_str());
  }
}

std::size_t distinct_points(lsr::Points<3> p) {
  std::sort(p.begin(), p.end(), [](const lsr::Vec<3>& a, const lsr::Vec<3>& b) {
    return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
  });
  return std::size_t(std::unique(p.begin(), p.end()) - p.begin());
}

// OUT with .l<k> before its extension: torus.ply -> torus.l0.ply.
std::string level_path(const std::string& output, int k) {
  const std::size_t dot = output.find_last_of('.');
  const std::size_t slash = output.find_last_of('/');
  const std::size_t at = dot == std::string::npos || (slash != std::string::npos && dot < slash) ? output.size() : dot;
  return output.substr(0, at) + ".l" + std::to_string(k) + output.substr(at);
}

// From the default start, or from the user's closed mesh (3D).
template <int D>
lsr::ReconstructionResult<D> solve(const Cli& c, const lsr::Points<D>& points) {
  if constexpr (D == 3) {
    if (!c.init_mesh.empty()) {
      const lsr::LevelSetMesh<3> start = lsr::adapters::from_openmesh(lsr::adapters::read_mesh_file(c.init_mesh));
      const lsr::SurfaceTopology t = lsr::analyze_surface(start.vertices, start.facets);
      if (!t.watertight || start.facets.empty()) {
        throw lsr::InvalidInput("the start mesh " + c.init_mesh + " is not closed (watertight)",
                                "close its holes first, or start from the default (drop --init-mesh)");
      }
      const lsr::TriangleMeshDistance distance(start.vertices, start.facets);
      const lsr::SignedDistance<3> sdf = [&distance](const lsr::Vec<3>& p) { return distance.signed_distance(p); };
      return lsr::reconstruct_from<3>(points, sdf, c.solver, printer(c.quiet));
    }
  } else if (!c.init_mesh.empty()) {
    const lsr::demos::Curves start = lsr::demos::read_polylines(c.init_mesh);
    std::vector<std::array<lsr::Index, 2>> segments;
    for (const auto& loop : start.loops) {
      for (std::size_t i = 0; i < loop.size(); ++i) segments.push_back({loop[i], loop[(i + 1) % loop.size()]});
    }
    const lsr::CurveDistance distance(start.vertices, segments);
    const lsr::SignedDistance<2> sdf = [&distance](const lsr::Vec<2>& p) { return distance.signed_distance(p); };
    return lsr::reconstruct_from<2>(points, sdf, c.solver, printer(c.quiet));
  }
  return lsr::reconstruct<D>(points, c.solver, printer(c.quiet));
}

// Where each output goes until the run commits them all (staged_outputs.h).
struct OutputFiles {
  lsr::demos::StagedOutputs staged;
  std::vector<std::string> levels;  ///< the temporary of OUT (or of each level's file)
  std::string report, save_points, volume_mesh;
};

// Solve, write every output to its temporary (the writer returns what it wrote and times its
// stages), commit them together, then one summary line per level.
template <int D, class Write>
int solve_and_write(const Cli& c, const Input& in, const lsr::Points<D>& points, const OuterStages& read_stages,
                    lsr::demos::Stopwatch& total, OutputFiles& files, Write write) {
  std::vector<lsr::ReconstructionResult<D>> levels;
  if (c.levels > 1) {
    levels = lsr::reconstruct_levels<D>(points, c.levels, c.solver, false, printer(c.quiet));
  } else {
    levels.push_back(solve<D>(c, points));
  }
  std::vector<std::string> lines;
  for (std::size_t k = 0; k < levels.size(); ++k) {
    const lsr::ReconstructionResult<D>& r = levels[k];
    summarize(r, c.solver.outlier_factor, c.quiet);
    if (r.status == lsr::ReconstructionStatus::cancelled) return 130;
    const bool finest = k + 1 == levels.size();
    const std::string output = c.levels > 1 ? level_path(c.output, int(k)) : c.output;
    OuterStages stages = read_stages;
    lsr::demos::Stopwatch clock;
    Outcome out = write(r, files.levels[k], clock, stages);
    if (finest && !c.volume_mesh.empty()) {
      lsr::adapters::write_volume_mesh(files.volume_mesh, r.volume);
      out.volume = lsr::volume_mesh_quality(r.volume);
      stages.emplace_back("volume mesh", clock.lap());
      const lsr::VolumeMeshQuality& q = out.volume;
      std::fprintf(stderr,
                   "[volume] %zu inside + %zu outside %s, %s min %.2f median %.1f degrees, %.1f%% with one below 5, "
                   "%zu inverted, %zu surface vertices kept short of the fit to keep their simplices valid -> %s\n",
                   q.inside_simplices, q.outside_simplices, D == 3 ? "tetrahedra" : "triangles",
                   D == 3 ? "dihedral angles" : "angles", q.min_angle_degrees, q.median_angle_degrees,
                   100 * q.small_angle_fraction, q.inverted, r.volume.pulled_back, c.volume_mesh.c_str());
    }
    // One level: the whole run; several: each level's own solve and write.
    double seconds = total.lap();
    if (c.levels > 1) {
      seconds = 0.0;
      for (const auto& stage : r.stages) seconds += r.seconds.at(stage);
      for (std::size_t s = read_stages.size(); s < stages.size(); ++s) seconds += stages[s].second;
    }
    if (finest && !c.report.empty()) write_report(c, in, r, out, output, seconds, stages, files.report);
    char line[1024];
    std::snprintf(line, sizeof(line), "%s: %s, %s after %d steps, %.1f s -> %s\n",
                  c.demo.empty() ? c.input.c_str() : c.demo.c_str(), out.summary.c_str(),
                  r.status == lsr::ReconstructionStatus::converged ? "converged" : "NOT converged", r.iterations, seconds,
                  output.c_str());
    lines.push_back(line);
  }
  // A signal during the writing: nothing is committed.
  if (g_interrupted) return 130;
  files.staged.commit_all();
  for (const auto& l : lines) std::fputs(l.c_str(), stdout);
  return 0;
}

int run(const Cli& c) {
  // Before any work: an output that cannot be written would be lost at the end of the run.
  OutputFiles files{lsr::demos::StagedOutputs(c.input), {}, {}, {}, {}};
  for (int k = 0; k < c.levels; ++k) files.levels.push_back(files.staged.stage(c.levels > 1 ? level_path(c.output, k) : c.output));
  if (!c.report.empty()) files.report = files.staged.stage(c.report);
  if (!c.save_points.empty()) files.save_points = files.staged.stage(c.save_points);
  if (!c.volume_mesh.empty()) files.volume_mesh = files.staged.stage(c.volume_mesh);
  if (!c.init_mesh.empty() && !std::filesystem::exists(c.init_mesh)) {
    throw lsr::Error("the start mesh " + c.init_mesh + " does not exist", "check the --init-mesh path");
  }
  lsr::demos::Stopwatch total;
  lsr::demos::Stopwatch clock;
  Input in = c.demo.empty() ? read_input(c) : generate(c);
  if (!c.save_points.empty()) lsr::demos::write_points(files.save_points, in.points);
  const double read_seconds = clock.lap();
  if (c.dim != 0) in.dim = c.dim;
  const std::string out_ext = lsr::adapters::file_extension(c.output);
  // Three distinct points or fewer are flat whatever they sample: the output decides, the
  // solver then says how many points a closed curve or surface needs.
  if (c.dim == 0 && distinct_points(in.points) <= 3) in.dim = is_curve_output(out_ext) ? 2 : 3;
  if (in.dim == 2 && is_mesh_output(out_ext)) {
    throw lsr::InvalidInput("the input is planar (2D), so the result is curves, not a mesh",
                            "write .svg or .txt (closed curves in the plane); a closed surface needs points that are not all in one plane");
  }
  if (in.dim == 3 && is_curve_output(out_ext)) {
    throw lsr::InvalidInput("the input is 3D, so the result is a surface",
                            "write " + lsr::adapters::extensions(lsr::adapters::FileRole::mesh_output) + ", or pass --dim 2 to use x and y only");
  }
  if (!c.quiet) {
    std::fprintf(stderr, "[read ] %zu points (%zu skipped: NaN / infinite), %dD, %.2f s\n", in.points.size(),
                 in.skipped, in.dim, read_seconds);
  }
  if (c.statistical.mean_k > 0) {
    const std::vector<std::size_t> kept = lsr::adapters::statistical_inliers(in.points, c.statistical);
    in.statistical_outliers = in.points.size() - kept.size();
    lsr::adapters::keep_only(in.points, kept);
    std::fprintf(stderr, "lsrecon: pcl::StatisticalOutlierRemoval (k = %d, %g deviations) left out %zu point(s), %.2f s\n",
                 c.statistical.mean_k, c.statistical.stddev_mul, in.statistical_outliers, clock.lap());
  }
  const OuterStages stages = {{"read", read_seconds}};
  if (in.dim == 2) {
    lsr::Points<2> planar;
    for (const auto& p : in.points) planar.emplace_back(p.x(), p.y());
    auto write = [&](const lsr::ReconstructionResult<2>& r, const std::string& output, lsr::demos::Stopwatch& timer,
                     OuterStages& times) {
      if (out_ext == "svg") {
        const lsr::demos::Curves start = c.init_mesh.empty() ? lsr::demos::Curves{} : lsr::demos::read_polylines(c.init_mesh);
        lsr::demos::write_svg(output, r.surface.vertices, r.loops, planar, c.init_mesh.empty() ? nullptr : &start);
      } else {
        lsr::demos::write_polylines(output, r.surface.vertices, r.loops);
      }
      times.emplace_back("write", timer.lap());
      return Outcome{r.surface.vertices.size(), r.surface.facets.size(), r.loops.size(), int(r.loops.size()), true,
                     std::to_string(r.loops.size()) + " closed curve(s), " + std::to_string(r.surface.vertices.size()) +
                         " vertices",
                     {}};
    };
    return solve_and_write<2>(c, in, planar, stages, total, files, write);
  }
  auto write = [&](const lsr::ReconstructionResult<3>& r, const std::string& output, lsr::demos::Stopwatch& timer,
                   OuterStages& times) {
    lsr::adapters::TriMesh mesh = lsr::adapters::to_openmesh(r.surface, r.normals);
    if (c.decimate > 0) lsr::adapters::decimate(mesh, std::size_t(c.decimate));
    lsr::adapters::smooth(mesh, c.smooth);
    times.emplace_back("postprocess", timer.lap());
    lsr::adapters::write_mesh_file(mesh, output);
    times.emplace_back("write", timer.lap());
    const lsr::LevelSetMesh<3> written = lsr::adapters::from_openmesh(mesh);
    const lsr::SurfaceTopology t = lsr::analyze_surface(written.vertices, written.facets);
    return Outcome{written.vertices.size(), written.facets.size(), 0, t.components, t.watertight,
                   std::to_string(written.facets.size()) + " triangles, " + std::to_string(t.components) +
                       " component(s), " + (t.watertight ? "watertight" : "NOT watertight"),
                   {}};
  };
  return solve_and_write<3>(c, in, in.points, stages, total, files, write);
}

}  // namespace

int main(int argc, char** argv) {
  const Cli c = parse(argc, argv);
  // Each ends the run as Ctrl-C does: nothing written. SIGXFSZ (a file size limit) would
  // otherwise kill the process mid-write; handled, the write fails and says so.
  for (const int signal_number : {SIGINT, SIGTERM, SIGHUP, SIGXFSZ}) std::signal(signal_number, on_interrupt);
  try {
    const int status = run(c);
    if (status == 130) std::fprintf(stderr, "\nlsrecon: interrupted; nothing was written\n");
    return status;
  } catch (const std::exception& e) {
    const std::string message = lsr::demos::StagedOutputs::in_destination_terms(e.what());
    std::cerr << (c.quiet ? "" : "\n") << "lsrecon: " << message << '\n';
    return 1;
  }
}
