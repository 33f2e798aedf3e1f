// SPDX-License-Identifier: BSD-3-Clause
/// @file gmsh_volume_mesh_test.cpp
/// @brief The volume meshes as a simulation code sees them: Debian's Gmsh reads the .msh lsrecon
/// writes, computes each element's Jacobian itself, and saves the mesh back with the physical
/// groups it understood; the counts must be lsrecon's, every Jacobian positive, and none below
/// 1e-9 of the mean (issue 46's bar for a flat element).
#include "cli_fixture.h"

#include <pcl/io/ply_io.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sys/wait.h>

#include <fstream>
#include <map>
#include <utility>
#include <sstream>

namespace {

using lsr_test::Cli;
using lsr_test::CliRun;

struct GmshView {
  int status = -1;
  long nodes = -1, elements = -1;
  double min_jacobian = -1.0, mean_jacobian = -1.0;
  std::map<std::pair<int, int>, long> by_type_and_group;  // (element type, physical group) -> count
};

class GmshReads : public Cli {
 protected:
  GmshView gmsh(const std::string& msh) const {
    const std::string saved = path("gmsh-saved.msh");
    std::ofstream(path("check.geo")) << "Merge \"" << msh << "\";\n"
                                     << "Plugin(AnalyseMeshQuality).JacobianDeterminant = 1;\n"
                                     << "Plugin(AnalyseMeshQuality).DimensionOfElements = -1;\n"
                                     << "Plugin(AnalyseMeshQuality).Run;\n"
                                     << "Mesh.MshFileVersion = 2.2;\n"
                                     << "Save \"" << saved << "\";\n";
    const std::string log = path("gmsh.txt");
    const std::string command = std::string(LSRECON_GMSH) + " -nopopup " + path("check.geo") + " -0 > " + log + " 2>&1";
    const int raw = std::system(command.c_str());
    GmshView v;
    v.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    const std::string text = read("gmsh.txt");
    // The first "Info : N nodes", "Info : N elements" and "minJ = a, b," of the log. Read by
    // hand: std::regex under GCC 12's -fsanitize builds warns inside libstdc++.
    std::istringstream log_lines(text);
    bool jacobians = false;
    for (std::string line; std::getline(log_lines, line);) {
      const std::size_t info = line.find("Info"), colon = line.find(':'), min_j = line.find("minJ");
      if (info != std::string::npos && colon != std::string::npos && colon > info) {
        std::istringstream rest(line.substr(colon + 1));
        long count = -1;
        std::string what;
        if (rest >> count >> what) {
          if (what == "nodes" && v.nodes < 0) v.nodes = count;
          if (what == "elements" && v.elements < 0) v.elements = count;
        }
      }
      const std::size_t equals = min_j == std::string::npos ? std::string::npos : line.find('=', min_j);
      if (equals != std::string::npos && !jacobians) {
        std::istringstream rest(line.substr(equals + 1));
        double low = 0.0, mean = 0.0;
        char comma = 0;
        if (rest >> low >> comma >> mean && comma == ',') {
          v.min_jacobian = low;
          v.mean_jacobian = mean;
          jacobians = true;
        }
      }
    }
    // Gmsh 2.2 elements: id type tag-count physical elementary nodes...
    std::ifstream in(saved);
    std::string line;
    bool elements = false;
    while (std::getline(in, line)) {
      if (line == "$Elements" || line == "$EndElements") {
        elements = line == "$Elements";
        std::getline(in, line);  // the count
        continue;
      }
      std::istringstream fields(line);
      long id = 0;
      int type = 0, tags = 0, group = 0;
      if (elements && fields >> id >> type >> tags >> group) ++v.by_type_and_group[{type, group}];
    }
    return v;
  }

  // lsrecon on a demo writing NAME.msh and NAME.json; Gmsh's view of the mesh, and lsrecon's report.
  std::pair<GmshView, nlohmann::json> reconstruct(const std::string& demo, const std::string& output,
                                                  const std::string& name) const {
    const CliRun r = run("--demo " + demo + " --points 3000 --quiet " + path(output) + " --volume-mesh " +
                         path(name + ".msh") + " --report " + path(name + ".json"));
    EXPECT_EQ(r.status, 0) << r.output;
    std::ifstream report(path(name + ".json"));
    return {gmsh(path(name + ".msh")), nlohmann::json::parse(report)["volume_mesh"]};
  }
};

TEST_F(GmshReads, TheTetrahedraOfASphereWithTheirLabelsAndPositiveVolumes) {
  const auto [g, r] = reconstruct("sphere", "s.ply", "s");
  ASSERT_EQ(g.status, 0) << read("gmsh.txt");
  pcl::PolygonMesh surface;
  ASSERT_EQ(pcl::io::loadPLYFile(path("s.ply"), surface), 0);
  const long inside = r["inside_simplices"], outside = r["outside_simplices"];
  const long triangles = long(surface.polygons.size());
  EXPECT_EQ((g.by_type_and_group.at({4, 1})), inside);   // type 4: tetrahedron
  EXPECT_EQ((g.by_type_and_group.at({4, 2})), outside);
  EXPECT_EQ((g.by_type_and_group.at({2, 10})), triangles);  // type 2: triangle; the surface
  const long walls = g.by_type_and_group.at({2, 20});
  EXPECT_GT(walls, 0);
  EXPECT_EQ(g.elements, inside + outside + triangles + walls);
  EXPECT_EQ(g.by_type_and_group.size(), 4u);
  std::istringstream nodes(read("s.msh").substr(read("s.msh").find("$Nodes\n") + 7));
  long written = 0;
  nodes >> written;
  EXPECT_EQ(g.nodes, written);
  EXPECT_GT(g.min_jacobian, 0.0) << read("gmsh.txt");
  EXPECT_GE(g.min_jacobian, 1e-9 * g.mean_jacobian) << read("gmsh.txt");
}

TEST_F(GmshReads, TheTrianglesOfThreeShapesWithTheirLabelsAndPositiveAreas) {
  const auto [g, r] = reconstruct("three-shapes", "t.svg", "t");
  ASSERT_EQ(g.status, 0) << read("gmsh.txt");
  EXPECT_EQ((g.by_type_and_group.at({2, 1})), r["inside_simplices"].get<long>());
  EXPECT_EQ((g.by_type_and_group.at({2, 2})), r["outside_simplices"].get<long>());
  EXPECT_GT((g.by_type_and_group.at({1, 10})), 0);  // type 1: line; the three curves
  EXPECT_GT((g.by_type_and_group.at({1, 20})), 0);
  EXPECT_EQ(g.by_type_and_group.size(), 4u);
  EXPECT_GT(g.min_jacobian, 0.0) << read("gmsh.txt");
  EXPECT_GE(g.min_jacobian, 1e-9 * g.mean_jacobian) << read("gmsh.txt");
}

}  // namespace
