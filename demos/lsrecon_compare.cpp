// SPDX-License-Identifier: BSD-3-Clause
/// @file lsrecon_compare.cpp
/// @brief lsrecon against PCL's reconstructors on the same clouds, in one run: time (normal
/// estimation included where a method needs normals), peak memory, distances to the ground
/// truth, normal consistency and topology. Writes results.md, results.csv, every mesh as PLY
/// and, per case, lsrecon's convergence history.
///
///   lsrecon-compare [--out DIR] [--cases a,b,.. | --input FILE] [--methods a,b,..] [...]
/// (lsrecon-compare --help lists the options.) --input compares on a user's cloud: time, memory
/// and topology only (no ground truth).
///
/// Each (case, method) runs in a child process (this program re-run with --run) so that its
/// peak memory is its own.
#include "command_line.h"
#include "compare_cases.h"
#include "compare_methods.h"
#include "mesh_measures.h"
#include "geometry/self_intersections.h"
#include "surface/embedded_moves.h"
#include "lsrecon/adapters/pcl_mesh.h"
#include "lsrecon/adapters/point_files.h"
#include "lsrecon/pcl/level_set_reconstruction.h"
#include "lsrecon/testdata/surface_distance.h"
#include "stopwatch.h"
#include "surface/surface_topology.h"

#include <pcl/common/io.h>
#include <pcl/features/normal_3d_omp.h>
#include <pcl/io/ply_io.h>
#include <pcl/surface/gp3.h>
#include <pcl/surface/marching_cubes_hoppe.h>
#include <pcl/surface/marching_cubes_rbf.h>
#include <pcl/surface/poisson.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <unordered_map>

namespace {

using lsr::demos::kMethods;
using lsr::demos::Produced;
using lsr::demos::run_method;



struct Settings {
  std::string out = "compare-out";
  std::string input;  ///< a user's cloud instead of the generated cases: no ground truth
  std::vector<std::string> cases = lsr::demos::case_names();
  std::vector<std::string> methods = {"lsrecon", "poisson8", "poisson8-lsrecon", "poisson8-true", "mc-hoppe", "mc-rbf", "gp3"};
  int points = 20000;
  lsr::SamplingVariant variant;
  int seed = int(lsr::demos::kDefaultSeed);
  lsr::ScannerSettings scanner;  ///< used when scanner.views > 0
  lsr::demos::LsreconOptions lsrecon;  ///< passed on to lsrecon
  int repeat = 1;  ///< runs per (case, method), interleaved; the row of the median time is kept
  bool save_points = false;  ///< also write each generated cloud as DIR/<case>-points.ply
};

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');) out.push_back(item);
  return out;
}

std::string join(const std::vector<std::string>& items, const std::string& separator) {
  std::string out;
  for (const auto& item : items) out += (out.empty() ? "" : separator) + item;
  return out;
}

// max distance data <-> front per time step, in units of the tolerance, on a log scale.
void write_convergence_svg(const std::string& path, const std::string& title, const std::vector<double>& residuals) {
  const double w = 640, h = 400, left = 60, bottom = 40, top = 30;
  double hi = 1.0, lo = 1.0;
  for (double r : residuals) {
    if (std::isfinite(r) && r > 0) {
      hi = std::max(hi, r);
      lo = std::min(lo, r);
    }
  }
  const double l0 = std::floor(std::log10(lo)), l1 = std::ceil(std::log10(hi));
  const double n = std::max<std::size_t>(2, residuals.size());
  auto X = [&](double i) { return left + (w - left - 20) * i / (n - 1); };
  auto Y = [&](double r) { return top + (h - top - bottom) * (l1 - std::log10(r)) / std::max(1.0, l1 - l0); };
  std::ofstream svg(path);
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << w << "\" height=\"" << h << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n<text x=\"" << left << "\" y=\"18\">" << title
      << ": max distance between data and front / tolerance, per time step</text>\n";
  for (double e = l0; e <= l1; ++e) {
    svg << "<line x1=\"" << left << "\" x2=\"" << w - 20 << "\" y1=\"" << Y(std::pow(10, e)) << "\" y2=\"" << Y(std::pow(10, e))
        << "\" stroke=\"#ddd\"/><text x=\"8\" y=\"" << Y(std::pow(10, e)) + 4 << "\">1e" << e << "</text>\n";
  }
  svg << "<line x1=\"" << left << "\" x2=\"" << w - 20 << "\" y1=\"" << Y(1) << "\" y2=\"" << Y(1)
      << "\" stroke=\"#c33\" stroke-dasharray=\"4 3\"/>\n<polyline fill=\"none\" stroke=\"#1f3a93\" stroke-width=\"2\" points=\"";
  for (std::size_t i = 0; i < residuals.size(); ++i) {
    if (std::isfinite(residuals[i]) && residuals[i] > 0) svg << X(double(i)) << ',' << Y(residuals[i]) << ' ';
  }
  svg << "\"/>\n<text x=\"" << w / 2 << "\" y=\"" << h - 10 << "\">time step (" << residuals.size() << ")</text>\n</svg>\n";
}

