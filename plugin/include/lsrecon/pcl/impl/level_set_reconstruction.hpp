// SPDX-License-Identifier: BSD-3-Clause
/// @file level_set_reconstruction.hpp
/// @brief Template body of pcl::LevelSetReconstruction (included by the explicit instantiations,
/// or by the header under PCL_NO_PRECOMPILE for other point types).
#pragma once

#include "lsrecon/adapters/pcl_mesh.h"
#include "lsrecon/adapters/pcl_points.h"
#include "lsrecon/adapters/point_files.h"
#include "lsrecon/pcl/level_set_reconstruction.h"

#include <pcl/common/io.h>
#include <pcl/console/print.h>
#include <pcl/point_types.h>
#include <pcl/surface/impl/reconstruction.hpp>

#include <cmath>
#include <limits>

namespace pcl {

template <typename PointInT>
void LevelSetReconstruction<PointInT>::reconstruct(pcl::PolygonMesh& output) {
  if (!this->input_) {  // the base class would dereference the missing cloud
    PCL_ERROR("[pcl::%s::reconstruct] No input cloud [hint: call setInputCloud first]\n",
              getClassName().c_str());
    output = pcl::PolygonMesh();
    status_ = Status();
    status_.message = "no input cloud [hint: call setInputCloud first]";
    return;
  }
  SurfaceReconstruction<PointInT>::reconstruct(output);
}

template <typename PointInT>
void LevelSetReconstruction<PointInT>::reconstruct(pcl::PointCloud<PointInT>& points,
                                                   std::vector<pcl::Vertices>& polygons) {
  if (!this->input_) {
    PCL_ERROR("[pcl::%s::reconstruct] No input cloud [hint: call setInputCloud first]\n",
              getClassName().c_str());
    points.clear();
    polygons.clear();
    status_ = Status();
    status_.message = "no input cloud [hint: call setInputCloud first]";
    return;
  }
  SurfaceReconstruction<PointInT>::reconstruct(points, polygons);
}

template <typename PointInT>
bool LevelSetReconstruction<PointInT>::reconstruct(lsr::adapters::TriMesh& mesh) {
  mesh.clear();
  status_ = Status();
  if (!this->input_) {
    PCL_ERROR("[pcl::%s::reconstruct] No input cloud [hint: call setInputCloud first]\n",
              getClassName().c_str());
    return false;
  }
  if (!this->initCompute()) return false;
  pcl::PointCloud<pcl::PointNormal> vertices;
  std::vector<pcl::Vertices> polygons;
  const bool ok = run(vertices, polygons);
  this->deinitCompute();
  if (!ok) return false;
  if (status_.dimension != 3) {
    PCL_ERROR("[pcl::%s::reconstruct] the cloud is planar: closed curves are not a triangle mesh "
              "[hint: use reconstruct(pcl::PolygonMesh&) for 2D data]\n", getClassName().c_str());
    return false;
  }
  mesh.request_vertex_normals();
  std::vector<lsr::adapters::TriMesh::VertexHandle> handles;
  handles.reserve(vertices.size());
  for (const auto& p : vertices) {
    handles.push_back(mesh.add_vertex(lsr::adapters::TriMesh::Point(p.x, p.y, p.z)));
    mesh.set_normal(handles.back(), lsr::adapters::TriMesh::Normal(p.normal_x, p.normal_y, p.normal_z));
  }
  for (const auto& t : polygons) {
    mesh.add_face(handles[t.vertices[0]], handles[t.vertices[1]], handles[t.vertices[2]]);
  }
  return true;
}

template <typename PointInT>
bool LevelSetReconstruction<PointInT>::run(pcl::PointCloud<pcl::PointNormal>& vertices,
                                           std::vector<pcl::Vertices>& polygons) {
  status_ = Status();
  input_normals_.clear();
  volume2_ = {};
  volume3_ = {};
  vertices.clear();
  polygons.clear();
  try {
    lsr::adapters::ConvertedPoints in = lsr::adapters::points_from_cloud(*this->input_, this->indices_.get());
    status_.skipped_points = in.skipped_non_finite + in.skipped_bad_index;
    const std::vector<std::size_t> kept = lsr::adapters::statistical_inliers(in.points, statistical_);
    status_.statistical_outlier_points = in.points.size() - kept.size();
    lsr::adapters::keep_only(in.points, kept);
    lsr::adapters::keep_only(in.source, kept);
    if (in.points.empty()) {
      throw lsr::InvalidInput("the cloud has no finite point", "check the input cloud and its indices");
    }
    double z_min = in.points[0].z(), z_max = z_min;
    for (const auto& p : in.points) {
      z_min = std::min(z_min, p.z());
      z_max = std::max(z_max, p.z());
    }
    status_.dimension = dimension_ != 0 ? dimension_ : lsr::adapters::detect_dimension(in.points);
    if (status_.dimension != 2 && status_.dimension != 3) {
      throw lsr::InvalidInput("dimension " + std::to_string(dimension_) + " is not 0, 2 or 3",
                              "use setDimension(0) (automatic), 2 or 3");
    }
    auto record = [&](const auto& r) {
      status_.ok = true;
      status_.converged = r.status == lsr::ReconstructionStatus::converged;
      status_.cancelled = r.status == lsr::ReconstructionStatus::cancelled;
      status_.iterations = r.iterations;
      status_.residual = r.residual;
      status_.tolerance = r.tolerance;
      status_.residual_history = r.residual_history;
      status_.stage_seconds = r.seconds;
      status_.outlier_points = r.outlier_points;
      status_.sealed_cavities = r.sealed_cavities;
      status_.open_side_points = r.open_side_points;
      status_.mesh_vertices = std::size_t(r.mesh_vertices);
      if (r.status == lsr::ReconstructionStatus::not_converged) {
        // As PCL's own tools say it: the mesh is the best iterate, usable, but the user should know.
        PCL_WARN("[pcl::%s::reconstruct] not converged after %d steps (residual %g > tolerance %g); the best "
                 "iterate is returned [hint: raise setMaxIterations, or setCurvatureWeight for noisy data]\n",
                 getClassName().c_str(), r.iterations, r.residual, r.tolerance);
      }
    };
    if (status_.dimension == 2) {
      lsr::Points<2> planar;
      planar.reserve(in.points.size());
      for (const auto& p : in.points) planar.emplace_back(p.x(), p.y());
      auto r = lsr::reconstruct<2>(planar, options_, progress_);
      volume2_ = std::move(r.volume);
      vertices = lsr::adapters::normal_cloud<2>(r.surface.vertices, r.normals, 0.5 * (z_min + z_max));
      polygons = lsr::adapters::polygons_from_loops(r.loops);
      record(r);
    } else {
      auto r = lsr::reconstruct<3>(in.points, options_, progress_);
      volume3_ = std::move(r.volume);
      vertices = lsr::adapters::normal_cloud<3>(r.surface.vertices, r.normals);
      const float nan = std::numeric_limits<float>::quiet_NaN();
      input_normals_.assign(this->input_->size(), pcl::Normal(nan, nan, nan));
      for (std::size_t i = 0; i < in.source.size() && i < r.point_normals.size(); ++i) {
        const auto& n = r.point_normals[i];
        input_normals_[std::size_t(in.source[i])] = pcl::Normal(float(n.x()), float(n.y()), float(n.z()));
      }
      polygons = lsr::adapters::polygons_from_triangles(r.surface.facets);
      record(r);
    }
    return true;
  } catch (const std::exception& e) {
    PCL_ERROR("[pcl::%s::performReconstruction] %s\n", getClassName().c_str(), e.what());
    status_.ok = false;
    status_.message = e.what();
    vertices.clear();
    polygons.clear();
    return false;
  }
}

template <typename PointInT>
void LevelSetReconstruction<PointInT>::performReconstruction(pcl::PolygonMesh& output) {
  pcl::PointCloud<pcl::PointNormal> vertices;
  run(vertices, output.polygons);
  pcl::toPCLPointCloud2(vertices, output.cloud);
}

template <typename PointInT>
void LevelSetReconstruction<PointInT>::performReconstruction(pcl::PointCloud<PointInT>& points,
                                                             std::vector<pcl::Vertices>& polygons) {
  pcl::PointCloud<pcl::PointNormal> vertices;
  run(vertices, polygons);
  points.clear();
  points.resize(vertices.size());
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    points[i].x = vertices[i].x;
    points[i].y = vertices[i].y;
    points[i].z = vertices[i].z;
    if constexpr (pcl::traits::has_normal_v<PointInT>) {
      points[i].normal_x = vertices[i].normal_x;
      points[i].normal_y = vertices[i].normal_y;
      points[i].normal_z = vertices[i].normal_z;
    }
  }
  points.width = std::uint32_t(points.size());
  points.height = 1;
  points.is_dense = true;
}

}  // namespace pcl

#define PCL_INSTANTIATE_LevelSetReconstruction(T) template class pcl::LevelSetReconstruction<T>;
