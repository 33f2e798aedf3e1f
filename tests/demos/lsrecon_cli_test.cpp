// SPDX-License-Identifier: BSD-3-Clause
/// @file lsrecon_cli_test.cpp
/// @brief The lsrecon command line as a user runs it: every input and output format, the JSON
/// report, and every documented error path (exit code and message).
#include "cli_fixture.h"
#include "lsrecon/adapters/pcl_mesh.h"
#include "lsrecon/adapters/point_files.h"
#include "lsrecon/core/level_set_extraction.h"
#include "lsrecon/core/level_set_reconstruction.h"
#include "mesh/adaptive_refinement.h"

#include <pcl/common/io.h>
#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>
#include <pcl/io/vtk_lib_io.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace {

using lsr_test::Cli;
using lsr_test::CliRun;
using lsr_test::expect_closed_mesh;
namespace fs = std::filesystem;

// The PLY output holds each vertex's distance to the data (documented in --help). On a complete
// i.i.d. sample no part is a guess: every vertex lies within the widest gap the solver assumes
// between samples (SamplingOptions::gap_factor spacings) of a point.
TEST_F(Cli, PlyOutputHoldsTheDistanceToTheData) {
  const CliRun r = run("--demo sphere --points 3000 --quiet " + path("s.ply") + " --report " + path("s.json"));
  ASSERT_EQ(r.status, 0) << r.output;
  pcl::PolygonMesh mesh;
  ASSERT_EQ(pcl::io::loadPLYFile(path("s.ply"), mesh), 0);
  const int field = pcl::getFieldIndex(mesh.cloud, "distance");
  ASSERT_GE(field, 0);
  ASSERT_EQ(mesh.cloud.fields[std::size_t(field)].datatype, pcl::PCLPointField::FLOAT64);
  std::ifstream report(path("s.json"));
  const double spacing = nlohmann::json::parse(report)["spacing_input_units"];
  const std::size_t n = std::size_t(mesh.cloud.width) * mesh.cloud.height;
  ASSERT_GT(n, 0u);
  for (std::size_t i = 0; i < n; ++i) {
    double d = 0.0;
    std::memcpy(&d, &mesh.cloud.data[i * mesh.cloud.point_step + mesh.cloud.fields[std::size_t(field)].offset], sizeof d);
    EXPECT_GE(d, 0.0);
    EXPECT_LE(d, lsr::ReconstructionOptions().sampling.gap_factor * spacing) << i;
  }
  const CliRun help = run("--help");
  EXPECT_NE(help.output.find("distance to the nearest data point"), std::string::npos);
}

TEST_F(Cli, ReadsEveryInputFormat) {
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (const auto& p : sphere()) cloud.push_back(pcl::PointXYZ(float(p.x()), float(p.y()), float(p.z())));
  cloud.push_back(pcl::PointXYZ(NAN, 0, 0));
  pcl::io::savePCDFileBinary(path("in.pcd"), cloud);
  pcl::io::savePLYFileBinary(path("in.ply"), cloud);
  std::ofstream xyz(path("in.xyz")), obj(path("in.obj")), off(path("in.off"));
  xyz << "# a comment\n";
  off << "OFF\n" << sphere().size() << " 0 0\n";
  for (const auto& p : sphere()) {
    xyz << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
    obj << "v " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
    off << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  }
  xyz.close();
  obj.close();
  off.close();
  for (const char* in : {"in.pcd", "in.ply", "in.xyz", "in.obj", "in.off"}) {
    const CliRun r = run(path(in) + " " + path("out.ply") + " --resolution 32 --quiet");
    EXPECT_EQ(r.status, 0) << in << ": " << r.output;
    EXPECT_NE(r.output.find("converged"), std::string::npos) << r.output;
    expect_closed_mesh(path("out.ply"));
  }
}