// Child: one case, one method; prints one CSV row.
// A user's file: the points, and the normals a PLY file carries (a scanner's: poisson8-true is
// then Poisson given them). Without ground truth the distance columns stay empty.
lsr::demos::CompareCase file_case(const std::string& path) {
  lsr::demos::CompareCase c;
  c.name = "file";
  c.points = lsr::adapters::read_point_file(path).points;
  pcl::PCLPointCloud2 cloud;
  if (lsr::adapters::file_extension(path) == "ply" && pcl::io::loadPLYFile(path, cloud) == 0 &&
      pcl::getFieldIndex(cloud, "normal_x") >= 0 && std::size_t(cloud.width) * cloud.height == c.points.size()) {
    pcl::PointCloud<pcl::Normal> normals;
    pcl::fromPCLPointCloud2(cloud, normals);
    for (const auto& n : normals) c.normals.emplace_back(n.normal_x, n.normal_y, n.normal_z);
  }
  Eigen::Vector3d lo = c.points.at(0), hi = c.points.at(0);
  for (const auto& p : c.points) {
    lo = lo.cwiseMin(Eigen::Vector3d(p));
    hi = hi.cwiseMax(Eigen::Vector3d(p));
  }
  c.diagonal = (hi - lo).norm();
  return c;
}

