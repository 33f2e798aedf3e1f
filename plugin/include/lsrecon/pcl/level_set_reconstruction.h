// SPDX-License-Identifier: BSD-3-Clause
/// @file level_set_reconstruction.h
/// @brief pcl::LevelSetReconstruction: closed surfaces (3D) or closed curves (2D) from
/// unoriented points, used like pcl::Poisson.
///
/// @code
///   pcl::LevelSetReconstruction<pcl::PointXYZ> ls;
///   ls.setInputCloud(cloud);
///   pcl::PolygonMesh mesh;
///   ls.reconstruct(mesh);   // watertight, oriented; mesh.cloud carries normals
/// @endcode
#pragma once

#include "lsrecon/adapters/openmesh_mesh.h"  // first: OpenMesh wants its IO header first
#include "lsrecon/adapters/statistical_outliers.h"
#include "lsrecon/core/level_set_reconstruction.h"

#include <pcl/PolygonMesh.h>
#include <pcl/point_types.h>
#include <pcl/point_cloud.h>
#include <pcl/surface/reconstruction.h>

#include <map>
#include <string>
#include <vector>

namespace pcl {

/// @brief Level-set reconstruction (Claisse & Frey 2011) as a pcl::SurfaceReconstruction.
///
/// Needs no normals: a front evolves from outside onto the data, then a fit through the data
/// places the surface; the consistently oriented normals of the input come out as a by-product
/// (getInputNormals()). Lengths passed to
/// setters are relative to the unit box the cloud is mapped into (its bounding ball becomes a
/// ball of radius 0.4); the output is in the cloud's coordinates. Points with NaN or infinite
/// coordinates are skipped. On bad input the class logs PCL_ERROR and leaves the output empty.
/// Every option starts at the default of lsr::ReconstructionOptions, which documents it; the
/// getters return the values in use.
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
    int dimension = 0;       ///< 2 or 3, as used
    std::size_t skipped_points = 0;  ///< NaN / infinite points left out
    std::size_t outlier_points = 0;  ///< isolated points left out (no input normal either)
    std::size_t statistical_outlier_points = 0;  ///< left out by setStatisticalOutlierFilter's filter
    /// insides closed behind an opening narrower than the hole radius (an open end that a
    /// sampling hole made; lsr::ReconstructionResult::sealed_cavities)
    int sealed_cavities = 0;
    /// points seen from both sides when open sides were closed, else 0
    /// (lsr::ReconstructionResult::open_side_points)
    long long open_side_points = 0;
    std::size_t mesh_vertices = 0;  ///< of the mesh the front evolved on
    std::vector<double> residual_history;  ///< per time step, cloud units (convergence plots)
    std::map<std::string, double> stage_seconds;  ///< wall time per pipeline stage
  };

  LevelSetReconstruction() { this->check_tree_ = false; }

  /// @brief Resolution 1/h_min in the unit box, the same everywhere near the data; 0 follows the
  /// local sampling spacing and noise (lsr::MeshOptions::h_min).
  void setResolution(double resolution) { options_.mesh.h_min = resolution > 0 ? 1.0 / resolution : 0.0; }
  double getResolution() const { return options_.mesh.h_min > 0 ? 1.0 / options_.mesh.h_min : 0.0; }
  /// @brief Cap on the local resolution (lsr::MeshOptions::max_resolution); finer
  /// costs time and memory and tells closer sheets apart.
  void setMaximumResolution(double resolution) { options_.mesh.max_resolution = resolution; }
  double getMaximumResolution() const { return options_.mesh.max_resolution; }
  /// @brief Isolated points, whose nearest neighbour is farther than this many local spacings,
  /// are left out; 0 keeps every point (lsr::SamplingOptions::outlier_factor).
  void setOutlierFactor(double factor) { options_.sampling.outlier_factor = factor; }
  double getOutlierFactor() const { return options_.sampling.outlier_factor; }
  /// @brief Run pcl::StatisticalOutlierRemoval (setMeanK(mean_k), setStddevMulThresh(stddev_mul))
  /// on the input first, for scans with clusters of outliers that the isolated-point rule above
  /// keeps; mean_k = 0 (the default) is off. Removed points get NaN input normals. Keep the
  /// threshold high (3): on a random sample its tail is genuine points of sparse regions, and
  /// the holes their removal leaves let the front in (docs/how-it-works.md, "Outliers").
  void setStatisticalOutlierFilter(int mean_k, double stddev_mul) { statistical_ = {mean_k, stddev_mul}; }
  const lsr::adapters::StatisticalOutlierFilter& getStatisticalOutlierFilter() const { return statistical_; }
  /// @brief Widest sampling hole spanned, in the unit box (the cloud's bounding ball has radius
  /// 0.4); negative (the default): lsr::automatic_defaults(D).hole_radius, 0.06 in 3D, none in
  /// 2D; 0: none, the front enters through
  /// holes (lsr::SamplingOptions::hole_radius).
  void setHoleRadius(double radius) { options_.sampling.hole_radius = radius; }
  double getHoleRadius() const { return options_.sampling.hole_radius; }
  /// @brief Coarsest mesh size in the unit box (lsr::MeshOptions::h_max).
  void setMaximumSize(double h_max) { options_.mesh.h_max = h_max; }
  double getMaximumSize() const { return options_.mesh.h_max; }
  /// @brief Grading c of the adaptive mesh; smaller widens the fine band
  /// (lsr::MeshOptions::grading).
  void setGrading(double c) { options_.mesh.grading = c; }
  double getGrading() const { return options_.mesh.grading; }
  /// @brief Attraction weight alpha (lsr::EvolutionOptions::alpha).
  void setAlpha(double alpha) { options_.evolution.alpha = alpha; }
  double getAlpha() const { return options_.evolution.alpha; }
  /// @brief Curvature (smoothness) weight beta, unit box length^2; negative: from the local
  /// sampling spacing and noise (lsr::EvolutionOptions::curvature_weight).
  void setCurvatureWeight(double beta) { options_.evolution.curvature_weight = beta; }
  double getCurvatureWeight() const { return options_.evolution.curvature_weight; }
  /// @brief Time step in unit-box time (lsr::EvolutionOptions::time_step).
  void setTimeStep(double dt) { options_.evolution.time_step = dt; }
  double getTimeStep() const { return options_.evolution.time_step; }
  /// @brief Time steps at most (lsr::StoppingOptions::max_iterations).
  void setMaxIterations(int n) { options_.stopping.max_iterations = n; }
  int getMaxIterations() const { return options_.stopping.max_iterations; }
  /// @brief Stopping tolerance in the unit box; 0 follows the local sampling spacing
  /// (lsr::StoppingOptions::tolerance).
  void setTolerance(double eps) { options_.stopping.tolerance = eps; }
  double getTolerance() const { return options_.stopping.tolerance; }
  /// @brief Renormalise every k steps, k at most 5 (the stall rule's patience); 0: automatic
  /// (lsr::EvolutionOptions::renormalization_interval).
  void setRenormalizationInterval(int k) { options_.evolution.renormalization_interval = k; }
  int getRenormalizationInterval() const { return options_.evolution.renormalization_interval; }
  /// @brief Start from the tagged front around the data, a sphere around it or inside it
  /// (lsr::StartOptions::initial_front).
  void setInitialSurface(lsr::InitialFront start) { options_.start.initial_front = start; }
  lsr::InitialFront getInitialSurface() const { return options_.start.initial_front; }
  /// @brief 2 for curves in the plane z = const, 3 for surfaces, 0 (the default): 2 when the
  /// cloud is planar, else 3 (lsr::adapters::detect_dimension).
  void setDimension(int dimension) { dimension_ = dimension; }
  int getDimension() const { return dimension_; }
  /// @brief Refuse (reconstruct() fails with PCL_ERROR, nothing allocated) clouds and meshes
  /// predicted to need more bytes (lsr::LimitOptions::max_memory).
  void setMaximumMemory(double bytes) { options_.limits.max_memory = bytes; }
  double getMaximumMemory() const { return options_.limits.max_memory; }
  /// @brief Refuse meshes predicted to need more vertices; 0: from the memory limit
  /// (lsr::LimitOptions::max_vertices).
  void setMaxMeshVertices(int n) { options_.limits.max_vertices = n; }
  int getMaxMeshVertices() const { return options_.limits.max_vertices; }
  /// @brief Threads; 0: all cores (lsr::LimitOptions::threads).
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

  /// @brief All solver options at once.
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
  /// @brief Output vertices as PointInT (normals filled when PointInT has them).
  void reconstruct(pcl::PointCloud<PointInT>& points, std::vector<pcl::Vertices>& polygons);
  /// @brief The surface as an OpenMesh triangle mesh with vertex normals (3D only).
  /// @return false (logged with PCL_ERROR, mesh left empty) on bad input or 2D data.
  bool reconstruct(lsr::adapters::TriMesh& mesh);

 protected:
  std::string getClassName() const override { return "LevelSetReconstruction"; }
  void performReconstruction(pcl::PolygonMesh& output) override;
  void performReconstruction(pcl::PointCloud<PointInT>& points, std::vector<pcl::Vertices>& polygons) override;

 private:
  /// The core result as a PointNormal cloud and polygons; false (logged) on bad input.
  bool run(pcl::PointCloud<pcl::PointNormal>& vertices, std::vector<pcl::Vertices>& polygons);

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
