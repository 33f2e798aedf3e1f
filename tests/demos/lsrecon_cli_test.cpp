// SPDX-License-Identifier: BSD-3-Clause
/// @file lsrecon_cli_test.cpp
/// @brief The lsrecon command line as a user runs it: every input and output format, the JSON
/// report, and every documented error path (exit code and message).
#include "lsrecon/adapters/openmesh_mesh.h"
#include "lsrecon/adapters/point_files.h"
#include "lsrecon/core/analytic_shapes.h"
#include "lsrecon/core/surface_topology.h"

#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace {

namespace fs = std::filesystem;

struct CliRun {
  int status = -1;
  std::string output;  // stdout and stderr
};

class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("lsrecon_cli_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  CliRun run(const std::string& args) const {
    const std::string log = path("log.txt");
    const std::string command = std::string(LSRECON_CLI) + " " + args + " > " + log + " 2>&1";
    CliRun r;
    const int raw = std::system(command.c_str());
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    std::ifstream in(log);
    std::stringstream s;
    s << in.rdbuf();
    r.output = s.str();
    return r;
  }

  static lsr::Points<3> sphere() { return lsr::Sphere{lsr::Vec<3>(1, 2, 3), 2.0}.sample(3000); }

  fs::path dir_;
};

void expect_closed_mesh(const std::string& file, int genus = 0) {
  lsr::adapters::TriMesh mesh;
  ASSERT_TRUE(OpenMesh::IO::read_mesh(mesh, file)) << file;
  const lsr::LevelSetMesh<3> m = lsr::adapters::from_openmesh(mesh);
  const lsr::SurfaceTopology t = lsr::analyze_surface(m.vertices, m.facets);
  EXPECT_TRUE(t.watertight) << file;
  EXPECT_EQ(t.components, 1) << file;
  EXPECT_EQ(t.genus, std::vector<int>{genus}) << file;
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
  std::ifstream in(path("r.json"));
  std::stringstream s;
  s << in.rdbuf();
  const std::string json = s.str();
  for (const char* field : {"input_points", "dimension", "h_min", "mesh_vertices", "mesh_simplices", "time_steps",
                            "converged", "residual", "seconds", "total_seconds", "peak_memory_mib",
                            "output_vertices", "output_faces", "components", "watertight"}) {
    EXPECT_NE(json.find(std::string("\"") + field + "\""), std::string::npos) << field;
  }
  EXPECT_NE(json.find("\"watertight\": true"), std::string::npos);
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
}

TEST_F(Cli, BadInputExitsWithOneAndNeverClobbersTheOutput) {
  std::ofstream(path("keep.ply")) << "precious";
  std::ofstream(path("empty.xyz")) << "# nothing\n";
  std::ofstream(path("junk.pcd")) << "this is not a point cloud\n";
  std::ofstream(path("junk.ply")) << "ply\nformat nonsense\n";
  std::ofstream(path("words.xyz")) << "1 2 3\n4 five 6\n";
  std::ofstream line(path("line.xyz"));
  for (int i = 0; i < 100; ++i) line << i << ' ' << 2 * i << ' ' << 3 * i << '\n';
  line.close();
  std::ofstream flat(path("flat.xyz"));
  for (const auto& p : lsr::Circle{lsr::Vec<2>(0, 0), 1.0}.sample(500)) flat << p.x() << ' ' << p.y() << " 0\n";
  flat.close();
  const std::vector<std::pair<std::string, std::string>> cases = {
      {path("missing.xyz"), "cannot open"},      {path("empty.xyz"), "empty"},
      {path("junk.pcd"), "cannot read"},         {path("junk.ply"), "cannot read"},
      {path("words.xyz"), "words.xyz:2"},
      {path("line.xyz"), "colinear"},            {path("flat.xyz"), "planar"},
      {path("in.unknown"), "unknown input format"},
  };
  for (const auto& [input, message] : cases) {
    const CliRun r = run(input + " " + path("keep.ply") + " --quiet");
    EXPECT_EQ(r.status, 1) << input << ": " << r.output;
    EXPECT_NE(r.output.find(message), std::string::npos) << input << ": " << r.output;
    EXPECT_NE(r.output.find("hint"), std::string::npos) << input << ": " << r.output;
    std::ifstream kept(path("keep.ply"));
    std::string content;
    kept >> content;
    EXPECT_EQ(content, "precious") << input;
  }
  // A mesh that would not fit is refused, naming a feasible resolution.
  const CliRun big = run("--demo sphere --resolution 50000 --quiet " + path("keep.ply"));
  EXPECT_EQ(big.status, 1) << big.output;
  EXPECT_NE(big.output.find("resolution of at most"), std::string::npos) << big.output;
  for (const auto& entry : fs::directory_iterator(dir_)) {
    EXPECT_EQ(entry.path().string().find(".partial"), std::string::npos) << entry.path();
  }
}

}  // namespace
