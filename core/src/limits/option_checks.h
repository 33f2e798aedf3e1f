// SPDX-License-Identifier: BSD-3-Clause
/// @file option_checks.h
/// @brief Options out of range refused before any work, with what to use instead.
#pragma once

#include "lsrecon/core/level_set_reconstruction.h"

namespace lsr::detail {

/// @brief Refuses options out of range; the lengths only when they are in the unit box.
void check_options(const ReconstructionOptions& o);

/// @brief The options with their lengths in the unit box, `scale` unit-box lengths per input
/// length (UnitBoxTransform::scale), checked.
ReconstructionOptions in_unit_box(ReconstructionOptions o, double scale);

}  // namespace lsr::detail
