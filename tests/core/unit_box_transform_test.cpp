// SPDX-License-Identifier: BSD-3-Clause
/// @file unit_box_transform_test.cpp
#include "lsrecon/core/errors.h"
#include "sampling/unit_box_transform.h"

#include <gtest/gtest.h>

namespace lsr {
namespace {

TEST(UnitBoxTransform, FitsIntoTheBoxWithMarginAndRoundTrips) {
  for (double scale : {1e-6, 1.0, 1e6}) {
    const Points<3> p{Vec<3>(1, 2, 3) * scale, Vec<3>(3, 2, 4) * scale, Vec<3>(2, 5, 3) * scale};
    const auto t = UnitBoxTransform<3>::fit(p, 0.1);
    const Points<3> unit = t.to_unit(p);
    double lo = 1.0, hi = 0.0;
    for (const auto& y : unit) {
      lo = std::min(lo, y.minCoeff());
      hi = std::max(hi, y.maxCoeff());
    }
    EXPECT_NEAR(lo, 0.1, 1e-12);  // the longest side (y, extent 3) spans [0.1, 0.9]
    EXPECT_NEAR(hi, 0.9, 1e-12);
    const Points<3> back = t.from_unit(unit);
    for (std::size_t i = 0; i < p.size(); ++i) EXPECT_LE((back[i] - p[i]).norm(), 1e-12 * scale * 5);
  }
}

TEST(UnitBoxTransform, RejectsCoincidentEmptyAndNonFinitePoints) {
  EXPECT_THROW(UnitBoxTransform<3>::fit(Points<3>(10, Vec<3>(1e6, 1e6, 1e6)), 0.1), InvalidInput);
  EXPECT_THROW(UnitBoxTransform<3>::fit(Points<3>{}, 0.1), InvalidInput);
  EXPECT_THROW(UnitBoxTransform<2>::fit(Points<2>{Vec<2>(0, 0), Vec<2>(std::nan(""), 1)}, 0.1),
               InvalidInput);
  EXPECT_THROW(UnitBoxTransform<2>::fit(Points<2>{Vec<2>(0, 0), Vec<2>(1, 1)}, 0.5), InvalidInput);
}

}  // namespace
}  // namespace lsr