TEST_F(Cli, WritesEveryMeshFormatAndTheReport) {
  for (const char* out : {"t.ply", "t.obj", "t.off", "t.stl"}) {
    const CliRun r = run("--demo torus --points 5000 --resolution 32 --quiet " + path(out) + " --report " + path("r.json"));
    ASSERT_EQ(r.status, 0) << r.output;
    expect_closed_mesh(path(out), 1);
  }
  // Valid JSON whatever the path holds; units in the names; stages in pipeline order.
  const nlohmann::json j = nlohmann::json::parse(read("r.json"));
  for (const char* field : {"input_points", "dimension", "h_min_unit_box", "mesh_vertices", "mesh_simplices", "time_steps",
                            "status", "converged", "residual_input_units", "tolerance_input_units", "stage_seconds",
                            "total_seconds", "peak_memory_mib", "output_vertices", "output_faces", "components",
                            "watertight", "embedded", "intersecting_pairs", "scan_lines", "options"}) {
    EXPECT_TRUE(j.contains(field)) << field;
  }
  EXPECT_TRUE(j["watertight"].get<bool>());
  EXPECT_TRUE(j["embedded"].get<bool>());
  EXPECT_EQ(j["intersecting_pairs"].get<std::size_t>(), 0u);
  EXPECT_FALSE(j["scan_lines"].get<bool>());  // random samples
  EXPECT_EQ(j["options"]["scan_lines"].get<std::string>(), "auto");
  EXPECT_EQ(j["options"]["resolution"].get<double>(), 32.0);
  std::vector<std::string> stages;
  for (const auto& s : j["stage_seconds"]) stages.push_back(s["stage"].get<std::string>());
  ASSERT_GE(stages.size(), 4u);
  EXPECT_EQ(stages.front(), "read");
  EXPECT_EQ(stages.back(), "write");
  EXPECT_LT(std::find(stages.begin(), stages.end(), "mesh") - stages.begin(),
            std::find(stages.begin(), stages.end(), "solve") - stages.begin());
  // A path with a quote and a backslash stays valid JSON.
  const std::string odd = path("a\"b\\c.json");
  ASSERT_EQ(run("--demo sphere --points 3000 --resolution 32 --quiet " + path("s.ply") + " --report '" + odd + "'").status, 0);
  std::ifstream odd_in(odd);
  const nlohmann::json o = nlohmann::json::parse(odd_in);
  EXPECT_EQ(o["output"].get<std::string>(), path("s.ply"));
  // Read as scan lines when told, and said so.
  const CliRun lines = run("--demo sphere --points 3000 --resolution 32 --scan-lines yes " + path("s.ply") + " --report " + path("l.json"));
  ASSERT_EQ(lines.status, 0) << lines.output;
  EXPECT_NE(lines.output.find("read as scan lines"), std::string::npos) << lines.output;
  EXPECT_TRUE(nlohmann::json::parse(read("l.json"))["scan_lines"].get<bool>());
}

TEST_F(Cli, WritesVtkAsPclDoes) {
  const CliRun r = run("--demo torus --points 5000 --resolution 32 --quiet " + path("t.vtk"));
  ASSERT_EQ(r.status, 0) << r.output;
  pcl::PolygonMesh mesh;
  ASSERT_GT(pcl::io::loadPolygonFileVTK(path("t.vtk"), mesh), 0);
  lsr::Points<3> vertices;
  std::vector<std::array<lsr::Index, 3>> triangles;
  lsr::adapters::triangles_from_polygon_mesh(mesh, vertices, triangles);
  const lsr::SurfaceTopology t = lsr::analyze_surface(vertices, triangles);
  EXPECT_TRUE(t.watertight);
  EXPECT_EQ(t.genus, std::vector<int>{1});
}

TEST_F(Cli, DecimatesToTheRequestedFaceCount) {
  const CliRun r = run("--demo sphere --points 4000 --resolution 32 --decimate 500 --quiet " + path("s.off"));
  ASSERT_EQ(r.status, 0) << r.output;
  lsr::adapters::TriMesh mesh;
  ASSERT_TRUE(OpenMesh::IO::read_mesh(mesh, path("s.off")));
  EXPECT_LE(mesh.n_faces(), 500u);
  expect_closed_mesh(path("s.off"));
}

