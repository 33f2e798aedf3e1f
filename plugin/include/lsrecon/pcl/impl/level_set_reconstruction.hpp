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
#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/point_types.h>
#include <pcl/surface/impl/reconstruction.hpp>

#include <cmath>
#include <limits>

namespace pcl {

namespace lsrecon_detail {
/// Point types with fields beyond position and normal, carried to the vertices.
template <typename PointT>
constexpr bool kCarriesFields =
    pcl::traits::has_color_v<PointT> || pcl::traits::has_intensity_v<PointT> || pcl::traits::has_label_v<PointT>;
}  // namespace lsrecon_detail

template <typename PointInT>
bool LevelSetReconstruction<PointInT>::hasInput() {
  if (this->input_) return true;
  PCL_ERROR("[pcl::%s::reconstruct] No input cloud [hint: call setInputCloud first]\n", getClassName().c_str());
  status_ = Status();
  status_.message = "no input cloud [hint: call setInputCloud first]";
  return false;
}

template <typename PointInT>
void LevelSetReconstruction<PointInT>::reconstruct(pcl::PolygonMesh& output) {
  if (hasInput()) {
    SurfaceReconstruction<PointInT>::reconstruct(output);  // would dereference the missing cloud
  } else {
    output = pcl::PolygonMesh();
  }
}

template <typename PointInT>
void LevelSetReconstruction<PointInT>::reconstruct(pcl::PointCloud<PointInT>& points, std::vector<pcl::Vertices>& polygons) {
  if (hasInput()) {
    SurfaceReconstruction<PointInT>::reconstruct(points, polygons);
  } else {
    points.clear();
    polygons.clear();
  }
}

template <typename PointInT>
bool LevelSetReconstruction<PointInT>::run(Output& out) {
  status_ = Status();
  input_normals_.clear();
  volume2_ = {};
  volume3_ = {};
  out = Output();
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
      status_.spacing = r.spacing;
      status_.residual_history = r.residual_history;
      status_.stage_seconds = r.seconds;
      status_.outlier_points = r.outlier_points;
      status_.mesh_vertices = std::size_t(r.mesh_vertices);
      out.distance.assign(r.distance_to_data.begin(), r.distance_to_data.end());
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
      out.vertices = lsr::adapters::normal_cloud<2>(r.surface.vertices, r.normals, 0.5 * (z_min + z_max));
      out.polygons = lsr::adapters::polygons_from_loops(r.loops);
      record(r);
    } else {
      auto r = lsr::reconstruct<3>(in.points, options_, progress_);
      volume3_ = std::move(r.volume);
      out.vertices = lsr::adapters::normal_cloud<3>(r.surface.vertices, r.normals);
      const float nan = std::numeric_limits<float>::quiet_NaN();
      input_normals_.assign(this->input_->size(), pcl::Normal(nan, nan, nan));
      for (std::size_t i = 0; i < in.source.size() && i < r.point_normals.size(); ++i) {
        const auto& n = r.point_normals[i];
        input_normals_[std::size_t(in.source[i])] = pcl::Normal(float(n.x()), float(n.y()), float(n.z()));
      }
      out.polygons = lsr::adapters::polygons_from_triangles(r.surface.facets);
      record(r);
    }
    if constexpr (lsrecon_detail::kCarriesFields<PointInT>) {
      pcl::PointCloud<pcl::PointXYZ>::Ptr used(new pcl::PointCloud<pcl::PointXYZ>);
      for (const auto& p : in.points) used->push_back(pcl::PointXYZ(float(p.x()), float(p.y()), float(p.z())));
      pcl::KdTreeFLANN<pcl::PointXYZ> tree;
      tree.setInputCloud(used);
      pcl::Indices k(1);
      std::vector<float> d(1);
      out.nearest.resize(out.vertices.size());
      for (std::size_t i = 0; i < out.vertices.size(); ++i) {
        const auto& v = out.vertices[i];
        tree.nearestKSearch(pcl::PointXYZ(v.x, v.y, v.z), 1, k, d);
        out.nearest[i] = in.source[std::size_t(k[0])];
      }
    }
    return true;
  } catch (const std::exception& e) {
    PCL_ERROR("[pcl::%s::performReconstruction] %s\n", getClassName().c_str(), e.what());
    status_.ok = false;
    status_.message = e.what();
    out = Output();
    return false;
  }
}

template <typename PointInT>
void LevelSetReconstruction<PointInT>::performReconstruction(pcl::PolygonMesh& output) {
  Output out;
  run(out);
  output.polygons = std::move(out.polygons);
  pcl::toPCLPointCloud2(out.vertices, output.cloud);
  lsr::adapters::append_fields(lsr::adapters::scalar_field(lsr::adapters::kDistanceProperty, out.distance), output.cloud);
  if constexpr (lsrecon_detail::kCarriesFields<PointInT>) {
    pcl::PointCloud<PointInT> nearest;
    pcl::copyPointCloud(*this->input_, out.nearest, nearest);
    pcl::PCLPointCloud2 fields;
    pcl::toPCLPointCloud2(nearest, fields);
    lsr::adapters::append_fields(fields, output.cloud);
  }
}

template <typename PointInT>
void LevelSetReconstruction<PointInT>::performReconstruction(pcl::PointCloud<PointInT>& points,
                                                             std::vector<pcl::Vertices>& polygons) {
  Output out;
  run(out);
  polygons = std::move(out.polygons);
  points.clear();
  points.resize(out.vertices.size());
  for (std::size_t i = 0; i < out.vertices.size(); ++i) {
    if constexpr (lsrecon_detail::kCarriesFields<PointInT>) points[i] = (*this->input_)[std::size_t(out.nearest[i])];
    points[i].x = out.vertices[i].x;
    points[i].y = out.vertices[i].y;
    points[i].z = out.vertices[i].z;
    if constexpr (pcl::traits::has_normal_v<PointInT>) {
      points[i].normal_x = out.vertices[i].normal_x;
      points[i].normal_y = out.vertices[i].normal_y;
      points[i].normal_z = out.vertices[i].normal_z;
    }
  }
  points.width = std::uint32_t(points.size());
  points.height = 1;
  points.is_dense = true;
}

}  // namespace pcl

#define PCL_INSTANTIATE_LevelSetReconstruction(T) template class pcl::LevelSetReconstruction<T>;