int run_one(const Settings& s, const std::string& case_name, const std::string& method) {
  const lsr::demos::CompareCase c = s.input.empty()
                                        ? lsr::demos::make_case(case_name, s.points, s.variant, unsigned(s.seed),
                                                                 s.scanner.views > 0 ? &s.scanner : nullptr)
                                        : file_case(s.input);
  if (method == "poisson8-true" && c.normals.empty()) {
    std::printf("%s,%s,%zu,,,,,,,,,,,,,,no true normals\n", case_name.c_str(), method.c_str(), c.points.size());
    return 0;
  }
  if (s.save_points && s.input.empty()) lsr::adapters::write_points(s.out + "/" + case_name + "-points.ply", c.points);
  lsr::demos::Stopwatch clock;
  const Produced p = run_method(method, c, s.lsrecon);
  const double seconds = clock.lap();
  const double memory = lsr::demos::peak_memory_mib();
  lsr::Points<3> vertices;
  std::vector<std::array<lsr::Index, 3>> triangles;
  if (p.indexed) {
    lsr::adapters::triangles_from_polygon_mesh(p.mesh, vertices, triangles);
  } else {
    lsr::demos::weld(p.mesh, c.diagonal, vertices, triangles);
  }
  const lsr::SurfaceTopology t = lsr::analyze_surface(vertices, triangles);
  // As saved (floats, below): the pairs of triangles that intersect, decided exactly.
  lsr::Points<3> saved = vertices;
  for (auto& v : saved) v = lsr::detail::rounded_to_float(v);
  const std::size_t intersecting = lsr::detail::count_self_intersections(saved, triangles, 0);
  const lsr::SurfaceDistances d = c.sdf ? lsr::compare_to_truth(vertices, triangles, c.sdf, c.truth, 100000)
                                        : lsr::SurfaceDistances{};
  // The welded mesh, without normals (PCL's marching cubes emit all-zero normals, which
  // renderers light black), through PCL: OpenMesh refuses the non-manifold faces Poisson emits.
  pcl::PolygonMesh welded;
  pcl::PointCloud<pcl::PointXYZ> welded_vertices;
  for (const auto& v : vertices) welded_vertices.push_back(pcl::PointXYZ(float(v.x()), float(v.y()), float(v.z())));
  pcl::toPCLPointCloud2(welded_vertices, welded.cloud);
  welded.polygons = lsr::adapters::polygons_from_triangles(triangles);
  pcl::io::savePLYFileBinary(s.out + "/" + case_name + "-" + method + ".ply", welded);
  if (!p.residuals.empty()) write_convergence_svg(s.out + "/" + case_name + "-convergence.svg", case_name, p.residuals);
  std::string genus;
  for (int g : t.genus) genus += (genus.empty() ? "" : " ") + std::to_string(g);
  if (t.genus.size() > 4) genus = "(" + std::to_string(t.genus.size()) + " parts)";
  auto metric = [&](double v, const char* format) {
    char text[32];
    std::snprintf(text, sizeof text, format, v);
    return c.sdf ? std::string(text) : std::string("n/a");
  };
  const lsr::demos::SupportFigures support = lsr::demos::support_figures(vertices, triangles, c.points);
  std::printf("%s,%s,%zu,%.3f,%.0f,%s,%s,%s,%d,%d,%zu,%d,%s,%zu,%.6g,%.4f,%s\n", case_name.c_str(), method.c_str(),
              c.points.size(), seconds, memory, metric(d.chamfer / c.diagonal, "%.3e").c_str(),
              metric(d.hausdorff / c.diagonal, "%.3e").c_str(), metric(d.normal_consistency, "%.3f").c_str(),
              int(t.watertight), int(t.edge_manifold && t.vertex_manifold), intersecting, t.components, genus.c_str(),
              triangles.size(), support.area, support.far_share, p.note.c_str());
  return 0;
}

std::string child_row(const char* self, const Settings& s, const std::string& case_name, const std::string& method) {
  std::ostringstream command;
  command.precision(17);
  command << self << " --run " << case_name << '/' << method << " --out '" << s.out << "'"
          << (s.input.empty() ? "" : " --input '" + s.input + "'") << " --points " << s.points << " --noise "
          << s.variant.noise << " --holes " << s.variant.holes << " --density-ratio " << s.variant.density_ratio
          << " --seed " << s.seed << " --hole-radius " << s.lsrecon.hole_radius << " --max-resolution " << s.lsrecon.max_resolution
          << " --solve-tiles " << s.lsrecon.solve_tiles
          << " --scan-views " << s.scanner.views << " --scan-lines " << s.scanner.lines << " --scan-samples "
          << s.scanner.samples_per_line << (s.scanner.from_above ? " --from-above" : "") << " --scan-noise "
          << s.scanner.range_noise << " --misregistration " << s.scanner.registration_angle << " --misregistration-shift "
          << s.scanner.registration_shift << (s.save_points ? " --save-points" : "") << " 2>/dev/null";
  FILE* pipe = popen(command.str().c_str(), "r");
  std::string row;
  char buffer[4096];
  while (pipe && std::fgets(buffer, sizeof buffer, pipe)) row = buffer;
  const int status = pipe ? pclose(pipe) : -1;
  if (status != 0 || row.empty()) return case_name + "," + method + ",,,,,,,,,,,,,,,failed (exit " + std::to_string(status) + ")\n";
  return row;
}

double row_seconds(const std::string& row) {
  std::stringstream in(row);
  std::string cell;
  for (int k = 0; k < 4; ++k) std::getline(in, cell, ',');
  return cell.empty() ? std::numeric_limits<double>::infinity() : std::atof(cell.c_str());  // failed runs last
}

