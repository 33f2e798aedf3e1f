// SPDX-License-Identifier: BSD-3-Clause
/// @file winding_number.h
/// @brief The generalised winding number of an oriented point cloud (Barill et al., "Fast
/// winding numbers for soups and clouds", 2018): w(x) = sum_p a_p n_p . (p - x) / (c_D |p - x|^D)
/// with c_3 = 4 pi, c_2 = 2 pi: 1 inside a closed sampled surface (curve), 0 outside, and 1/2 on
/// the disc that spans the rim of an open one (the sheet then subtends half the sphere of
/// directions), whatever its shape. Summed by Barnes-Hut over a 2^D-tree: a cell farther than
/// kFarRatio times its radius counts as one dipole at its centroid.
#pragma once

#include "lsrecon/core/types.h"

#include <vector>

namespace lsr::detail {

template <int D>
class WindingNumber {
 public:
  /// @param points the samples, `normals` their unit normals (oriented outwards), `areas` the
  /// area (2D: length) each stands for; `radii`, if not empty, each sample's own radius: nearer
  /// than it, x sees the sample as at that distance (the patch it stands for, whose field is
  /// bounded, instead of a dipole's), so w is smooth across the samples.
  WindingNumber(const Points<D>& points, const Points<D>& normals, const std::vector<double>& areas,
                const std::vector<double>& radii = {});
  /// @brief w at x.
  double at(const Vec<D>& x) const;

 private:
  struct Cell {
    Vec<D> centroid = Vec<D>::Zero();
    Vec<D> dipole = Vec<D>::Zero();  ///< sum of a_p n_p
    double radius = 0.0;             ///< of the ball around the centroid holding its points
    double reach = 0.0;              ///< the largest sample radius in it
    Index begin = 0, end = 0;        ///< its points in order_
    Index child = -1;                ///< its first child (they are consecutive); -1 for a leaf
    int children = 0;
  };
  void build(Index id, Index begin, Index end, int depth);
  static double term(const Vec<D>& dipole, const Vec<D>& at, double radius, const Vec<D>& x);
  std::vector<Cell> cells_;
  std::vector<Index> order_;
  Points<D> points_;
  Points<D> dipoles_;  ///< a_p n_p in order_
  std::vector<double> radii_;
};

/// @brief The area (2D: length) a sample stands for when `others` other samples lie within
/// `reach` of it: pi reach^2 / others (2D: 2 reach / others), the density of its neighbourhood.
/// With others = LocalSampling::kSpacingRank and the spacing as reach it is the patch the
/// spacing rule assumes (6 samples in a disc of radius s; 2D: 2 along a segment s either side).
template <int D>
double sample_measure(double reach, int others);

}  // namespace lsr::detail
