// SPDX-License-Identifier: BSD-3-Clause
/// @file lsrecon_main.cpp
/// @brief The lsrecon command line: a point cloud file (or a generated demo cloud) in, a closed
/// surface (3D) or closed curves (2D) out. Progress and timings on stderr, an optional JSON
/// report, outputs written atomically, non-zero exit with a message that says what to change.
#include "cli_options.h"
#include "geometry/facet_mesh_distance.h"
#include "geometry/self_intersections.h"
#include "lsrecon/adapters/curve_files.h"
#include "lsrecon/adapters/image_points.h"
#ifdef LSRECON_MPI
#include "lsrecon/adapters/mpi_tile_exchange.h"
#endif
#include "lsrecon/adapters/openmesh_mesh.h"
#include "lsrecon/adapters/point_files.h"
#include "lsrecon/adapters/statistical_outliers.h"
#include "lsrecon/adapters/volume_mesh_files.h"
#include "lsrecon/core/level_set_reconstruction.h"
#include "lsrecon/core/resolution_hierarchy.h"
#include "lsrecon/testdata/analytic_shapes.h"
#include "lsrecon/testdata/shape_corpus.h"
#include "run_report.h"
#include "staged_outputs.h"
#include "stopwatch.h"
#include "surface/surface_topology.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <sstream>
#include <string>

namespace {

using namespace lsr::demos;

std::atomic<bool> g_interrupted{false};
extern "C" void on_interrupt(int) { g_interrupted = true; }

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

Input read_input(const Cli& c, lsr::adapters::FileShare share) {
  Input in;
  const std::string ext = lsr::adapters::file_extension(c.input);
  if (lsr::adapters::has_role(ext, lsr::adapters::FileRole::image_input)) {
    for (const auto& p : lsr::adapters::read_image_points(c.input)) in.points.emplace_back(p.x(), p.y(), 0.0);
    in.dim = 2;
    return in;
  }
  lsr::adapters::PointFile file = lsr::adapters::read_point_file(c.input, share);
  in.points = std::move(file.points);
  in.skipped = file.skipped;
  in.other_ranks = file.other_rows;
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
    const lsr::adapters::Curves start = lsr::adapters::read_polylines(c.init_mesh);
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
    summarize(r, c.solver.sampling.outlier_factor, c.quiet);
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
                   "%zu inverted, smallest %.1e of the mean %s, %zu surface vertices kept short of the fit to keep their simplices valid -> %s\n",
                   q.inside_simplices, q.outside_simplices, D == 3 ? "tetrahedra" : "triangles",
                   D == 3 ? "dihedral angles" : "angles", q.min_angle_degrees, q.median_angle_degrees,
                   100 * q.small_angle_fraction, q.inverted, q.min_relative_measure, D == 3 ? "volume" : "area",
                   r.volume.pulled_back, c.volume_mesh.c_str());
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

// lsrecon-mpi: 2 if every rank's points lie in one plane z = const (detect_dimension of the
// whole cloud) or a rank read a 2D file; the non-finite points of every share counted in rank 0's.
int dimension_over_ranks(const lsr::TileExchange& x, Input& in) {
  struct Share {
    double lo, hi;
    std::size_t skipped;
  };
  Share mine{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(), in.skipped};
  for (const auto& p : in.points) mine = {std::min(mine.lo, p.z()), std::max(mine.hi, p.z()), in.skipped};
  std::vector<std::vector<unsigned char>> bytes(std::size_t(x.workers()), std::vector<unsigned char>(sizeof(Share)));
  for (auto& b : bytes) std::memcpy(b.data(), &mine, sizeof(Share));
  x.all_to_all(bytes);
  Share all{mine.lo, mine.hi, 0};
  for (const auto& b : bytes) {
    Share each;
    std::memcpy(&each, b.data(), sizeof(Share));
    all = {std::min(all.lo, each.lo), std::max(all.hi, each.hi), all.skipped + each.skipped};
  }
  if (x.worker() == 0) {
    in.other_ranks -= all.skipped - in.skipped;
    in.skipped = all.skipped;
  }
  return in.dim == 2 || all.lo == all.hi ? 2 : 3;
}

// The points as the solver gets them: read (or generated), their dimension settled, the
// statistical outliers left out. With files, the points are also saved if asked.
Input prepared_input(const Cli& c, OutputFiles* files, double& read_seconds) {
  lsr::demos::Stopwatch clock;
  // lsrecon-mpi: each rank reads its share of the points, in rank order (tile_exchange.h).
  const lsr::TileExchange* x = c.solver.limits.exchange.get();
  const lsr::adapters::FileShare share{x ? std::size_t(x->worker()) : 0, x ? std::size_t(x->workers()) : 1};
  if (share.parts > 1 && (c.statistical.mean_k > 0 || !c.save_points.empty())) {
    throw lsr::InvalidInput(std::string(c.statistical.mean_k > 0 ? "--sor-mean-k (statistical outlier removal)" : "--save-points") +
                                " reads the whole cloud, which lsrecon-mpi splits among its ranks",
                            "run lsrecon for it");
  }
  Input in = c.demo.empty() ? read_input(c, share) : generate(c);
  if (!c.demo.empty() && share.parts > 1) {
    const std::size_t n = in.points.size();
    lsr::Points<3> part(in.points.begin() + long(share.part * n / share.parts), in.points.begin() + long((share.part + 1) * n / share.parts));
    in.other_ranks = n - part.size();
    in.points = std::move(part);
  }
  if (share.parts > 1 && dimension_over_ranks(*x, in) == 2) {
    throw lsr::InvalidInput("the input is planar (2D): lsrecon-mpi reconstructs surfaces", "run lsrecon for closed curves");
  }
  if (files && !c.save_points.empty()) lsr::adapters::write_points(files->save_points, in.points);
  read_seconds = clock.lap();
  if (c.dim != 0) in.dim = c.dim;
  const std::string out_ext = lsr::adapters::file_extension(c.output);
  // Three distinct points or fewer are flat whatever they sample: the output decides, the
  // solver then says how many points a closed curve or surface needs.
  if (c.dim == 0 && share.parts == 1 && distinct_points(in.points) <= 3) in.dim = is_curve_output(out_ext) ? 2 : 3;
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
    if (files) {
      std::fprintf(stderr, "lsrecon: pcl::StatisticalOutlierRemoval (k = %d, %g deviations) left out %zu point(s), %.2f s\n",
                   c.statistical.mean_k, c.statistical.stddev_mul, in.statistical_outliers, clock.lap());
    }
  }
  return in;
}

