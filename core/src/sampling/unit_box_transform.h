// SPDX-License-Identifier: BSD-3-Clause
/// @file unit_box_transform.h
/// @brief The uniform scaling that maps a point set into the unit box [0,1]^D with a margin
/// (aspect kept), and its inverse for the output.
#pragma once

#include "lsrecon/core/types.h"

namespace lsr {

/// @brief x_unit = 0.5 + scale * (x - center).
template <int D>
class UnitBoxTransform {
 public:
  /// @brief Fits the bounding box of points into [margin, 1 - margin]^D, centred.
  /// @throw InvalidInput if points is empty, non-finite, all coincident, or margin is not in
  /// [0, 0.5).
  static UnitBoxTransform fit(const Points<D>& points, double margin);

  /// @brief Maps the ball around the bounding-box centre that holds every point onto the ball
  /// of the given radius around the box centre (0.5, ..., 0.5).
  /// @throw InvalidInput as fit(), or if radius is not in (0, 0.5].
  static UnitBoxTransform fit_ball(const Points<D>& points, double radius);
  /// @brief fit() from the bounding box [lo, hi] of `count` points (a cloud split among workers).
  static UnitBoxTransform fit_bounds(const Vec<D>& lo, const Vec<D>& hi, std::size_t count, double margin);
  /// @brief fit_ball() from this box's centre and the farthest point's distance to it.
  UnitBoxTransform with_ball(double reach, double radius) const;

  Vec<D> to_unit(const Vec<D>& x) const { return (x - center_) * scale_ + Vec<D>::Constant(0.5); }
  Vec<D> from_unit(const Vec<D>& y) const { return (y - Vec<D>::Constant(0.5)) / scale_ + center_; }
  Points<D> to_unit(const Points<D>& xs) const;
  Points<D> from_unit(const Points<D>& ys) const;
  /// @brief Unit-box lengths per input length.
  double scale() const { return scale_; }
  const Vec<D>& center() const { return center_; }

 private:
  Vec<D> center_ = Vec<D>::Zero();
  double scale_ = 1.0;
};

}  // namespace lsr