// The run of median time (the upper median of an even count), its note listing every run's time.
std::string median_run(std::vector<std::string> runs) {
  if (runs.size() == 1) return runs[0];
  std::vector<double> seconds;
  for (const auto& r : runs) seconds.push_back(row_seconds(r));
  std::string times;
  for (double t : seconds) {
    char text[32];
    std::snprintf(text, sizeof text, "%s%.3f", times.empty() ? "" : " ", t);
    times += text;
  }
  std::stable_sort(runs.begin(), runs.end(), [](const std::string& a, const std::string& b) { return row_seconds(a) < row_seconds(b); });
  std::string row = runs[runs.size() / 2];
  if (!row.empty() && row.back() == '\n') row.pop_back();
  return row + " (median of " + std::to_string(runs.size()) + " runs: " + times + " s)\n";
}

// lsrecon / poisson8 (PCL normal estimation + Poisson depth 8, as PCL ships it: one thread) and
// lsrecon / poisson8-mt (the same on every core) per case, where they ran; lsrecon-tiles /
// lsrecon (its front in tiles against one mesh) with the Chamfer distances' ratio too.
void write_ratios(std::ostream& md, const std::vector<std::string>& rows) {
  struct Figures {
    double seconds, mib, chamfer, area;
  };
  std::map<std::string, std::map<std::string, Figures>> figures;  // case -> method
  for (const auto& row : rows) {
    std::stringstream in(row);
    std::string name, method, points, seconds, memory, chamfer;
    std::getline(in, name, ',');
    std::getline(in, method, ',');
    std::getline(in, points, ',');
    std::getline(in, seconds, ',');
    std::getline(in, memory, ',');
    std::getline(in, chamfer, ',');
    std::string area;
    for (int k = 6; k <= 14; ++k) std::getline(in, area, ',');  // column 14: the area
    const double c = chamfer.empty() || chamfer == "n/a" ? std::nan("") : std::atof(chamfer.c_str());
    const double a = area.empty() ? std::nan("") : std::atof(area.c_str());
    if (!seconds.empty() && !memory.empty()) figures[name][method] = {std::atof(seconds.c_str()), std::atof(memory.c_str()), c, a};
  }
  // The area against Poisson given the true (or the scanner's) normals: flaps and fins add area.
  for (const std::string ours : {"lsrecon", "lsrecon-occupancy"}) {
    bool area_header = false;
    for (const auto& [name, methods] : figures) {
      if (!methods.count(ours) || !methods.count("poisson8-true") || !(methods.at("poisson8-true").area > 0.0)) continue;
      if (!area_header) md << "\n| case | area " << ours << " / poisson8-true |\n|---|--:|\n";
      area_header = true;
      char line[96];
      std::snprintf(line, sizeof line, "| %s | %.3f |\n", name.c_str(), methods.at(ours).area / methods.at("poisson8-true").area);
      md << line;
    }
  }
  for (const std::string compared : {"poisson8", "poisson8-mt", "lsrecon-tiles"}) {
    const bool tiles = compared == "lsrecon-tiles";
    const std::string a_name = tiles ? compared : "lsrecon", b_name = tiles ? "lsrecon" : compared;
    bool header = false;
    for (const auto& [name, methods] : figures) {
      if (!methods.count(a_name) || !methods.count(b_name)) continue;
      if (!header) {
        const std::string r = " " + a_name + " / " + b_name + " |";
        md << "\n| case | time" << r << " peak memory" << r << (tiles ? " Chamfer" + r + "\n|---|--:|--:|--:|\n" : "\n|---|--:|--:|\n");
        header = true;
      }
      const Figures& a = methods.at(a_name);
      const Figures& b = methods.at(b_name);
      char line[160];
      std::snprintf(line, sizeof line, "| %s | %.2f | %.2f |", name.c_str(), a.seconds / b.seconds, a.mib / b.mib);
      md << line;
      if (tiles) {
        std::snprintf(line, sizeof line, " %.3f |", a.chamfer / b.chamfer);
        md << (std::isnan(a.chamfer / b.chamfer) ? std::string(" n/a |") : std::string(line));
      }
      md << "\n";
    }
  }
}

