// SPDX-License-Identifier: BSD-3-Clause
/// @file option_checks_test.cpp
/// @brief Options out of range are refused with a hint; a cloud beyond the memory budget is
/// refused before anything is allocated for it.
#include "limits/memory_budget.h"
#include "limits/option_checks.h"

#include "lsrecon/core/errors.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>

namespace lsr::detail {
namespace {

TEST(OptionChecks, EachOptionOutOfRangeIsRefusedWithAHint) {
  EXPECT_NO_THROW(check_options(ReconstructionOptions{}));
  const std::vector<std::function<void(ReconstructionOptions&)>> bad = {
      [](auto& o) { o.mesh.h_min = 1.0; },           [](auto& o) { o.mesh.max_resolution = 2.0; },
      [](auto& o) { o.evolution.alpha = NAN; },           [](auto& o) { o.evolution.time_step = -1.0; },
      [](auto& o) { o.stopping.tolerance = 1.0; },       [](auto& o) { o.sampling.gap_factor = 0.0; },
      [](auto& o) { o.stopping.max_iterations = 0; },    [](auto& o) { o.evolution.renormalization_interval = -1; },
      [](auto& o) { o.evolution.renormalization_interval = o.stopping.patience + 1; },
      [](auto& o) { o.sampling.outlier_factor = 0.5; },  [](auto& o) { o.limits.max_memory = -1.0; },
      [](auto& o) { o.evolution.alpha = -2.0; },  // an enclosing start with alpha < 0
  };
  for (std::size_t i = 0; i < bad.size(); ++i) {
    ReconstructionOptions o;
    bad[i](o);
    try {
      check_options(o);
      ADD_FAILURE() << "case " << i << " accepted";
    } catch (const InvalidInput& e) {
      EXPECT_NE(std::string(e.what()).find("[hint: "), std::string::npos) << i;
    }
  }
}

TEST(MemoryBudget, TheVerticesThatFitBesideThePoints) {
  ReconstructionOptions o;
  o.limits.max_memory = 1e9;
  // (budget - 1 KB per point kept - 150 bytes per point left out) / 1.3 KB per 3D vertex.
  EXPECT_EQ(memory_limited_vertices<3>(o, 100000, 100000), Index((1e9 - 1e8) / 1300.0));
  EXPECT_EQ(memory_limited_vertices<2>(o, 100000, 100000), Index((1e9 - 1e8) / 2000.0));
  EXPECT_EQ(memory_limited_vertices<3>(o, 1000000, 100000), Index((1e9 - 1e8 - 9e5 * 150.0) / 1300.0));
  EXPECT_EQ(memory_limited_vertices<3>(o, 100000, 300000), Index((1e9 - 3e8) / 1300.0));  // rank 0: the whole sample
  EXPECT_NO_THROW(require_cloud_fits<3>(o, 900000));
  EXPECT_THROW(require_cloud_fits<3>(o, 1000000), ResourceLimit);
}

}  // namespace
}  // namespace lsr::detail
