// SPDX-License-Identifier: BSD-3-Clause
/// @file lsrecon_view.cpp
/// @brief Viewer: a point cloud and its reconstruction side by side in the PCL visualiser.
///   lsrecon-view CLOUD [RESULT] [--overlay] [--screenshot FILE.png]
/// CLOUD: any input lsrecon reads. RESULT: a mesh (.ply .obj .off .stl .vtk) or, in 2D, the closed
/// curves lsrecon wrote as .txt. --overlay draws the cloud over the result in one view;
/// --screenshot renders once and saves a PNG instead of opening a window (use xvfb-run when no
/// display is available).
#include "command_line.h"
#include "lsrecon/adapters/openmesh_mesh.h"  // first: OpenMesh wants its IO header first
#include "lsrecon/adapters/pcl_mesh.h"
#include "lsrecon/adapters/point_files.h"

#include <pcl/point_types.h>
#include <pcl/visualization/pcl_visualizer.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

namespace {

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// Loops of the .txt format lsrecon writes: "# loop k" then "x y" per vertex.
std::vector<pcl::PointCloud<pcl::PointXYZ>::Ptr> read_loops(const std::string& path) {
  std::vector<pcl::PointCloud<pcl::PointXYZ>::Ptr> loops;
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("# loop", 0) == 0) {
      loops.emplace_back(new pcl::PointCloud<pcl::PointXYZ>);
    } else if (!line.empty() && line[0] != '#' && !loops.empty()) {
      float x = 0, y = 0;
      std::istringstream(line) >> x >> y;
      loops.back()->push_back(pcl::PointXYZ(x, y, 0));
    }
  }
  return loops;
}

// Every mesh format lsrecon writes.
pcl::PolygonMesh read_result_mesh(const std::string& path) {
  pcl::PolygonMesh mesh;
  const lsr::LevelSetMesh<3> m = lsr::adapters::from_openmesh(lsr::adapters::read_mesh_file(path));
  pcl::PointCloud<pcl::PointXYZ> vertices;
  for (const auto& v : m.vertices) vertices.push_back(pcl::PointXYZ(float(v.x()), float(v.y()), float(v.z())));
  pcl::toPCLPointCloud2(vertices, mesh.cloud);
  mesh.polygons = lsr::adapters::polygons_from_triangles(m.facets);
  return mesh;
}

}  // namespace

int main(int argc, char** argv) {
  std::string screenshot;
  bool overlay = false;
  lsr::demos::CommandLine line("lsrecon-view", LSRECON_VERSION,
                               "usage: lsrecon-view CLOUD [RESULT] [options]\n\n"
                               "  CLOUD   any point file lsrecon reads (.pcd .ply .xyz .txt .obj .off .stl .conf)\n"
                               "  RESULT  a mesh lsrecon wrote (.ply .obj .off .stl .vtk) or its 2D curves (.txt)\n");
  line.group("view")
      .flag("overlay", overlay, "the cloud over the result in one view (default: side by side)")
      .text("screenshot", "FILE.png", screenshot,
            "render once to a PNG instead of opening a window (xvfb-run -a without a display)");
  const std::vector<std::string> files = line.parse(argc, argv, 1, 2, "CLOUD [RESULT]");
  const std::string cloud_path = files[0];
  const std::string result_path = files.size() > 1 ? files[1] : "";
  try {
    pcl::PointCloud<pcl::PointXYZ>::Ptr cloud(new pcl::PointCloud<pcl::PointXYZ>);
    for (const auto& p : lsr::adapters::read_point_file(cloud_path).points) {
      cloud->push_back(pcl::PointXYZ(float(p.x()), float(p.y()), float(p.z())));
    }
    pcl::visualization::PCLVisualizer viewer("lsrecon-view");
    viewer.setSize(1400, 700);
    int left = 0, right = 0;
    if (result_path.empty() || overlay) {
      viewer.createViewPort(0.0, 0.0, 1.0, 1.0, left);
      right = left;
    } else {
      viewer.createViewPort(0.0, 0.0, 0.5, 1.0, left);
      viewer.createViewPort(0.5, 0.0, 1.0, 1.0, right);
    }
    for (int v : {left, right}) viewer.setBackgroundColor(1, 1, 1, v);
    pcl::visualization::PointCloudColorHandlerCustom<pcl::PointXYZ> grey(cloud, 90, 90, 90);
    viewer.addPointCloud<pcl::PointXYZ>(cloud, grey, "cloud", left);
    viewer.addText(cloud_path + " (" + std::to_string(cloud->size()) + " points)", 10, 10, 14, 0, 0, 0, "cloud label", left);
    if (!result_path.empty()) {
      if (ends_with(result_path, ".txt")) {
        int k = 0;
        for (const auto& loop : read_loops(result_path)) {
          viewer.addPolygon<pcl::PointXYZ>(loop, 0.1, 0.2, 0.7, "loop" + std::to_string(k++), right);
        }
      } else {
        viewer.addPolygonMesh(read_result_mesh(result_path), "result", right);
        viewer.setPointCloudRenderingProperties(pcl::visualization::PCL_VISUALIZER_COLOR, 0.85, 0.75, 0.55, "result", right);
      }
      if (right != left) viewer.addText(result_path, 10, 10, 14, 0, 0, 0, "result label", right);
    }
    viewer.resetCamera();
    if (!screenshot.empty()) {
      viewer.spinOnce(100);
      viewer.saveScreenshot(screenshot);
      std::printf("wrote %s\n", screenshot.c_str());
      return 0;
    }
    viewer.spin();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lsrecon-view: %s\n", e.what());
    return 1;
  }
  return 0;
}
