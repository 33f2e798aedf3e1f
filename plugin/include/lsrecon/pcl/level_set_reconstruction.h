// SPDX-License-Identifier: BSD-3-Clause
/// @file level_set_reconstruction.h
/// @brief pcl::LevelSetReconstruction: closed surfaces (3D) or closed curves (2D) from
/// unoriented points, used like pcl::Poisson.
///
/// @code
///   pcl::LevelSetReconstruction<pcl::PointXYZRGB> ls;
///   ls.setInputCloud(cloud);
///   pcl::PolygonMesh mesh;
///   ls.reconstruct(mesh);   // watertight, oriented; per vertex: normal, distance, colour
/// @endcode
#pragma once

#include "lsrecon/adapters/statistical_outliers.h"
#include "lsrecon/core/level_set_reconstruction.h"

#include <pcl/PolygonMesh.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/surface/reconstruction.h>

#include <map>
#include <string>
#include <vector>

namespace pcl {

/// @brief Level-set reconstruction (Claisse & Frey 2011) as a pcl::SurfaceReconstruction.
///
/// Needs no normals: a front evolves from outside onto the data, then a fit through the data
/// places the surface; the consistently oriented normals of the input come out as a by-product
/// (getInputNormals()). Every length is in the cloud's units, and so is the output. Points with
/// NaN or infinite coordinates are skipped. On bad input the class logs PCL_ERROR and leaves the
/// output empty (getStatus() says why).
///
/// The vertices of reconstruct(pcl::PolygonMesh&) carry x, y, z, normal_x, normal_y, normal_z,
/// curvature (0), `distance` (to the nearest input point, cloud units: large where the surface
/// is a guess, e.g. a side no view saw; trim by it) and the other fields of PointInT (rgb,
/// intensity, label...) from the nearest input point. reconstruct(cloud, polygons) gives each
/// vertex its nearest input point's fields, with the vertex's position and normal.
/// @note setSearchMethod() is accepted for compatibility and not used: distances come from an
/// exact FLANN index of lsrecon's own.
template <typename PointInT>
class LevelSetReconstruction : public SurfaceReconstruction<PointInT> {
 public:
  using Ptr = shared_ptr<LevelSetReconstruction<PointInT>>;
  using ConstPtr = shared_ptr<const LevelSetReconstruction<PointInT>>;

  /// @brief Outcome of the last reconstruct().
  struct Status {
    bool ok = false;         ///< false when the input was rejected (see message)
    std::string message;     ///< why it was rejected, with a hint (also logged by PCL_ERROR)
    bool converged = false;  ///< the stopping test was met
    bool cancelled = false;  ///< the progress callback asked to stop
    int iterations = 0;      ///< time steps taken
    double residual = 0.0;   ///< max distance data -> surface at the end, cloud units
    double tolerance = 0.0;  ///< the stopping tolerance, cloud units
    double spacing = 0.0;    ///< median sampling spacing, cloud units (a scale for trimming by distance)
    int dimension = 0;       ///< 2 or 3, as used
    std::size_t skipped_points = 0;  ///< NaN / infinite points left out
    std::size_t outlier_points = 0;  ///< isolated points left out (no input normal either)
    std::size_t statistical_outlier_points = 0;  ///< left out by setStatisticalOutlierFilter's filter
    std::size_t mesh_vertices = 0;  ///< of the mesh the front evolved on
    std::vector<double> residual_history;  ///< per time step, cloud units (convergence plots)
    std::map<std::string, double> stage_seconds;  ///< wall time per pipeline stage
  };

  LevelSetReconstruction() {
    this->check_tree_ = false;
    options_.lengths = lsr::LengthUnit::input;
  }

