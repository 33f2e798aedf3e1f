// SPDX-License-Identifier: BSD-3-Clause
/// @file quadric_implicit.h
/// @brief An implicit function through oriented points: one quadric height field per point,
/// fitted to its neighbours in its tangent frame, blended by a partition of unity (the local
/// fits of MPU implicits, Ohtake et al. 2003). Its zero set passes through the data to second
/// order, where a front held between samples by curvature alone sags by O(spacing).
///
/// Each fit uses only neighbours whose normal agrees with the centre's (n_j . n_i > 0): with
/// outward normals, the samples of the other side of a thin part or a close sheet are left out.
/// The others weigh exp(-(1 - n_i . n_j) / (1 - cos kNormalWidth)), so that a fit next to a
/// crease follows its own side instead of rounding the crease over its whole neighbourhood
/// (the robust local fits of Oeztireli et al. 2009, in their simplest form).
#pragma once

#include "geometry/nearest_point_index.h"
#include "lsrecon/core/progress.h"

#include <vector>

namespace lsr {

/// @brief F(x) ~ signed distance to the surface through the points (> 0 outside).
template <int D>
class QuadricImplicit {
 public:
  /// Points per local fit on clean data. Noise sigma_i widens a fit to
  /// kFitNeighbours (1 + (sigma_i / (0.05 s_i))^2) points, at most kMaxFitNeighbours: its height
  /// error falls like sigma / sqrt(K) while the curvature bias grows like K^2 s^4 / R^3
  /// (calibrated, docs/calibration.md). In 3D a fit of kCubicNeighbours or more also fits the cubic terms of its
  /// height field and keeps them where they explain more than its noise (Schwarz's criterion,
  /// height_field_fit.h): the cubic follows a crease or a bend across the wide neighbourhood
  /// that a quadric rounds, which lets noisy fits grow wider where the quadric suffices.
  static constexpr int kFitNeighbours = D == 2 ? 10 : 30;
  static constexpr int kMaxFitNeighbours = D == 2 ? 40 : 160;
  static constexpr int kCubicNeighbours = 2 * kFitNeighbours;
  /// A fit keeps no cubic terms where the weighted centroid of its neighbours lies farther than
  /// this fraction of its reach from it: on a straight rim it lies at 4 / (3 pi) = 0.42 of the
  /// reach (uniform weights), inside the data within about 0.03 of it (160 random neighbours).
  static constexpr double kCubicBalance = 0.2;
  static constexpr int kBlendCentres = D == 2 ? 4 : 12;    ///< fits blended at a query
  /// Points fitted per block: the wide neighbour lists are held for one block at a time (at
  /// most 42 MB), and progress is reported (and cancellation checked) between blocks.
  static constexpr long kFitBlock = 1 << 16;
  /// Normal width of a fit's neighbours on clean data, widened on noisy data by the factor
  /// sqrt(1 + (sigma_i / (0.05 s_i))^2) that widens the neighbourhood (at most 90 degrees).
  /// Calibrated (docs/calibration.md). A smooth part turns by less than 7 degrees across a fit's
  /// neighbourhood wherever its radius of curvature exceeds about 25 spacings (the neighbours
  /// lie within about 3), and a fit on a tighter bend still keeps its nearest neighbours. Where
  /// the other side of a thin part lies among the PCA neighbours (within sqrt(15 / 6) s_i) the
  /// normals tell no crease, and the fit keeps plain weights.
  static constexpr double kNormalWidth = 7.0 * kPi / 180.0;
  /// A fit widened by noise is redone on its kFitNeighbours nearest alone where it misses
  /// them by more than this times sigma_i^2 in mean square: there its width rounds off what
  /// lies within its reach (a face's nose and mouth, a horn thinner than the fit). Noise alone
  /// keeps that mean below sigma^2 (the fit leaves part of it in its residual), with a standard
  /// deviation of sigma^2 sqrt(2 / 30) = 0.26 sigma^2: 3 is eight of them above.
  static constexpr double kMaxMissRatio = 3.0;

  /// @param data the points (#N) and their kd-tree
  /// @param normals #N unit outward normals
  /// @param spacing #N local sampling spacing: the width of each fit's blending weight
  /// @param noise #N local noise deviation (empty: clean), not raised by curvature
  /// (residual_noise.h): a curved clean part is fitted as clean
  /// @param threads 0 for all cores
  /// @param nearest the min(kFitNeighbours, #N) nearest of each point, as query_k gives them,
  /// when the caller has them already (residual_noise uses the same); null: queried here
  /// @param progress stage "fit", the fraction of the points fitted; throws Cancelled
  QuadricImplicit(const NearestPointIndex<D>& data, Points<D> normals, std::vector<double> spacing,
                  const std::vector<double>& noise = {}, int threads = 0,
                  const LargeVector<Index>* nearest = nullptr, const Progress& progress = Progress());
  /// @brief F at each query (#Q) and, if asked, the unit outward normal of the blended fits.
  void evaluate(const Points<D>& queries, std::vector<double>& value, Points<D>* normal = nullptr,
                int threads = 0) const;

  /// @brief Moves each point onto {F = 0} (two steps x -= F(x) n(x)); returns the normals of the
  /// second step's start (the second step moves points by rounding errors only: another blend
  /// there would cost a third of the projection for nothing).
  /// The blended fits are those of the starting position: a step moves a point by far less
  /// than a spacing, over which the weight of a change in the k nearest is negligible.
  Points<D> project(Points<D>& points, int threads = 0) const;

 private:
  struct Fit {
    /// the frame's normal: its rows (D-1 tangents, then the normal) are recomputed where a
    /// blend reads it, 48 bytes less per point (0.5 GB at 10M points)
    Vec<D> normal;
    double c0 = 0.0;
    Eigen::Matrix<double, D - 1, 1> g;
    Eigen::Matrix<double, D - 1, D - 1> h;
    /// 3D, wide fits: the coefficients of t0^3 / 6, t0^2 t1 / 2, t0 t1^2 / 2, t1^3 / 6 (zero
    /// where the quadric was selected)
    Eigen::Matrix<double, D == 3 ? 4 : 0, 1> cubic = Eigen::Matrix<double, D == 3 ? 4 : 0, 1>::Zero();
    double reach = 0.0;  ///< radius of the neighbourhood fitted
    double fade_width2 = 0.0;  ///< (2 reach)^2: the curvature term fades beyond 2 reach
  };
  /// The fit of point i (width: 1 - cos of its normal width) from its k nearest.
  Fit fit_point(const Points<D>& p, const Points<D>& normals, std::size_t i, const Index* near, int k, double width,
                double noise) const;
  double fit_value(const Fit& f, const Vec<D>& centre, const Vec<D>& x, Vec<D>* normal) const;
  /// F (and the normal) at each query from the given blend centres (kBlendCentres per query).
  void blend(const Points<D>& queries, const LargeVector<Index>& nearest, int k, std::vector<double>& value,
             Points<D>* normal, int threads) const;

  const NearestPointIndex<D>* data_;
  std::vector<double> spacing_;
  std::vector<double> blend_width2_;  ///< per point: the squared width of its blending weight
  std::vector<Fit> fits_;
};

}  // namespace lsr