TEST_F(Cli, TwoDimensionalInputsGiveClosedLoops) {
  // A PGM image: a dark ring of radius 40 px, as in the paper's first example.
  {
    std::ofstream pgm(path("ring.pgm"), std::ios::binary);
    pgm << "P5\n128 128\n255\n";
    for (int y = 0; y < 128; ++y) {
      for (int x = 0; x < 128; ++x) {
        const double r = std::hypot(x + 0.5 - 64, y + 0.5 - 64);
        pgm.put(char(std::abs(r - 40) < 1.0 ? 0 : 255));
      }
    }
  }
  CliRun r = run(path("ring.pgm") + " " + path("ring.txt") + " --quiet");
  ASSERT_EQ(r.status, 0) << r.output;
  std::ifstream loops(path("ring.txt"));
  std::string line;
  int headers = 0, vertices = 0;
  double worst = 0;
  while (std::getline(loops, line)) {
    if (line.rfind("# loop", 0) == 0) ++headers;
    if (line.empty() || line[0] == '#') continue;
    double x, y;
    std::istringstream(line) >> x >> y;
    worst = std::max(worst, std::abs(std::hypot(x - 64, y - 64) - 40));
    ++vertices;
  }
  EXPECT_EQ(headers, 1);
  EXPECT_GT(vertices, 100);
  EXPECT_LE(worst, 2.0);  // pixels are 1 wide: within two pixels of the ring
  // A two-column text file to SVG.
  std::ofstream xy(path("c.xy"));
  for (const auto& p : lsr::Circle{lsr::Vec<2>(0, 0), 3.0}.sample(1000)) xy << p.x() << ' ' << p.y() << '\n';
  xy.close();
  r = run(path("c.xy") + " " + path("c.svg") + " --quiet");
  ASSERT_EQ(r.status, 0) << r.output;
  std::ifstream svg(path("c.svg"));
  std::stringstream s;
  s << svg.rdbuf();
  EXPECT_EQ(s.str().rfind("<svg", 0), 0u);
  EXPECT_NE(s.str().find(" Z\""), std::string::npos);  // a closed path
}

TEST_F(Cli, CommandLineErrorsExitWithTwoAndSayWhatToChange) {
  for (const std::string& args : {std::string("--resolution abc in.xyz out.ply"), std::string("--bogus 1 in.xyz out.ply"),
                                  std::string("in.xyz out.xyz"), std::string("in.xyz"), std::string("--demo cube out.ply"),
                                  std::string("--demo star out.svg --decimate 100"), std::string("--resolution")}) {
    const CliRun r = run(args);
    EXPECT_EQ(r.status, 2) << args << ": " << r.output;
    EXPECT_NE(r.output.find("lsrecon: "), std::string::npos) << args;
  }
  const CliRun help = run("--help");
  EXPECT_EQ(help.status, 0);
  EXPECT_NE(help.output.find("--resolution"), std::string::npos);
  // An abbreviation is refused, not guessed: --res could be --resolution or --report.
  EXPECT_EQ(run("--demo sphere " + path("o.ply") + " --res 64").status, 2);
  EXPECT_EQ(run("--demo sphere " + path("o.ply") + " --quiet=1").status, 2);
  EXPECT_EQ(run("-h").status, 0);
}

// Counts of the labels in each section of a Medit file: section -> label -> entities.
std::map<std::string, std::map<int, int>> medit_labels(const std::string& file) {
  std::ifstream in(file);
  std::map<std::string, std::map<int, int>> labels;
  std::string word;
  while (in >> word) {
    if (word != "Vertices" && word != "Tetrahedra" && word != "Triangles" && word != "Edges") continue;
    const int per_entity = word == "Vertices" ? 0 : word == "Tetrahedra" ? 4 : word == "Triangles" ? 3 : 2;
    std::size_t n = 0;
    in >> n;
    for (std::size_t i = 0; i < n; ++i) {
      double skip = 0;
      const int reads = per_entity == 0 ? 3 : per_entity;  // 3D coordinates or vertex indices
      for (int k = 0; k < reads; ++k) in >> skip;
      int label = 0;
      in >> label;
      ++labels[word][label];
    }
  }
  return labels;
}

