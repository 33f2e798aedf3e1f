// SPDX-License-Identifier: BSD-3-Clause
/// @file cli_fixture.h
/// @brief Runs the lsrecon command line in a scratch directory, as a user would.
#pragma once

#include "checks/exact_self_intersections.h"
#include "lsrecon/adapters/openmesh_mesh.h"
#include "lsrecon/testdata/analytic_shapes.h"
#include "surface/surface_topology.h"

#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace lsr_test {

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
  void TearDown() override {
    std::error_code e;
    fs::permissions(dir_, fs::perms::owner_all, fs::perm_options::add, e);
    fs::remove_all(dir_, e);
  }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  CliRun run(const std::string& args) const { return run_program(LSRECON_CLI, args); }

  CliRun run_program(const std::string& program, const std::string& args) const {
    const std::string log = path("log.txt");
    const std::string command = program + " " + args + " > " + log + " 2>&1";
    CliRun r;
    const int raw = std::system(command.c_str());
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    std::ifstream in(log);
    std::stringstream s;
    s << in.rdbuf();
    r.output = s.str();
    return r;
  }

  std::string read(const std::string& name) const {
    std::ifstream in(path(name), std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }

  static lsr::Points<3> sphere() { return lsr::Sphere{lsr::Vec<3>(1, 2, 3), 2.0}.sample(3000); }

  fs::path dir_;
};

inline void expect_closed_mesh(const std::string& file, int genus = 0) {
  lsr::adapters::TriMesh mesh;
  ASSERT_TRUE(OpenMesh::IO::read_mesh(mesh, file)) << file;
  const lsr::LevelSetMesh<3> m = lsr::adapters::from_openmesh(mesh);
  const lsr::SurfaceTopology t = lsr::analyze_surface(m.vertices, m.facets);
  EXPECT_TRUE(t.watertight) << file;
  EXPECT_EQ(t.components, 1) << file;
  EXPECT_EQ(t.genus, std::vector<int>{genus}) << file;
  EXPECT_EQ(lsr::testing::cgal_self_intersections(m.vertices, m.facets), 0u) << file;  // embedded, as written
}

}  // namespace lsr_test
