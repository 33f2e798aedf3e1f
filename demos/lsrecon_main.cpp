// SPDX-License-Identifier: BSD-3-Clause
/// @file lsrecon_main.cpp
/// @brief The lsrecon command line: a point cloud file (or a generated demo cloud) in, a closed
/// surface (3D) or closed curves (2D) out. Progress and timings on stderr, an optional JSON
/// report, outputs written atomically, non-zero exit with a message that says what to change.
#include "curve_files.h"
#include "image_points.h"
#include "lsrecon/adapters/openmesh_mesh.h"
#include "lsrecon/adapters/point_files.h"
#include "lsrecon/core/analytic_shapes.h"
#include "lsrecon/core/shape_corpus.h"
#include "lsrecon/core/atomic_file.h"
#include "lsrecon/core/level_set_reconstruction.h"
#include "lsrecon/core/surface_topology.h"
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

options (lengths are in the unit box the data is mapped into: its bounding ball has radius 0.4)
  --resolution R                1/h_min, same mesh size everywhere near the data;
                                0 = follow the local sampling spacing             (default 0)
  --max-resolution R            cap on the local resolution (finer = more time,
                                memory, and closer sheets told apart);
                                0 = 256 in 3D, 4096 in 2D                         (default 0)
  --max-size H                  coarsest mesh size                                (default 0.125)
  --grading C                   mesh grading; smaller = wider fine band           (default 2)
  --alpha A                     attraction; 0 = +2 (enclose), -2 (inside)         (default 0)
  --curvature-weight B          smoothness; < 0 = local, from spacing and noise   (default -1)
  --time-step DT                0 = 0.2/|alpha|                                   (default 0)
  --max-iterations N            time steps at most                                (default 1000)
  --tolerance EPS               stop when data and front are this close;
                                0 = one local sampling spacing                    (default 0)
  --hole-radius H               experimental: span sampling holes up to H          (default 0)
  --no-fit                      output the front itself, not the fit through the data
  --keep-outliers               keep isolated points (nearest neighbour farther than
                                3 local spacings); by default they are left out
  --renormalization-interval K  0 = automatic                                     (default 0)
  --init tagged|enclose|inside  start hugging the data from outside (flood from the
                                box walls), on a sphere around it or inside it    (default tagged)
  --dim 2|3                     force the dimension; else 2 for planar input      (default auto)
  --decimate FACES              simplify the 3D result to at most FACES faces     (default off)
  --smooth N                    N rounds of Laplace smoothing of the 3D result    (default 0)
  --threads N                   0 = all cores                                     (default 0)
  --max-memory GIB              refuse clouds and meshes predicted to need more;
                                0 = min(4, half the machine's memory)             (default 0)
  --max-mesh-vertices N         refuse larger meshes; 0 = from --max-memory       (default 0)
  --points N                    points of a --demo cloud                          (default 20000)
  --report FILE.json            write figures of the run as JSON
  --save-points FILE.xyz        also write the input points (a --demo cloud) as text
  --quiet                       no progress on stderr
  --help, -h                    this text
  --version                     the version
  Options take their value as --opt VALUE or --opt=VALUE.

exit status: 0 written (see the summary for convergence), 1 bad input or file error,
             2 bad command line, 130 interrupted (nothing written)
)";

std::atomic<bool> g_interrupted{false};
extern "C" void on_interrupt(int) { g_interrupted = true; }

struct Cli {
  std::string input, output, demo, report, save_points;
  lsr::ReconstructionOptions solver;
  int dim = 0;
  long decimate = 0;
  unsigned smooth = 0;
  int points = 20000;
  bool quiet = false;
};

[[noreturn]] void usage_error(const std::string& message) {
  std::cerr << "lsrecon: " << message << "\n(run lsrecon --help for the usage)\n";
  std::exit(2);
}

double number(const std::string& flag, const char* text, double lo, double hi) {
  char* end = nullptr;
  const double v = std::strtod(text, &end);
  if (end == text || *end != '\0' || !(v >= lo && v <= hi)) {
    std::ostringstream range;
    range << lo << " and " << hi;
    usage_error(flag + " expects a number between " + range.str() + ", got '" + text + "'");
  }
  return v;
}

double integer(const std::string& flag, const char* text, double lo, double hi) {
  const double v = number(flag, text, lo, hi);
  if (v != std::floor(v)) usage_error(flag + " expects a whole number, got '" + text + "'");
  return v;
}