// Inside and outside meshes in the three formats, 3D and 2D, labelled as documented.
TEST_F(Cli, WritesVolumeMeshesInThreeFormats) {
  CliRun r = run("--demo sphere --points 3000 --quiet " + path("s.ply") + " --volume-mesh " + path("s.mesh") +
                 " --report " + path("s.json"));
  ASSERT_EQ(r.status, 0) << r.output;
  auto labels = medit_labels(path("s.mesh"));
  EXPECT_GT(labels["Tetrahedra"][1], 0);
  EXPECT_GT(labels["Tetrahedra"][2], 0);
  EXPECT_EQ(labels["Tetrahedra"].size(), 2u);
  EXPECT_EQ(labels["Triangles"].size(), 2u);  // the surface (10) and the box walls (20)
  // The surface written is the inside's boundary: as many triangles as the output mesh.
  pcl::PolygonMesh mesh;
  ASSERT_EQ(pcl::io::loadPLYFile(path("s.ply"), mesh), 0);
  EXPECT_EQ(labels["Triangles"][10], int(mesh.polygons.size()));
  std::ifstream report(path("s.json"));
  const nlohmann::json j = nlohmann::json::parse(report);
  EXPECT_EQ(j["volume_mesh"]["inverted"].get<int>(), 0);
  EXPECT_EQ(j["volume_mesh"]["inside_simplices"].get<int>(), labels["Tetrahedra"][1]);

  r = run("--demo three-shapes --points 3000 --quiet " + path("t.svg") + " --volume-mesh " + path("t.msh"));
  ASSERT_EQ(r.status, 0) << r.output;
  const std::string msh = read("t.msh");
  EXPECT_EQ(msh.rfind("$MeshFormat\n2.2 0 8\n", 0), 0u);
  EXPECT_NE(msh.find("2 1 \"inside\""), std::string::npos);
  EXPECT_NE(msh.find("1 10 \"surface\""), std::string::npos);
  r = run("--demo three-shapes --points 3000 --quiet " + path("t.svg") + " --volume-mesh " + path("t.vtu"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(read("t.vtu").find("Name=\"region\""), std::string::npos);
  // Unknown format, and a post-processing that would detach the surface: refused up front.
  EXPECT_EQ(run("--demo sphere " + path("o.ply") + " --volume-mesh " + path("o.stl")).status, 2);
  EXPECT_EQ(run("--demo sphere " + path("o.ply") + " --volume-mesh " + path("o.mesh") + " --smooth 2").status, 2);
  EXPECT_FALSE(fs::exists(path("o.ply")));
}

// A user's closed mesh as the start, crossing the data: a sphere through the tube of the demo
// torus becomes the torus (1 part, genus 1, embedded), converged.
TEST_F(Cli, StartsFromAClosedMeshThatCrossesTheData) {
  const lsr::Sphere sphere{lsr::Vec<3>(0.5, 0.5, 0.5), 0.4};
  lsr::AdaptiveMeshOptions o;
  o.h_min = 1.0 / 32;
  const lsr::AdaptiveMesh<3> m = lsr::build_adaptive_mesh(lsr::NearestPointIndex<3>(sphere.sample(2000)), o);
  std::vector<double> u(m.mesh.vertices.size());
  for (std::size_t i = 0; i < u.size(); ++i) u[i] = sphere.signed_distance(m.mesh.vertices[i]);
  const lsr::LevelSetMesh<3> unit = lsr::extract_zero_level_set(m.mesh, u);
  // The torus demo has R = 1, r = 0.4 in its own units. A sphere of radius 1.2 about its centre
  // cuts the tube's outer half; one of 1.05, the paper's figure 8 in 3D, cuts it near its core
  // circle and leaves two sheets spanning the hole where the data pull neither way.
  for (const double radius : {1.2, 1.05}) {
    lsr::LevelSetMesh<3> start = unit;
    for (auto& v : start.vertices) v = (v - sphere.center) * (radius / sphere.radius);
    lsr::adapters::write_mesh_file(lsr::adapters::to_openmesh(start, {}), path("start.off"));
    const CliRun r = run("--demo torus --points 6000 --quiet --init-mesh " + path("start.off") + " " + path("t.off"));
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find(" converged"), std::string::npos) << radius << ": " << r.output;
    expect_closed_mesh(path("t.off"), 1);
  }
  // An open start mesh, a missing one, or a 2D output: refused, nothing written.
  std::ofstream(path("open.off")) << "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  CliRun bad = run("--demo torus --points 3000 --quiet --init-mesh " + path("open.off") + " " + path("o.off"));
  EXPECT_EQ(bad.status, 1);
  EXPECT_NE(bad.output.find("not closed"), std::string::npos) << bad.output;
  EXPECT_EQ(run("--demo torus --quiet --init-mesh " + path("none.off") + " " + path("o.off")).status, 1);
  EXPECT_EQ(run("--demo star --quiet --init-mesh " + path("start.off") + " " + path("o.svg")).status, 2);
  EXPECT_FALSE(fs::exists(path("o.off")));
}

// The paper's figure 8 from the command line: a start circle across the star demo.
TEST_F(Cli, StartsFromClosedCurvesThatCrossTheData) {
  std::ofstream start(path("start.txt"));
  start << "# loop 0\n";
  for (int k = 0; k < 200; ++k) start << 0.6 + 0.9 * std::cos(2 * lsr::kPi * k / 200) << ' ' << 0.3 + 0.9 * std::sin(2 * lsr::kPi * k / 200) << '\n';
  start.close();
  const CliRun r = run("--demo star --points 3000 --init-mesh " + path("start.txt") + " " + path("s.svg") + " --quiet");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("1 closed curve(s)"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(" converged"), std::string::npos) << r.output;
  EXPECT_NE(read("s.svg").find("stroke-dasharray"), std::string::npos);  // the start, dashed
  std::ofstream(path("short.txt")) << "# loop 0\n0 0\n1 0\n";
  EXPECT_EQ(run("--demo star --init-mesh " + path("short.txt") + " " + path("o.svg") + " --quiet").status, 1);
}

// Levels of detail: OUT.l0 (coarsest) .. OUT.l<N-1>, each closed, finer each time; OUT itself
// is not written.
TEST_F(Cli, WritesLevelsOfDetail) {
  const CliRun r = run("--demo torus --points 3000 --quiet --levels 2 " + path("t.off"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_FALSE(fs::exists(path("t.off")));
  expect_closed_mesh(path("t.l0.off"), 1);
  expect_closed_mesh(path("t.l1.off"), 1);
  EXPECT_LT(fs::file_size(path("t.l0.off")), fs::file_size(path("t.l1.off")));
  EXPECT_EQ(run("--demo torus --levels 9 " + path("o.off")).status, 2);
  EXPECT_EQ(run("--demo torus --levels 2 --init-mesh " + path("t.l0.off") + " " + path("o.off")).status, 2);
}

// --help prints the defaults the library starts with, from the one options object.
TEST_F(Cli, HelpShowsTheLibraryDefaults) {
  const CliRun help = run("--help");
  ASSERT_EQ(help.status, 0);
  const lsr::ReconstructionOptions o;
  auto shown = [&](const std::string& option, double value) {
    std::ostringstream s;
    s << option << " (=" << value << ")";
    EXPECT_NE(help.output.find(s.str()), std::string::npos) << s.str() << " in\n" << help.output;
  };
  shown("--max-iterations N", o.stopping.max_iterations);
  shown("--max-size H", o.mesh.h_max);
  shown("--grading C", o.mesh.grading);
  shown("--curvature-weight B", o.evolution.curvature_weight);
  shown("--max-resolution R", o.mesh.max_resolution);
  shown("--tolerance EPS", o.stopping.tolerance);
  EXPECT_NE(help.output.find("--init START (=tagged)"), std::string::npos);
  ASSERT_EQ(o.start.initial_front, lsr::InitialFront::tagged);
  std::ostringstream outliers;
  outliers << "farther than " << o.sampling.outlier_factor << " local";
  EXPECT_NE(help.output.find(outliers.str()), std::string::npos);
}

TEST_F(Cli, SavesItsCloudAndAnswersVersionHelpAndInlineValues) {
  CliRun r = run("--demo=sphere --points=3000 --resolution=32 --quiet --save-points " + path("s.xyz") + " " + path("s.off"));
  ASSERT_EQ(r.status, 0) << r.output;
  const lsr::adapters::PointFile saved = lsr::adapters::read_point_file(path("s.xyz"));
  EXPECT_EQ(saved.points.size(), 3000u);
  // The saved cloud gives the same mesh as the demo that generated it.
  r = run(path("s.xyz") + " " + path("again.off") + " --resolution 32 --quiet");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(read("s.off"), read("again.off"));
  r = run("--version");
  EXPECT_EQ(r.status, 0);
  EXPECT_EQ(r.output.rfind("lsrecon ", 0), 0u) << r.output;
  // PCL's naming: the same program as pcl_level_set_reconstruction.
  const std::string alias = fs::path(LSRECON_CLI).parent_path() / "pcl_level_set_reconstruction";
  const int version = std::system((alias + " --version > " + path("alias.txt")).c_str());
  EXPECT_EQ(WEXITSTATUS(version), 0);
  EXPECT_EQ(read("alias.txt").rfind("lsrecon ", 0), 0u);
  const int view = std::system((std::string(LSRECON_VIEW) + " --help > " + path("view.txt")).c_str());
  EXPECT_EQ(WEXITSTATUS(view), 0);
  EXPECT_NE(read("view.txt").find(".off"), std::string::npos);
}

}  // namespace
