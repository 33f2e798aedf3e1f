// SPDX-License-Identifier: BSD-3-Clause
/// @file openmesh_mesh_test.cpp
#include "lsrecon/adapters/mesh_file_vertices.h"
#include "lsrecon/adapters/openmesh_mesh.h"
#include "lsrecon/core/errors.h"
#include "lsrecon/core/level_set_reconstruction.h"
#include "lsrecon/testdata/analytic_shapes.h"
#include "surface/surface_topology.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

namespace lsr::adapters {
namespace {

namespace fs = std::filesystem;

const ReconstructionResult<3>& sphere() {
  static const ReconstructionResult<3> r = [] {
    ReconstructionOptions o;
    o.mesh.h_min = 1.0 / 32;
    return reconstruct<3>(Sphere{Vec<3>(0, 0, 0), 1.0}.sample(4000), o);
  }();
  return r;
}

struct TempDir {
  TempDir() : path(fs::temp_directory_path() / ("lsrecon_om_" + std::to_string(::getpid()))) { fs::create_directories(path); }
  ~TempDir() { fs::remove_all(path); }
  fs::path path;
};

TEST(OpenMeshAdapter, RoundTripKeepsTopologyAndNormals) {
  const TriMesh mesh = to_openmesh(sphere().surface, sphere().normals);
  EXPECT_EQ(mesh.n_vertices(), sphere().surface.vertices.size());
  EXPECT_EQ(mesh.n_faces(), sphere().surface.facets.size());
  const LevelSetMesh<3> back = from_openmesh(mesh);
  const SurfaceTopology t = analyze_surface(back.vertices, back.facets);
  EXPECT_TRUE(t.watertight && t.oriented);
  EXPECT_GT(t.signed_volume, 0.0);
  const auto n = mesh.normal(*mesh.vertices_begin());
  EXPECT_NEAR(n.norm(), 1.0, 1e-5);
}

TEST(OpenMeshAdapter, WritesEveryFormatAndReadsItBack) {
  TempDir dir;
  const TriMesh mesh = to_openmesh(sphere().surface, sphere().normals);
  for (const char* ext : {"ply", "obj", "off", "stl"}) {
    const std::string file = (dir.path / (std::string("sphere.") + ext)).string();
    write_mesh_file(mesh, file);
    if (std::string(ext) == "ply") continue;  // read as a point cloud (PCL), not here
    const Points<3> vertices = read_mesh_file_vertices(file);
    // STL stores triangle corners; the reader welds them back to the shared vertices.
    EXPECT_EQ(vertices.size(), mesh.n_vertices()) << ext;
  }
  EXPECT_THROW(write_mesh_file(mesh, (dir.path / "sphere.xyz").string()), Error);
  EXPECT_THROW(write_mesh_file(mesh, (dir.path / "missing" / "a.ply").string()), Error);
  EXPECT_THROW(read_mesh_file_vertices((dir.path / "none.obj").string()), Error);
  for (const auto& entry : fs::directory_iterator(dir.path)) {
    EXPECT_EQ(entry.path().string().find(".partial"), std::string::npos) << entry.path();
  }
}

TEST(OpenMeshAdapter, DecimationReachesTheTargetAndStaysClosed) {
  TriMesh mesh = to_openmesh(sphere().surface, sphere().normals);
  const std::size_t target = mesh.n_faces() / 4;
  EXPECT_LE(decimate(mesh, target), target);
  const LevelSetMesh<3> back = from_openmesh(mesh);
  const SurfaceTopology t = analyze_surface(back.vertices, back.facets);
  EXPECT_TRUE(t.watertight && t.oriented);
  EXPECT_EQ(t.genus, std::vector<int>{0});
}

TEST(OpenMeshAdapter, SmoothingKeepsTheSurfaceClosedAndOnTheSphere) {
  TriMesh mesh = to_openmesh(sphere().surface, sphere().normals);
  smooth(mesh, 5);
  const LevelSetMesh<3> back = from_openmesh(mesh);
  const SurfaceTopology t = analyze_surface(back.vertices, back.facets);
  EXPECT_TRUE(t.watertight && t.oriented);
  // Laplace smoothing shrinks a sphere by O(iterations * edge^2 / r): stay within 2 h_min.
  for (const auto& v : back.vertices) EXPECT_NEAR(v.norm(), 1.0, 2 * sphere().tolerance);
}

}  // namespace
// The first n vertex positions of a binary PLY whose vertices are double x y z nx ny nz.
Points<3> double_ply_vertices(const std::string& file, std::size_t n) {
  std::ifstream in(file, std::ios::binary);
  std::string line;
  while (std::getline(in, line) && line != "end_header") {
  }
  Points<3> points(n);
  for (auto& p : points) {
    double v[6];
    in.read(reinterpret_cast<char*>(v), sizeof(v));
    p = Vec<3>(v[0], v[1], v[2]);
  }
  return points;
}

TEST(OpenMeshAdapter, AGeoreferencedOffsetSurvivesTheFileRoundTrip) {
  // A unit sphere at 1e6 (a scan in metres, georeferenced): floats would step by 0.06 there.
  TempDir dir;
  LevelSetMesh<3> surface = sphere().surface;
  for (auto& v : surface.vertices) v += Vec<3>(1e6, -2e6, 3e5);
  const TriMesh mesh = to_openmesh(surface, sphere().normals);
  for (const char* ext : {"ply", "obj", "off"}) {
    const std::string file = (dir.path / (std::string("far.") + ext)).string();
    write_mesh_file(mesh, file);
    const Points<3> back = std::string(ext) == "ply" ? double_ply_vertices(file, surface.vertices.size())
                                                     : read_mesh_file_vertices(file);
    ASSERT_EQ(back.size(), surface.vertices.size()) << ext;
    double worst = 0.0;
    for (std::size_t i = 0; i < back.size(); ++i) worst = std::max(worst, (back[i] - surface.vertices[i]).norm());
    EXPECT_LT(worst, 1e-6) << ext;  // 1e-12 of the coordinates
    // And OpenMesh still reads the file as a closed mesh.
    TriMesh read;
    ASSERT_TRUE(OpenMesh::IO::read_mesh(read, file)) << ext;
    EXPECT_EQ(read.n_faces(), mesh.n_faces()) << ext;
  }
}

}  // namespace lsr::adapters