bool is_2d_shape(const std::string& s) { return s == "star" || s == "three-shapes"; }
bool is_curve_output(const std::string& ext) { return lsr::adapters::has_role(ext, lsr::adapters::FileRole::curve_output); }
bool is_mesh_output(const std::string& ext) { return lsr::adapters::has_role(ext, lsr::adapters::FileRole::mesh_output); }

Cli parse(int argc, char** argv) {
  Cli c;
  std::vector<std::string> positional;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    // --opt=value as well as --opt value
    std::string inline_value;
    const std::size_t eq = a.find('=');
    const bool has_inline = a.rfind("--", 0) == 0 && eq != std::string::npos;
    if (has_inline) {
      inline_value = a.substr(eq + 1);
      a.resize(eq);
    }
    if (a == "--help" || a == "-h") {
      std::cout << kUsage;
      std::exit(0);
    }
    if (a == "--version") {
      std::cout << "lsrecon " << LSRECON_VERSION << '\n';
      std::exit(0);
    }
    if (has_inline && (a == "--quiet" || a == "--no-fit" || a == "--keep-outliers")) usage_error(a + " takes no value");
    if (a == "--quiet") {
      c.quiet = true;
      continue;
    }
    if (a == "--no-fit") {
      c.solver.fit_surface = false;
      continue;
    }
    if (a == "--keep-outliers") {
      c.solver.outlier_factor = 0.0;
      continue;
    }
    if (a.rfind("--", 0) != 0) {
      positional.push_back(a);
      continue;
    }
    if (!has_inline && i + 1 >= argc) usage_error("option " + a + " needs a value");
    const char* v = has_inline ? inline_value.c_str() : argv[++i];
    auto& s = c.solver;
    if (a == "--demo") {
      c.demo = v;
    } else if (a == "--resolution") {
      const double r = number(a, v, 0, 1e5);
      if (r > 0 && r < 4) usage_error("--resolution must be 0 (automatic) or at least 4");
      s.h_min = r > 0 ? 1.0 / r : 0.0;
    } else if (a == "--max-resolution") {
      const double r = number(a, v, 0, 1e5);
      if (r > 0 && r < 4) usage_error("--max-resolution must be 0 (automatic) or at least 4");
      s.max_resolution = r;
    } else if (a == "--max-size") {
      s.h_max = number(a, v, 1e-4, 1);
    } else if (a == "--grading") {
      s.grading = number(a, v, 1e-3, 100);
    } else if (a == "--alpha") {
      s.alpha = number(a, v, -1e3, 1e3);
    } else if (a == "--curvature-weight") {
      s.curvature_weight = number(a, v, -1, 1e3);
    } else if (a == "--time-step") {
      s.time_step = number(a, v, 0, 100);
    } else if (a == "--max-iterations") {
      s.max_iterations = int(integer(a, v, 1, 1e7));
    } else if (a == "--tolerance") {
      s.tolerance = number(a, v, 0, 0.5);
    } else if (a == "--hole-radius") {
      s.hole_radius = number(a, v, 0, 0.49);
    } else if (a == "--renormalization-interval") {
      s.renormalization_interval = int(integer(a, v, 0, 1000));
    } else if (a == "--init") {
      const std::string init = v;
      if (init != "tagged" && init != "enclose" && init != "inside") {
        usage_error("--init must be tagged, enclose or inside, got '" + init + "'");
      }
      s.initial_front = init == "inside"    ? lsr::InitialFront::inside
                        : init == "enclose" ? lsr::InitialFront::enclosing
                                            : lsr::InitialFront::tagged;
    } else if (a == "--dim") {
      c.dim = int(integer(a, v, 2, 3));
    } else if (a == "--decimate") {
      c.decimate = long(integer(a, v, 4, 1e9));
    } else if (a == "--smooth") {
      c.smooth = unsigned(integer(a, v, 0, 1000));
    } else if (a == "--threads") {
      s.threads = int(integer(a, v, 0, 1024));
    } else if (a == "--max-mesh-vertices") {
      s.max_vertices = lsr::Index(integer(a, v, 0, 2e9));
    } else if (a == "--max-memory") {
      s.max_memory = number(a, v, 0, 1e5) * double(1 << 30);
    } else if (a == "--points") {
      c.points = int(integer(a, v, 4, 5e7));
    } else if (a == "--report") {
      c.report = v;
    } else if (a == "--save-points") {
      c.save_points = v;
    } else {
      usage_error("unknown option " + a);
    }
  }
  const std::size_t expected = c.demo.empty() ? 2 : 1;
  if (positional.size() != expected) {
    usage_error(c.demo.empty() ? "expected INPUT and OUTPUT" : "with --demo, expected only OUTPUT");
  }
  if (c.demo.empty()) c.input = positional[0];
  c.output = positional.back();
  const auto shapes = lsr::test_shape_names();
  if (!c.demo.empty() && std::find(shapes.begin(), shapes.end(), c.demo) == shapes.end() && !is_2d_shape(c.demo)) {
    usage_error("--demo must be one of the SHAPE names in --help, got '" + c.demo + "'");
  }
  const std::string out = lsr::adapters::file_extension(c.output);
  if (!is_curve_output(out) && !is_mesh_output(out)) {
    usage_error("cannot write '" + c.output + "': use " + lsr::adapters::extensions(lsr::adapters::FileRole::mesh_output) +
                " (3D) or " + lsr::adapters::extensions(lsr::adapters::FileRole::curve_output) + " (2D)");
  }
  if ((c.decimate > 0 || c.smooth > 0) && is_curve_output(out)) usage_error("--decimate and --smooth apply to 3D meshes only");
  return c;
}


