// SPDX-License-Identifier: BSD-3-Clause
/// @file option_checks.h
/// @brief Options out of range refused before any work, with what to use instead.
#pragma once

#include "lsrecon/core/level_set_reconstruction.h"

namespace lsr::detail {

void check_options(const ReconstructionOptions& o);

}  // namespace lsr::detail