lsr::Points<2> planar(const Input& in) {
  lsr::Points<2> xy;
  for (const auto& p : in.points) xy.emplace_back(p.x(), p.y());
  return xy;
}

#ifdef LSRECON_MPI
// A rank other than 0 of lsrecon-mpi: its share of the points, the same options, its part of the
// sampling (lsrecon/core/tile_exchange.h), nothing written.
int share_run(const Cli& c) {
  double read_seconds = 0.0;
  const Input in = prepared_input(c, nullptr, read_seconds);
  const lsr::ReconstructionStatus status = in.dim == 2 ? solve<2>(c, planar(in)).status : solve<3>(c, in.points).status;
  if (status == lsr::ReconstructionStatus::cancelled) return 130;
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  std::fprintf(stderr, "lsrecon-mpi: rank %d of %d shared its run of the cloud%s, peak memory %.0f MiB\n",
               c.solver.limits.exchange->worker(), c.solver.limits.exchange->workers(),
               c.solver.limits.solve_tiles > 1 ? " and solved its tiles" : "", double(usage.ru_maxrss) / 1024.0);
  return 0;
}
#endif

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
  double read_seconds = 0.0;
  const Input in = prepared_input(c, &files, read_seconds);
  const OuterStages stages = {{"read", read_seconds}};
  const std::string out_ext = lsr::adapters::file_extension(c.output);
  if (in.dim == 2) {
    const lsr::Points<2> xy = planar(in);
    auto write = [&](const lsr::ReconstructionResult<2>& r, const std::string& output, lsr::demos::Stopwatch& timer,
                     OuterStages& times) {
      if (out_ext == "svg") {
        const lsr::adapters::Curves start = c.init_mesh.empty() ? lsr::adapters::Curves{} : lsr::adapters::read_polylines(c.init_mesh);
        lsr::adapters::write_svg(output, r.surface.vertices, r.loops, xy, c.init_mesh.empty() ? nullptr : &start);
      } else {
        lsr::adapters::write_polylines(output, r.surface.vertices, r.loops);
      }
      times.emplace_back("write", timer.lap());
      const std::size_t crossings = lsr::detail::count_self_intersections(r.surface.vertices, r.surface.facets, c.solver.limits.threads);
      return Outcome{r.surface.vertices.size(), r.surface.facets.size(), r.loops.size(), int(r.loops.size()), true, crossings,
                     std::to_string(r.loops.size()) + " closed curve(s), " + std::to_string(r.surface.vertices.size()) +
                         " vertices, " + (crossings == 0 ? "simple" : std::to_string(crossings) + " crossing pairs of segments"),
                     {}};
    };
    return solve_and_write<2>(c, in, xy, stages, total, files, write);
  }
  auto write = [&](const lsr::ReconstructionResult<3>& r, const std::string& output, lsr::demos::Stopwatch& timer,
                   OuterStages& times) {
    lsr::adapters::TriMesh mesh = lsr::adapters::to_openmesh(r.surface, r.normals);
    lsr::adapters::set_distance_to_data(mesh, r.distance_to_data);
    if (c.decimate > 0) lsr::adapters::decimate(mesh, std::size_t(c.decimate));
    lsr::adapters::smooth(mesh, c.smooth);
    times.emplace_back("postprocess", timer.lap());
    lsr::adapters::write_mesh_file(mesh, output);
    times.emplace_back("write", timer.lap());
    const lsr::LevelSetMesh<3> written = lsr::adapters::from_openmesh(mesh);
    const lsr::SurfaceTopology t = lsr::analyze_surface(written.vertices, written.facets);
    const std::size_t crossings = lsr::detail::count_self_intersections(written.vertices, written.facets, c.solver.limits.threads);
    return Outcome{written.vertices.size(), written.facets.size(), 0, t.components, t.watertight, crossings,
                   std::to_string(written.facets.size()) + " triangles, " + std::to_string(t.components) + " component(s), " +
                       (t.watertight ? "watertight" : "NOT watertight") + ", " +
                       (crossings == 0 ? "embedded" : std::to_string(crossings) + " intersecting pairs of triangles"),
                   {}};
  };
  return solve_and_write<3>(c, in, in.points, stages, total, files, write);
}

}  // namespace

