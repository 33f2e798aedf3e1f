// SPDX-License-Identifier: BSD-3-Clause
/// @file compare_methods.cpp
#include "compare_methods.h"

#include "stopwatch.h"

#include "lsrecon/adapters/pcl_mesh.h"
#include "lsrecon/core/errors.h"
#include "lsrecon/pcl/level_set_reconstruction.h"

#include <pcl/common/io.h>
#include <pcl/features/normal_3d_omp.h>
#include <pcl/surface/gp3.h>
#include <pcl/surface/marching_cubes_hoppe.h>
#include <pcl/surface/marching_cubes_rbf.h>
#include <pcl/surface/poisson.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

namespace lsr::demos {

const std::vector<std::string> kMethods = {"lsrecon",  "lsrecon-anisotropic", "lsrecon-tiles", "lsrecon-occupancy", "poisson8",
                                          "poisson8-mt", "poisson9", "poisson8-lsrecon", "poisson8-true", "mc-hoppe", "mc-rbf", "gp3"};

namespace {

using Cloud = pcl::PointCloud<pcl::PointNormal>;

std::string join_methods() {
  std::string out;
  for (const auto& m : kMethods) out += (out.empty() ? "" : ", ") + m;
  return out;
}

const int kRbfPoints = 1000;  // MarchingCubesRBF solves a dense 2N x 2N system


// Normals by PCA of 16 neighbours, oriented away from the centroid: the usual recipe for a
// closed object, and wrong wherever the surface faces its centroid (a torus's inner side).
Cloud with_estimated_normals(const pcl::PointCloud<pcl::PointXYZ>::Ptr& xyz) {
  pcl::NormalEstimationOMP<pcl::PointXYZ, pcl::Normal> ne;
  pcl::PointCloud<pcl::Normal> normals;
  ne.setInputCloud(xyz);
  ne.setKSearch(16);
  ne.compute(normals);
  Eigen::Vector4f centroid;
  pcl::compute3DCentroid(*xyz, centroid);
  Cloud cloud;
  for (std::size_t i = 0; i < xyz->size(); ++i) {
    pcl::PointNormal p;
    p.x = (*xyz)[i].x;
    p.y = (*xyz)[i].y;
    p.z = (*xyz)[i].z;
    Eigen::Vector3f n(normals[i].normal_x, normals[i].normal_y, normals[i].normal_z);
    if (!n.allFinite()) continue;
    if (n.dot(p.getVector3fMap() - centroid.head<3>()) < 0) n = -n;
    p.normal_x = n.x();
    p.normal_y = n.y();
    p.normal_z = n.z();
    cloud.push_back(p);
  }
  return cloud;
}

Cloud with_true_normals(const CompareCase& c) {
  Cloud cloud;
  for (std::size_t i = 0; i < c.points.size(); ++i) {
    pcl::PointNormal p;
    p.x = float(c.points[i].x());
    p.y = float(c.points[i].y());
    p.z = float(c.points[i].z());
    p.normal_x = float(c.normals[i].x());
    p.normal_y = float(c.normals[i].y());
    p.normal_z = float(c.normals[i].z());
    cloud.push_back(p);
  }
  return cloud;
}


// " stage 1.23 s" per stage taking 5% of the time or more, slowest first (no commas: CSV).
std::string stage_breakdown(const std::map<std::string, double>& seconds) {
  std::vector<std::pair<double, std::string>> stages;
  double total = 0.0;
  for (const auto& [stage, t] : seconds) {
    stages.emplace_back(t, stage);
    total += t;
  }
  std::sort(stages.rbegin(), stages.rend());
  std::string out;
  char text[64];
  for (const auto& [t, stage] : stages) {
    if (t < 0.05 * total) break;
    std::snprintf(text, sizeof text, " %s %.2f s", stage.c_str(), t);
    out += text;
  }
  return out;
}


}  // namespace

Produced run_method(const std::string& method, const CompareCase& c, const LsreconOptions& s) {
  Produced out;
  pcl::PointCloud<pcl::PointXYZ>::Ptr xyz(new pcl::PointCloud<pcl::PointXYZ>);
  for (const auto& p : c.points) xyz->push_back(pcl::PointXYZ(float(p.x()), float(p.y()), float(p.z())));
  if (method.rfind("lsrecon", 0) == 0 || method == "poisson8-lsrecon") {
    pcl::LevelSetReconstruction<pcl::PointXYZ> ls;
    ls.setInputCloud(xyz);
    lsr::ReconstructionOptions options;
    options.sampling.hole_radius = s.hole_radius;
    options.mesh.max_resolution = s.max_resolution;
    options.limits.solve_tiles = method == "lsrecon-tiles" ? std::max(2, s.solve_tiles) : s.solve_tiles;
    options.mesh.anisotropic = method == "lsrecon-anisotropic";
    if (method == "lsrecon-occupancy") options.start.initial_front = lsr::InitialFront::occupancy;
    ls.setOptions(options);
    ls.reconstruct(out.mesh);
    out.note = std::string(ls.getStatus().converged ? "converged" : "not converged") + " in " +
               std::to_string(ls.getStatus().iterations) + " steps; " + std::to_string(ls.getStatus().mesh_vertices) + " mesh vertices;" + stage_breakdown(ls.getStatus().stage_seconds);
    out.residuals = ls.getStatus().residual_history;
    for (double& r : out.residuals) r /= ls.getStatus().tolerance;
    if (method != "poisson8-lsrecon") {
      out.indexed = true;
      return out;
    }
    // Poisson given lsrecon's oriented normals of the input points.
    Cloud::Ptr cloud(new Cloud);
    pcl::concatenateFields(*xyz, ls.getInputNormals(), *cloud);
    pcl::Poisson<pcl::PointNormal> poisson;
    poisson.setDepth(8);
    poisson.setInputCloud(cloud);
    out.mesh = pcl::PolygonMesh();
    poisson.reconstruct(out.mesh);
    out.note = "lsrecon's normals (" + out.note + ")";
    out.residuals.clear();
    return out;
  }
  Cloud::Ptr cloud(new Cloud(method == "poisson8-true" ? with_true_normals(c) : with_estimated_normals(xyz)));
  if (method.rfind("poisson", 0) == 0) {
    pcl::Poisson<pcl::PointNormal> poisson;
    poisson.setDepth(method == "poisson9" ? 9 : 8);
    // pcl::Poisson solves on one thread unless told otherwise; poisson8-mt uses every core.
    if (method == "poisson8-mt") poisson.setThreads(0);
    poisson.setInputCloud(cloud);
    poisson.reconstruct(out.mesh);
    out.note = method == "poisson8-true" ? "true normals"
               : method == "poisson8-mt" ? "estimated normals; every core"
                                         : "estimated normals";
  } else if (method == "mc-hoppe") {
    pcl::MarchingCubesHoppe<pcl::PointNormal> mc;
    mc.setInputCloud(cloud);
    mc.setGridResolution(100, 100, 100);
    mc.setIsoLevel(0.0f);
    mc.setPercentageExtendGrid(0.05f);
    mc.reconstruct(out.mesh);
    out.note = "grid 100^3";
  } else if (method == "mc-rbf") {
    Cloud::Ptr few(new Cloud);
    const std::size_t stride = std::max<std::size_t>(1, cloud->size() / kRbfPoints);
    for (std::size_t i = 0; i < cloud->size(); i += stride) few->push_back((*cloud)[i]);
    pcl::MarchingCubesRBF<pcl::PointNormal> mc;
    mc.setInputCloud(few);
    mc.setGridResolution(60, 60, 60);
    mc.setIsoLevel(0.0f);
    mc.setPercentageExtendGrid(0.05f);
    mc.setOffSurfaceDisplacement(float(0.01 * c.diagonal));
    mc.reconstruct(out.mesh);
    out.note = "subsampled to " + std::to_string(few->size()) + " points; grid 60^3";
  } else if (method == "gp3") {
    pcl::search::KdTree<pcl::PointNormal>::Ptr tree(new pcl::search::KdTree<pcl::PointNormal>);
    pcl::GreedyProjectionTriangulation<pcl::PointNormal> gp3;
    gp3.setSearchRadius(0.05 * c.diagonal);
    gp3.setMu(2.5);
    gp3.setMaximumNearestNeighbors(100);
    gp3.setMaximumSurfaceAngle(lsr::kPi / 4);
    gp3.setMinimumAngle(lsr::kPi / 18);
    gp3.setMaximumAngle(2 * lsr::kPi / 3);
    gp3.setNormalConsistency(false);
    gp3.setInputCloud(cloud);
    gp3.setSearchMethod(tree);
    gp3.reconstruct(out.mesh);
    out.note = "radius 5% of diagonal";
  } else {
    throw lsr::InvalidInput("unknown method '" + method + "'",
                            "use " + join_methods());
  }
  return out;
}

}  // namespace lsr::demos