// The input as 3D points and its dimension.
struct Input {
  lsr::Points<3> points;
  int dim = 3;
  std::size_t skipped = 0;
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
    std::fprintf(stderr, "\r[%-5s] %3.0f%%  %6.1f s", stage.c_str(), 100 * std::max(0.0, fraction), elapsed);
    if (fraction > 0.05) std::fprintf(stderr, "  ETA %5.1f s ", stage_seconds * (1 - fraction) / fraction);
    return true;
  };
}

struct Outcome {
  std::size_t vertices = 0, faces = 0, curves = 0;
  int components = 0;
  bool watertight = false;
};

template <int D>
void write_report(const Cli& c, const Input& in, const lsr::ReconstructionResult<D>& r, const Outcome& out,
                  double total, const std::vector<std::pair<std::string, double>>& extra_seconds) {
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
                        {"initial_front", o.initial_front == lsr::InitialFront::tagged      ? "tagged"
                                          : o.initial_front == lsr::InitialFront::enclosing ? "enclose"
                                                                                             : "inside"},
                        {"max_memory_bytes", o.max_memory},
                        {"max_mesh_vertices", o.max_vertices},
                        {"threads", o.threads}};
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
                 {"tolerance_input_units", r.tolerance},
                 {"unreached_points", r.unreached_points},
                 {"spacing_input_units", r.spacing},
                 {"noise_input_units", r.noise},
                 {"tagged_start", r.tagged_start},
                 {"stage_seconds", stages},
                 {"total_seconds", total},
                 {"peak_memory_mib", lsr::demos::peak_memory_mib()},
                 {"output", c.output},
                 {"output_vertices", out.vertices},
                 {D == 2 ? "curves" : "output_faces", D == 2 ? out.curves : out.faces},
                 {"components", out.components},
                 {"watertight", out.watertight}};
  lsr::write_file_atomically(c.report, [&](const std::string& file) {
    std::ofstream j(file);
    if (!j) throw lsr::Error("cannot write the report " + c.report, "check that the folder exists");
    j << report.dump(2) << '\n';
    if (!j.flush()) throw lsr::Error("writing " + c.report + " failed", "check free disk space");
  });
}

