// SPDX-License-Identifier: BSD-3-Clause
/// @file cli_options.cpp
#include "cli_options.h"

#include "command_line.h"
#include "lsrecon/adapters/point_files.h"
#include "lsrecon/testdata/shape_corpus.h"

#include <algorithm>
#include <sstream>
#include <vector>

namespace lsr::demos {
namespace {

const char* kUsage = R"(usage: lsrecon INPUT OUTPUT [options]
       lsrecon --demo SHAPE OUTPUT [options]

Reconstructs a closed surface (3D) or closed curves (2D) from unoriented points with the
level-set method of Claisse & Frey (2011). No normals needed.

INPUT   .pcd .ply (point clouds), .xyz .txt (x y [z] or x,y,z per line), .obj .off .stl (vertices),
        .conf (range scans registered as in the Stanford 3D Scanning Repository),
        .pgm .ppm .pbm .png (2D: every dark pixel is a point)
OUTPUT  3D: .ply .obj .off (double precision) .stl .vtk (float)
        2D: .svg (drawing) or .txt (one closed polyline per loop)
        .ply also holds each vertex's distance to the nearest data point (property "distance",
        input units; with --smooth, before smoothing): large where the surface is a guess (a
        side no view saw, a spanned hole). To keep only what the data support, drop the faces
        with a vertex farther than a few spacings (the report's spacing_input_units).
SHAPE   generated clouds: i.i.d. random samples of sphere torus double-torus triple-torus
        trefoil linked-rings cup limb two-spheres (3D); star three-shapes (2D)

Options take their value as --opt VALUE or --opt=VALUE; (=X) is the default. Lengths are in the
unit box the data is mapped into (its bounding ball has radius 0.4); 0 means "from the data".
)";

const char* kExitStatus = R"(exit status: 0 written (see the summary for convergence), 1 bad input or file error,
             2 bad command line, 130 interrupted (nothing written)
)";

}  // namespace

bool is_2d_shape(const std::string& s) { return s == "star" || s == "three-shapes"; }
bool is_curve_output(const std::string& ext) { return lsr::adapters::has_role(ext, lsr::adapters::FileRole::curve_output); }
bool is_mesh_output(const std::string& ext) { return lsr::adapters::has_role(ext, lsr::adapters::FileRole::mesh_output); }

std::string format_number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

const char* initial_front_name(lsr::InitialFront f) {
  return f == lsr::InitialFront::tagged      ? "tagged"
         : f == lsr::InitialFront::enclosing ? "enclose"
         : f == lsr::InitialFront::occupancy ? "occupancy"
                                             : "inside";
}

const char* scan_lines_name(lsr::ScanLines s) {
  return s == lsr::ScanLines::yes ? "yes" : s == lsr::ScanLines::no ? "no" : "auto";
}

