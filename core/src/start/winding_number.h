// SPDX-License-Identifier: BSD-3-Clause
/// @file winding_number.h
/// @brief The generalised winding number of an oriented point cloud (Barill et al., "Fast
/// winding numbers for soups and clouds", 2018): w(x) = sum_p a_p n_p . (p - x) / (4 pi |p - x|^3),
/// 1 inside a closed sampled surface, 0 outside, and 1/2 on the disc that spans the rim of an
/// open one (the sheet then subtends half the sphere of directions), whatever its shape. Summed
/// by Barnes-Hut over an octree: a cell farther than kFarRatio times its radius counts as one
/// dipole at its centroid.
#pragma once

#include "lsrecon/core/types.h"

#include <vector>

namespace lsr::detail {

class WindingNumber {
 public:
  /// @param points the samples, `normals` their unit normals (oriented outwards), `areas` the
  /// area each stands for
  WindingNumber(const Points<3>& points, const Points<3>& normals, const std::vector<double>& areas);
  /// @brief w at x.
  double at(const Vec<3>& x) const;

 private:
  struct Cell {
    Vec<3> centroid = Vec<3>::Zero();
    Vec<3> dipole = Vec<3>::Zero();  ///< sum of a_p n_p
    double radius = 0.0;             ///< of the ball around the centroid holding its points
    Index begin = 0, end = 0;        ///< its points in order_
    Index child = -1;                ///< its first child (they are consecutive); -1 for a leaf
    int children = 0;
  };
  void build(Index id, Index begin, Index end, int depth);
  std::vector<Cell> cells_;
  std::vector<Index> order_;
  Points<3> points_;
  Points<3> dipoles_;  ///< a_p n_p in order_
};

}  // namespace lsr::detail