  /// @brief Mesh size near the data, cloud units, as pcl::GridProjection's; 0 (the default)
  /// follows the local sampling spacing and noise (lsr::MeshOptions::h_min).
  void setResolution(double cell_size) { options_.mesh.h_min = cell_size; }
  double getResolution() const { return options_.mesh.h_min; }
  /// @brief Widest sampling hole spanned, cloud units; negative (the default): automatic (in 3D
  /// 0.06 of the unit box the cloud's bounding ball of radius 0.4 is mapped to; in 2D none);
  /// 0: none, the front enters through holes (lsr::SamplingOptions::hole_radius).
  void setHoleRadius(double radius) { options_.sampling.hole_radius = radius; }
  double getHoleRadius() const { return options_.sampling.hole_radius; }
  /// @brief Smoothness: the curvature weight beta, cloud units squared; negative (the default):
  /// from the local sampling spacing and noise (lsr::EvolutionOptions::curvature_weight).
  void setCurvatureWeight(double beta) { options_.evolution.curvature_weight = beta; }
  double getCurvatureWeight() const { return options_.evolution.curvature_weight; }
  /// @brief Stopping tolerance, cloud units; 0 (the default) follows the local sampling
  /// spacing (lsr::StoppingOptions::tolerance).
  void setTolerance(double eps) { options_.stopping.tolerance = eps; }
  double getTolerance() const { return options_.stopping.tolerance; }
  /// @brief Time steps at most (lsr::StoppingOptions::max_iterations).
  void setMaxIterations(int n) { options_.stopping.max_iterations = n; }
  int getMaxIterations() const { return options_.stopping.max_iterations; }
  /// @brief Isolated points, whose nearest neighbour is farther than this many local spacings,
  /// are left out; 0 keeps every point (lsr::SamplingOptions::outlier_factor).
  void setOutlierFactor(double factor) { options_.sampling.outlier_factor = factor; }
  double getOutlierFactor() const { return options_.sampling.outlier_factor; }
  /// @brief Run pcl::StatisticalOutlierRemoval (setMeanK(mean_k), setStddevMulThresh(stddev_mul))
  /// on the input first, for scans with clusters of outliers that the isolated-point rule above
  /// keeps; mean_k = 0 (the default) is off. Removed points get NaN input normals. Keep the
  /// threshold high (3): on a random sample its tail is genuine points of sparse regions.
  void setStatisticalOutlierFilter(int mean_k, double stddev_mul) { statistical_ = {mean_k, stddev_mul}; }
  const lsr::adapters::StatisticalOutlierFilter& getStatisticalOutlierFilter() const { return statistical_; }
  /// @brief Start from the tagged front around the data, a sphere around it or inside it
  /// (lsr::StartOptions::initial_front).
  void setInitialFront(lsr::InitialFront start) { options_.start.initial_front = start; }
  lsr::InitialFront getInitialFront() const { return options_.start.initial_front; }
  /// @brief 2 for curves in the plane z = const, 3 for surfaces, 0 (the default): 2 when the
  /// cloud is planar, else 3 (lsr::adapters::detect_dimension).
  void setDimension(int dimension) { dimension_ = dimension; }
  int getDimension() const { return dimension_; }
  /// @brief Refuse (reconstruct() fails with PCL_ERROR, nothing allocated) clouds and meshes
  /// predicted to need more bytes; 0: half the physical memory (lsr::LimitOptions::max_memory).
  void setMaxMemory(double bytes) { options_.limits.max_memory = bytes; }
  double getMaxMemory() const { return options_.limits.max_memory; }
  /// @brief Refuse meshes predicted to need more vertices; 0: from the memory limit
  /// (lsr::LimitOptions::max_vertices).
  void setMaxMeshVertices(int n) { options_.limits.max_vertices = n; }
  int getMaxMeshVertices() const { return options_.limits.max_vertices; }
  /// @brief Threads, as pcl::Poisson::setThreads; 0: all cores (lsr::LimitOptions::threads).
  void setThreads(int n) { options_.limits.threads = n; }
  int getThreads() const { return options_.limits.threads; }
  /// @brief Also mesh the inside and the outside of the result within the box, sharing its
  /// surface vertex for vertex (lsr::OutputOptions::volume_mesh); after reconstruct(),
  /// getVolumeMesh3D() (surfaces) or getVolumeMesh2D() (curves) holds it, in cloud coordinates.
  void setVolumeMeshOutput(bool on) { options_.output.volume_mesh = on; }
  const lsr::VolumeMesh<3>& getVolumeMesh3D() const { return volume3_; }
  const lsr::VolumeMesh<2>& getVolumeMesh2D() const { return volume2_; }
  /// @brief Called with (stage, fraction in [0, 1]); return false to cancel.
  void setProgressCallback(lsr::ProgressCallback callback) { progress_ = std::move(callback); }

  /// @brief Every solver option at once, for those the setters above leave out. The setters'
  /// lengths are in the cloud's units because the options start with lengths =
  /// lsr::LengthUnit::input; options given here keep their own unit.
  void setOptions(const lsr::ReconstructionOptions& options) { options_ = options; }
  const lsr::ReconstructionOptions& getOptions() const { return options_; }
  const Status& getStatus() const { return status_; }
  /// @brief After a 3D reconstruct(): one outward unit normal per point of the input cloud
  /// (same size and order; NaN for points that were skipped or not in the indices), from PCA
  /// of each point's neighbours oriented by the reconstructed level set. Consistently oriented
  /// normals are what pcl::Poisson and the marching-cubes methods need:
  /// @code
  ///   pcl::concatenateFields(*cloud, ls.getInputNormals(), *with_normals);
  /// @endcode
  const pcl::PointCloud<pcl::Normal>& getInputNormals() const { return input_normals_; }

  /// @brief As SurfaceReconstruction::reconstruct, but safe without an input cloud.
  void reconstruct(pcl::PolygonMesh& output) override;
  /// @brief Output vertices as PointInT (see the class).
  void reconstruct(pcl::PointCloud<PointInT>& points, std::vector<pcl::Vertices>& polygons);

 protected:
  std::string getClassName() const override { return "LevelSetReconstruction"; }
  void performReconstruction(pcl::PolygonMesh& output) override;
  void performReconstruction(pcl::PointCloud<PointInT>& points, std::vector<pcl::Vertices>& polygons) override;

 private:
  /// The surface in PCL's terms.
  struct Output {
    pcl::PointCloud<pcl::PointNormal> vertices;
    std::vector<pcl::Vertices> polygons;
    std::vector<float> distance;  ///< per vertex, to the nearest input point
    pcl::Indices nearest;         ///< per vertex, the cloud index of that point
  };
  /// False (logged, status_ says why) without an input cloud.
  bool hasInput();
  /// The core's result as Output; false (logged) on bad input.
  bool run(Output& out);

  lsr::ReconstructionOptions options_;
  lsr::adapters::StatisticalOutlierFilter statistical_;
  lsr::ProgressCallback progress_;
  int dimension_ = 0;
  Status status_;
  pcl::PointCloud<pcl::Normal> input_normals_;
  lsr::VolumeMesh<2> volume2_;
  lsr::VolumeMesh<3> volume3_;
};

}  // namespace pcl

#ifdef PCL_NO_PRECOMPILE
#include "lsrecon/pcl/impl/level_set_reconstruction.hpp"
#endif