void write_markdown(const std::string& path, const std::vector<std::string>& rows, const Settings& s) {
  std::ofstream md(path);
  md << "| case | method | points | seconds | peak MiB | Chamfer / diag | Hausdorff / diag | normal consistency | "
        "watertight | manifold | intersecting pairs | components | genus | triangles | area | far from data | note |\n"
     << "|---|---|--:|--:|--:|--:|--:|--:|:-:|:-:|--:|--:|--:|--:|--:|--:|---|\n";
  for (const auto& row : rows) {
    std::stringstream in(row);
    std::string cell;
    md << "|";
    int k = 0;
    while (std::getline(in, cell, ',')) {
      if (!cell.empty() && cell.back() == '\n') cell.pop_back();
      if (k == 8 || k == 9) cell = cell == "1" ? "yes" : cell == "0" ? "no" : cell;
      md << ' ' << cell << " |";
      ++k;
    }
    md << '\n';
  }
  write_ratios(md, rows);
  if (s.scanner.views > 0) {
    md << "\nSimulated scans: " << s.scanner.views << " views" << (s.scanner.from_above ? " from above" : "") << ", "
       << s.scanner.lines << " lines x " << s.scanner.samples_per_line << " samples, range noise " << s.scanner.range_noise
       << ", misregistration " << s.scanner.registration_angle << " rad and " << s.scanner.registration_shift
       << " x diagonal per view, seed " << s.seed << ".\n";
    return;
  }
  if (s.input.empty())
    md << "\nPoints per case: " << s.points << " i.i.d. area-uniform, noise " << s.variant.noise << " x diagonal, "
       << s.variant.holes << " holes of radius " << s.variant.hole_radius << " x diagonal, density ratio "
       << s.variant.density_ratio << ", seed " << s.seed << ".";
  md << "\nSeconds include normal estimation for the methods that need normals (PCA of 16 neighbours, oriented "
     << "away from the centroid).\n";
}

