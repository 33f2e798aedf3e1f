// SPDX-License-Identifier: BSD-3-Clause
/// @file run_report.cpp
#include "run_report.h"

#include "stopwatch.h"

#include "lsrecon/core/errors.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <fstream>
#include <sstream>

namespace lsr::demos {

template <int D>
void write_report(const Cli& c, const Input& in, const lsr::ReconstructionResult<D>& r, const Outcome& out,
                  const std::string& output, double total, const OuterStages& extra_seconds, const std::string& file) {
  using nlohmann::json;
  const lsr::ReconstructionOptions& o = c.solver;
  // The options as given (0 = automatic); lengths in the unit box the data is mapped into.
  const json options = {{"resolution", o.mesh.h_min > 0.0 ? 1.0 / o.mesh.h_min : 0.0},
                        {"max_resolution", o.mesh.max_resolution},
                        {"max_size_unit_box", o.mesh.h_max},
                        {"grading", o.mesh.grading},
                        {"anisotropic", o.mesh.anisotropic},
                        {"anisotropic_error", o.mesh.anisotropic_error},
                        {"alpha", o.evolution.alpha},
                        {"curvature_weight", o.evolution.curvature_weight},
                        {"time_step", o.evolution.time_step},
                        {"max_iterations", o.stopping.max_iterations},
                        {"tolerance_unit_box", o.stopping.tolerance},
                        {"hole_radius_unit_box", o.sampling.hole_radius},
                        {"fit_surface", o.output.fit_surface},
                        {"outlier_factor", o.sampling.outlier_factor},
                        {"scan_lines", scan_lines_name(o.sampling.scan_lines)},
                        {"renormalization_interval", o.evolution.renormalization_interval},
                        {"initial_front", initial_front_name(o.start.initial_front)},
                        {"max_memory_bytes", o.limits.max_memory},
                        {"max_mesh_vertices", o.limits.max_vertices},
                        {"threads", o.limits.threads},
                        {"tiles", o.limits.tiles},
                        {"two_sided", o.evolution.two_sided},
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
                       : r.status == lsr::ReconstructionStatus::shared        ? "shared"
                                                                              : "cancelled";
  json report = {{"lsrecon_version", LSRECON_VERSION},
                 {"input", c.demo.empty() ? c.input : "demo:" + c.demo},
                 {"input_points", in.points.size() + in.skipped + in.other_ranks},
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
                 {"scan_lines", r.scan_lines},
                 {"tagged_start", r.tagged_start},
                 {"sealed_cavities", r.sealed_cavities},
                 {"open_side_points", r.open_side_points},
                 {"stage_seconds", stages},
                 {"total_seconds", total},
                 {"peak_memory_mib", lsr::demos::peak_memory_mib()},
                 {"output", output},
                 {"output_vertices", out.vertices},
                 {D == 2 ? "curves" : "output_faces", D == 2 ? out.curves : out.faces},
                 {"components", out.components},
                 {"watertight", out.watertight},
                 {"embedded", out.intersecting_pairs == 0},
                 {"intersecting_pairs", out.intersecting_pairs}};
  if (!c.volume_mesh.empty()) {
    const lsr::VolumeMeshQuality& q = out.volume;
    report["volume_mesh"] = {{"file", c.volume_mesh},
                             {"inside_simplices", q.inside_simplices},
                             {"outside_simplices", q.outside_simplices},
                             {"inverted", q.inverted},
                             {"min_relative_measure", q.min_relative_measure},
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
  if (r.scan_lines) {
    std::fprintf(stderr, "lsrecon: read as scan lines (dense along lines, sparser across): spacings from the gaps "
                         "between lines; --scan-lines no reads the points as scattered samples\n");
  }
  if (r.open_side_points > 0) {
    std::fprintf(stderr, "lsrecon: the data are open (%lld points seen from both sides: an unseen underside, a single "
                         "view); the open sides were closed where the data wind round more than half\n",
                 static_cast<long long>(r.open_side_points));
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

template void write_report<2>(const Cli&, const Input&, const lsr::ReconstructionResult<2>&, const Outcome&, const std::string&,
                              double, const OuterStages&, const std::string&);
template void write_report<3>(const Cli&, const Input&, const lsr::ReconstructionResult<3>&, const Outcome&, const std::string&,
                              double, const OuterStages&, const std::string&);
template void summarize<2>(const lsr::ReconstructionResult<2>&, double, bool);
template void summarize<3>(const lsr::ReconstructionResult<3>&, double, bool);

}  // namespace lsr::demos