// Why a run stopped short, from what it measured: the step limit, noise, or points never reached.
template <int D>
std::string not_converged_hint(const lsr::ReconstructionResult<D>& r) {
  std::ostringstream s;
  s.precision(3);
  if (r.best_iteration == r.iterations) {
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
void summarize(const lsr::ReconstructionResult<D>& r, bool quiet) {
  if (!quiet) {
    std::fputc('\n', stderr);
    for (const auto& stage : r.stages) std::fprintf(stderr, "  %-14s %8.3f s\n", stage.c_str(), r.seconds.at(stage));
  }
  if (r.outlier_points > 0) {
    std::fprintf(stderr, "lsrecon: left out %zu isolated point(s) (nearest neighbour farther than 3 local spacings); "
                         "--keep-outliers keeps them\n", r.outlier_points);
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

// Before any work: a result that cannot be written would be lost at the end of the run.
void check_writable(const std::string& file, const std::string& input) {
  namespace fs = std::filesystem;
  const fs::path out(file);
  const fs::path dir = out.has_parent_path() ? out.parent_path() : fs::path(".");
  std::error_code e;
  if (!fs::is_directory(dir, e)) throw lsr::Error("the output directory " + dir.string() + " does not exist", "create it first");
  if (::access(dir.c_str(), W_OK) != 0) {
    throw lsr::Error("cannot write in " + dir.string() + " (permission denied)", "write the output elsewhere");
  }
  if (fs::is_directory(out, e)) throw lsr::Error(file + " is a directory", "name an output file");
  if (!input.empty() && fs::exists(out, e) && fs::equivalent(input, out, e)) {
    throw lsr::Error(file + " is the input file", "name another output file; the input would be overwritten");
  }
}

int run(const Cli& c) {
  check_writable(c.output, c.input);
  if (!c.report.empty()) check_writable(c.report, c.input);
  if (!c.save_points.empty()) check_writable(c.save_points, c.input);
  lsr::demos::Stopwatch total;
  lsr::demos::Stopwatch clock;
  Input in = c.demo.empty() ? read_input(c) : generate(c);
  if (!c.save_points.empty()) lsr::demos::write_points(c.save_points, in.points);
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
  Outcome out;
  if (in.dim == 2) {
    lsr::Points<2> planar;
    for (const auto& p : in.points) planar.emplace_back(p.x(), p.y());
    const auto r = lsr::reconstruct<2>(planar, c.solver, printer(c.quiet));
    summarize(r, c.quiet);
    if (r.status == lsr::ReconstructionStatus::cancelled) return 130;
    clock.lap();
    if (out_ext == "svg") {
      lsr::demos::write_svg(c.output, r.surface.vertices, r.loops, planar);
    } else {
      lsr::demos::write_polylines(c.output, r.surface.vertices, r.loops);
    }
    out = {r.surface.vertices.size(), r.surface.facets.size(), r.loops.size(), int(r.loops.size()), true};
    const double write_seconds = clock.lap();
    const double seconds = total.lap();
    if (!c.report.empty()) write_report(c, in, r, out, seconds, {{"read", read_seconds}, {"write", write_seconds}});
    std::printf("%s: %zu closed curve(s), %zu vertices, %s after %d steps, %.1f s -> %s\n",
                c.demo.empty() ? c.input.c_str() : c.demo.c_str(), r.loops.size(), r.surface.vertices.size(),
                r.status == lsr::ReconstructionStatus::converged ? "converged" : "NOT converged", r.iterations,
                seconds, c.output.c_str());
    return 0;
  }
  const auto r = lsr::reconstruct<3>(in.points, c.solver, printer(c.quiet));
  summarize(r, c.quiet);
  if (r.status == lsr::ReconstructionStatus::cancelled) return 130;
  clock.lap();
  lsr::adapters::TriMesh mesh = lsr::adapters::to_openmesh(r.surface, r.normals);
  if (c.decimate > 0) lsr::adapters::decimate(mesh, std::size_t(c.decimate));
  lsr::adapters::smooth(mesh, c.smooth);
  const double postprocess_seconds = clock.lap();
  lsr::adapters::write_mesh_file(mesh, c.output);
  const double write_seconds = clock.lap();
  const lsr::LevelSetMesh<3> written = lsr::adapters::from_openmesh(mesh);
  const lsr::SurfaceTopology t = lsr::analyze_surface(written.vertices, written.facets);
  out = {written.vertices.size(), written.facets.size(), 0, t.components, t.watertight};
  const double seconds = total.lap();
  if (!c.report.empty()) {
    write_report(c, in, r, out, seconds, {{"read", read_seconds}, {"postprocess", postprocess_seconds}, {"write", write_seconds}});
  }
  std::printf("%s: %zu triangles, %d component(s), %s, %s after %d steps, %.1f s -> %s\n",
              c.demo.empty() ? c.input.c_str() : c.demo.c_str(), written.facets.size(), t.components,
              t.watertight ? "watertight" : "NOT watertight",
              r.status == lsr::ReconstructionStatus::converged ? "converged" : "NOT converged", r.iterations, seconds,
              c.output.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const Cli c = parse(argc, argv);
  std::signal(SIGINT, on_interrupt);
  std::signal(SIGTERM, on_interrupt);
  try {
    const int status = run(c);
    if (status == 130) std::fprintf(stderr, "\nlsrecon: interrupted; nothing was written\n");
    return status;
  } catch (const std::exception& e) {
    std::cerr << (c.quiet ? "" : "\n") << "lsrecon: " << e.what() << '\n';
    return 1;
  }
}