// Every option once; the defaults are Settings'.
Settings parse(int argc, char** argv, std::string& run_case, std::string& run_method) {
  Settings s;
  std::string cases = "all", methods = join(s.methods, ","), run;
  lsr::demos::CommandLine line(
      "lsrecon-compare", LSRECON_VERSION,
      "usage: lsrecon-compare [options]\n\n"
      "lsrecon against PCL's reconstructors on the same clouds: time, peak memory, distances to the\n"
      "exact surface, normal consistency and topology. Writes DIR/results.md, results.csv and every mesh.\n"
      "Each (case, method) runs in its own process, so that its peak memory is its own.\n");
  line.group("what to compare")
      .text("cases", "A,B,..", cases, "generated clouds (all, or some of: " + join(lsr::demos::case_names(), " ") + ")")
      .text("input", "FILE", s.input, "a cloud of yours instead: time, memory and topology only (no ground truth)")
      .text("methods", "A,B,..", methods, "reconstructors, some of: " + join(kMethods, " "))
      .text("out", "DIR", s.out, "where results and meshes go")
      .flag("save-points", s.save_points, "also write each generated cloud as DIR/CASE-points.ply (binary doubles; to rerun it with lsrecon)")
      .number("repeat", "N", s.repeat, 1, 99,
              "runs per case and method, the methods taking turns; reports the run of median time "
              "(this machine's times vary 10-20% between runs)");
  line.group("generated clouds (i.i.d. area-uniform random samples)")
      .number("points", "N", s.points, 4, 5e7, "points per cloud")
      .number("noise", "S", s.variant.noise, 0, 0.5, "Gaussian noise, times the diagonal")
      .number("holes", "N", s.variant.holes, 0, 100, "unsampled caps")
      .number("density-ratio", "R", s.variant.density_ratio, 1, 1e4, "densest / sparsest, varying along x")
      .number("seed", "N", s.seed, 0, 2147483647,
              "the draw: another seed, another cloud of the same shape (how much a figure owes to one draw)");
  s.scanner.views = 0;
  line.group("simulated scans (instead of i.i.d. samples: --scan-views > 0)")
      .number("scan-views", "N", s.scanner.views, 0, 100, "viewpoints around the shape; 0 = i.i.d. samples")
      .flag("from-above", s.scanner.from_above, "viewpoints above the shape only: its underside unseen")
      .number("scan-lines", "N", s.scanner.lines, 2, 1e5, "scan lines per view")
      .number("scan-samples", "N", s.scanner.samples_per_line, 2, 1e5, "samples along each line")
      .number("scan-noise", "S", s.scanner.range_noise, 0, 0.1, "Gaussian range error, relative to the range")
      .number("misregistration", "RAD", s.scanner.registration_angle, 0, 0.5, "per-view rotation error")
      .number("misregistration-shift", "S", s.scanner.registration_shift, 0, 0.5,
              "per-view translation error, times the diagonal");
  line.group("lsrecon")
      .number("hole-radius", "H", s.lsrecon.hole_radius, -1, 0.49, "lsrecon's --hole-radius")
      .number("max-resolution", "R", s.lsrecon.max_resolution, 0, 65536, "lsrecon's --max-resolution (0: its default)")
      .number("solve-tiles", "K", s.lsrecon.solve_tiles, 1, 64, "lsrecon's --solve-tiles (1: one mesh)");
  line.group("internal").text("run", "CASE/METHOD", run, "run one case in this process (the parent run does)");
  line.parse(argc, argv, 0, 0, "no positional argument");
  if (cases != "all") s.cases = split(cases);
  s.methods = split(methods);
  for (const auto& m : s.methods) {
    if (std::find(kMethods.begin(), kMethods.end(), m) == kMethods.end()) line.fail("unknown method '" + m + "'");
  }
  const auto known = lsr::demos::case_names();
  for (const auto& c : s.cases) {
    if (std::find(known.begin(), known.end(), c) == known.end() && c != "file") line.fail("unknown case '" + c + "'");
  }
  if (!run.empty()) {
    const std::size_t slash = run.find('/');
    if (slash == std::string::npos) line.fail("--run expects CASE/METHOD, got '" + run + "'");
    run_case = run.substr(0, slash);
    run_method = run.substr(slash + 1);
  }
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  std::string run_case, run_method_name;
  Settings s = parse(argc, argv, run_case, run_method_name);
  try {
    if (!run_case.empty()) return run_one(s, run_case, run_method_name);
    std::filesystem::create_directories(s.out);
    if (!s.input.empty()) s.cases = {"file"};
    std::vector<std::string> rows;
    for (const auto& c : s.cases) {
      std::vector<std::vector<std::string>> runs(s.methods.size());
      for (int r = 0; r < s.repeat; ++r) {
        for (std::size_t m = 0; m < s.methods.size(); ++m) {
          std::fprintf(stderr, "%-12s %-14s ", c.c_str(), s.methods[m].c_str());
          runs[m].push_back(child_row(argv[0], s, c, s.methods[m]));
          std::fprintf(stderr, "%s", runs[m].back().c_str());
        }
      }
      for (auto& r : runs) rows.push_back(median_run(r));
    }
    std::ofstream csv(s.out + "/results.csv");
    csv << "case,method,points,seconds,peak_mib,chamfer_rel,hausdorff_rel,normal_consistency,watertight,manifold,"
           "intersecting_pairs,components,genus,triangles,area,far_share,note\n";
    for (const auto& r : rows) csv << r;
    write_markdown(s.out + "/results.md", rows, s);
    std::fprintf(stderr, "wrote %s/results.md, results.csv and the meshes\n", s.out.c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lsrecon-compare: %s\n", e.what());
    return 1;
  }
  return 0;
}