// Every option once: its default is the value Cli (and so lsr::ReconstructionOptions) starts with.
Cli parse(int argc, char** argv) {
  Cli c;
  auto& s = c.solver;
  lsr::demos::CommandLine line("lsrecon", LSRECON_VERSION, kUsage, kExitStatus);
  std::string init = initial_front_name(s.start.initial_front);
  std::string scan_lines = scan_lines_name(s.sampling.scan_lines);
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
      .text("save-points", "FILE", c.save_points, "also write the input points (a --demo cloud): FILE.ply binary, else text")
      .text("volume-mesh", "FILE", c.volume_mesh,
            "also write meshes of the inside (label 1) and the outside (2) of the result within the box, "
            "sharing its surface (label 10; box walls 20): .mesh (Medit), .msh (Gmsh 2.2), .vtu")
      .flag("quiet", c.quiet, "no progress on stderr");
  line.group("mesh")
      .number("resolution", "R", s.mesh.h_min > 0 ? 1 / s.mesh.h_min : 0.0, 0, 1e5, false,
              "1/h_min, the same mesh size everywhere near the data; 0 = follow the local sampling spacing",
              [&](double r) { s.mesh.h_min = resolution("--resolution", r) > 0 ? 1.0 / r : 0.0; })
      .number("max-resolution", "R", s.mesh.max_resolution, 0, 1e5, false,
              "cap on the local resolution (finer = more time and memory, closer sheets told apart); "
              "0 = " + format_number(lsr::automatic_defaults(3).max_resolution) + " in 3D, " +
                  format_number(lsr::automatic_defaults(2).max_resolution) + " in 2D",
              [&](double r) { s.mesh.max_resolution = resolution("--max-resolution", r); })
      .number("max-size", "H", s.mesh.h_max, 1e-4, 1, "coarsest mesh size")
      .number("grading", "C", s.mesh.grading, 1e-3, 100, "mesh grading; smaller = wider fine band")
      .flag("anisotropic", s.mesh.anisotropic, "adapt the mesh to the data's curvature (elements long and thin along "
            "flat parts, the paper's section 6.2): fewer vertices")
      .number("anisotropic-error", "E", s.mesh.anisotropic_error, 1e-3, 100,
              "with --anisotropic: the chord error allowed along the data, in local mesh sizes");
  line.group("front")
      .text("init", "START", init, "tagged: hug the data from outside (flood from the box walls); "
            "enclose: a sphere around it; inside: a sphere inside it; occupancy: where the data's winding "
            "number is above 1/2 (experimental)", {"tagged", "enclose", "inside", "occupancy"})
      .text("init-mesh", "FILE", c.init_mesh,
            "start from this closed surface (.ply .obj .off .stl .vtk; a previous scan, a rough model) or, "
            "in 2D, closed curves (.txt as lsrecon writes them), which may cross the data: the front is "
            "then attracted from both sides")
      .number("alpha", "A", s.evolution.alpha, -1e3, 1e3, "attraction to the data; 0 = +" + format_number(lsr::automatic_defaults(3).alpha) + " (from outside), -" +
                  format_number(lsr::automatic_defaults(3).alpha) + " (inside)")
      .number("curvature-weight", "B", s.evolution.curvature_weight, -1, 1e3, "smoothness; < 0 = local, from spacing and noise")
      .number("time-step", "DT", s.evolution.time_step, 0, 100, "0 = " + format_number(lsr::automatic_defaults(3).time_step_factor) + " / |alpha|")
      .number("max-iterations", "N", s.stopping.max_iterations, 1, 1e7, "time steps at most")
      .number("tolerance", "EPS", s.stopping.tolerance, 0, 0.5, "stop when data and front are this close; 0 = one local sampling spacing")
      .number("renormalization-interval", "K", s.evolution.renormalization_interval, 0, s.stopping.patience,
              "renormalise every K steps (the stopping test measures the front then); 0 = automatic")
      .number("hole-radius", "H", s.sampling.hole_radius, -1, 0.49, "span sampling holes up to radius H with tangent discs on their rims (docs/how-it-works.md: Sampling holes); -1 = " +
                  format_number(lsr::automatic_defaults(3).hole_radius) + " in 3D, off in 2D; 0 = off");
  line.group("data and result")
      .text("scan-lines", "MODE", scan_lines, "3D: read the points as scan lines (yes: spacings from the gaps between "
            "lines) or as scattered samples (no); auto = decided from the cloud", {"auto", "yes", "no"})
      .flag("keep-outliers", keep_outliers, "keep isolated points (nearest neighbour farther than " +
            format_number(s.sampling.outlier_factor) + " local spacings); by default they are left out")
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
      .number("threads", "N", s.limits.threads, 0, 1024, "0 = all cores")
      .number("tiles", "N", s.limits.tiles, 0, 1e6,
              "split the sampling of the points into N tiles (runs along a Z-order curve, one after another; "
              "lsrecon-mpi shares them among its ranks): less memory at once, the same result; 0 = one")
      .number("solve-tiles", "K", s.limits.solve_tiles, 1, 64,
              "experimental: solve the front in K x K x K tiles, one mesh at a time, welded at the seams (less "
              "memory at once, a memory limit per tile): one mesh's topology on random samples and most scans, not yet "
              "everywhere on unseen undersides; no --volume-mesh or "
              "--anisotropic; 1 = one mesh")
      .number("max-memory", "GIB", s.limits.max_memory / double(1 << 30), 0, 1e5, false,
              "refuse clouds and meshes predicted to need more; 0 = half the machine's memory",
              [&](double gib) { s.limits.max_memory = gib * double(1 << 30); })
      .number("max-mesh-vertices", "N", s.limits.max_vertices, 0, 2e9, "refuse larger meshes; 0 = from --max-memory");
  const std::vector<std::string> positional = line.parse(argc, argv, 1, 2, "INPUT OUTPUT (or --demo SHAPE OUTPUT)");
  if (no_fit) s.output.fit_surface = false;
  if (keep_outliers) s.sampling.outlier_factor = 0.0;
  s.sampling.scan_lines = scan_lines == "yes" ? lsr::ScanLines::yes : scan_lines == "no" ? lsr::ScanLines::no : lsr::ScanLines::automatic;
  s.start.initial_front = init == "inside"      ? lsr::InitialFront::inside
                         : init == "enclose"   ? lsr::InitialFront::enclosing
                         : init == "occupancy" ? lsr::InitialFront::occupancy
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
    s.evolution.two_sided = true;
  }
  if (!c.volume_mesh.empty()) {
    if (!lsr::adapters::has_role(lsr::adapters::file_extension(c.volume_mesh), lsr::adapters::FileRole::volume_output)) {
      line.fail("cannot write the volume mesh '" + c.volume_mesh + "': use " +
                lsr::adapters::extensions(lsr::adapters::FileRole::volume_output));
    }
    if (c.decimate > 0 || c.smooth > 0) line.fail("--decimate and --smooth would detach the surface from --volume-mesh");
    s.output.volume_mesh = true;
  }
  return c;
}

}  // namespace lsr::demos