#ifdef LSRECON_MPI
// A barrier that sleeps: Open MPI's blocking calls (MPI_Finalize among them) poll at full speed,
// and a rank done with its tiles would take a core from rank 0 until the end (1M-point scan, 2
// ranks on 2 cores: 98 s against 76 s for lsrecon).
void wait_for_all_ranks() {
  MPI_Request request;
  MPI_Ibarrier(MPI_COMM_WORLD, &request);
  for (int done = 0; MPI_Test(&request, &done, MPI_STATUS_IGNORE), !done;) usleep(20000);
}

// lsrecon-mpi: every rank parses the same command line and reads its share of the input (from
// shared storage); rank 0 runs lsrecon, the others share the sampling (and the front's tiles,
// --solve-tiles) with it and stop. A rank
// that fails aborts them all, as the others would wait for it.
int main(int argc, char** argv) {
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);  // OpenMP threads make no MPI calls
  Cli c = parse(argc, argv);
  for (const int signal_number : {SIGINT, SIGTERM, SIGHUP, SIGXFSZ}) std::signal(signal_number, on_interrupt);
  int status = 1;
  int rank = 0;
  try {
    const auto exchange = std::make_shared<const lsr::adapters::MpiTileExchange>();
    rank = exchange->worker();
    if (c.levels > 1) {
      throw lsr::InvalidInput("--levels runs several reconstructions, which lsrecon-mpi does not share yet", "run lsrecon for levels");
    }
    c.solver.limits.exchange = exchange;
    if (rank != 0) c.quiet = true;
    status = rank == 0 ? run(c) : share_run(c);
    if (status == 130) std::fprintf(stderr, "\nlsrecon-mpi: rank %d interrupted; nothing was written\n", rank);
  } catch (const std::exception& e) {
    const std::string message = lsr::demos::StagedOutputs::in_destination_terms(e.what());
    std::cerr << (c.quiet ? "" : "\n") << "lsrecon-mpi: rank " << rank << ": " << message << '\n';
    status = 1;
  }
  if (status != 0) MPI_Abort(MPI_COMM_WORLD, status);
  wait_for_all_ranks();
  MPI_Finalize();
  return 0;
}
#else
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
#endif
