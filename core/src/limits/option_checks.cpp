// SPDX-License-Identifier: BSD-3-Clause
/// @file option_checks.cpp
#include "limits/option_checks.h"

#include "lsrecon/core/errors.h"

#include <cmath>
#include <string>

namespace lsr::detail {
namespace {

[[noreturn]] void bad(const std::string& what, const std::string& hint) { throw InvalidInput(what, hint); }

// The lengths, in the unit box.
void check_lengths(const ReconstructionOptions& o) {
  const std::string unit = o.lengths == LengthUnit::input ? " (unit box: your value times the box's scale)" : "";
  if (!(o.mesh.h_min >= 0.0 && o.mesh.h_min < 1.0)) bad("h_min must be in [0, 1)" + unit, "use 0 (automatic) or e.g. 1/128");
  if (!(o.mesh.max_resolution == 0.0 || (o.mesh.max_resolution >= 4.0 && o.mesh.max_resolution <= 1e5))) {
    bad("max_resolution must be 0 (automatic) or in [4, 1e5]" + unit, "use 0 (256 in 3D, 4096 in 2D) or e.g. 512");
  }
  if (!(o.stopping.tolerance >= 0.0 && o.stopping.tolerance < 1.0)) {
    bad("tolerance must be in [0, 1)" + unit, "use 0 (automatic: tolerance_factor local spacings)");
  }
  if (!(o.sampling.hole_radius < 0.5)) bad("hole_radius must be below 0.5" + unit, "use -1 (automatic), 0 (no closing) or e.g. 0.06");
}

}  // namespace

ReconstructionOptions in_unit_box(ReconstructionOptions o, double scale) {
  if (o.lengths == LengthUnit::input) {
    o.mesh.h_min *= scale;
    o.mesh.max_resolution /= scale;
    if (o.sampling.hole_radius > 0.0) o.sampling.hole_radius *= scale;
    if (o.evolution.curvature_weight > 0.0) o.evolution.curvature_weight *= scale * scale;
    o.stopping.tolerance *= scale;
  }
  check_lengths(o);
  o.lengths = LengthUnit::unit_box;
  return o;
}

void check_options(const ReconstructionOptions& o) {
  if (o.lengths == LengthUnit::unit_box) check_lengths(o);
  if (!(o.mesh.anisotropic_error > 0.0 && o.mesh.anisotropic_error <= 100.0)) {
    bad("anisotropic_error must be in (0, 100]", "use 0.25 (local mesh sizes)");
  }
  if (!std::isfinite(o.evolution.alpha)) bad("alpha is not finite", "use 0 (automatic), 2 or -2");
  if (!std::isfinite(o.evolution.curvature_weight)) bad("curvature_weight is not finite", "use -1 (automatic)");
  if (!(o.mesh.h_min >= 0.0)) bad("h_min must be >= 0", "use 0 (automatic)");
  if (!(o.mesh.max_resolution >= 0.0)) bad("max_resolution must be >= 0", "use 0 (automatic)");
  if (!(o.stopping.tolerance >= 0.0)) bad("tolerance must be >= 0", "use 0 (automatic)");
  if (!(o.evolution.time_step >= 0.0 && o.evolution.time_step < 1e3)) bad("time_step must be >= 0 and finite", "use 0 (automatic: 0.2 / |alpha|)");
  auto factor = [&](double v, const char* name, double lo, double hi, const char* use) {
    if (!(v > lo && v <= hi)) bad(std::string(name) + " must be in (" + std::to_string(lo) + ", " + std::to_string(hi) + "]", use);
  };
  factor(o.sampling.gap_factor, "gap_factor", 0.0, 20.0, "use 2 (local scales)");
  factor(o.evolution.pin_factor, "pin_factor", 0.0, 20.0, "use 2 (local scales)");
  factor(o.stopping.tolerance_factor, "tolerance_factor", 0.0, 20.0, "use 1 (local scales)");
  factor(o.evolution.curvature_factor, "curvature_factor", -1e-300, 100.0, "use 0.25");
  if (!(o.start.start_offset >= 0.0 && o.start.start_offset < o.sampling.gap_factor)) {
    bad("start_offset must be in [0, gap_factor)", "use 0.5 (local spacings) or 0 (the flood's boundary)");
  }
  if (o.stopping.max_iterations < 1) bad("max_iterations must be at least 1", "try 1000");
  if (o.evolution.renormalization_interval < 0) bad("renormalization_interval must be >= 0", "use 0 (automatic), 1 or 2");
  if (o.stopping.patience < 1) bad("patience must be at least 1", "use 5");
  // The front side of the stopping test is read at renormalisations: with none for `patience`
  // steps no residual is known, and the run stops as stalled at its start. Without
  // renormalising, |u| is no distance either.
  if (o.evolution.renormalization_interval > o.stopping.patience) {
    bad("renormalization_interval " + std::to_string(o.evolution.renormalization_interval) + " exceeds patience " +
            std::to_string(o.stopping.patience) + ": the stopping test measures the front at renormalisations",
        "use 0 (automatic), 1 or 2; every 5-20 steps also leaves islands and holes");
  }
  if (!(o.stopping.stall_gain >= 0.0 && o.stopping.stall_gain < 1.0)) bad("stall_gain must be in [0, 1)", "use 0.05");
  if (!(o.stopping.near_residual < 1e3)) bad("near_residual must be below 1000", "use a negative value (automatic)");
  if (!(o.stopping.stall_stillness >= 0.0 && o.stopping.stall_stillness < 1e3)) bad("stall_stillness must be in [0, 1000)", "use 0.01 (or 0: off)");
  if (!(o.stopping.unreached_fraction >= 0.0 && o.stopping.unreached_fraction < 1.0)) bad("unreached_fraction must be in [0, 1)", "use 0.01");
  if (!(o.sampling.outlier_factor == 0.0 || (o.sampling.outlier_factor >= 1.0 && o.sampling.outlier_factor <= 1e3))) {
    bad("outlier_factor must be 0 (keep every point) or in [1, 1000]", "use 3");
  }
  if (!(o.limits.solve_tiles >= 1 && o.limits.solve_tiles <= 64)) bad("solve_tiles must be in [1, 64] (tiles per axis)", "use 1 (one mesh) or e.g. 2");
  if (o.limits.solve_tiles > 1 && (o.output.volume_mesh || o.mesh.anisotropic)) {
    bad("the front solved in tiles gives no volume mesh and no anisotropic mesh", "use solve_tiles 1 for those");
  }
  if (o.limits.max_vertices < 0) bad("max_vertices must be >= 0", "use 0 (from max_memory)");
  if (!(o.limits.max_memory >= 0.0 && o.limits.max_memory < 1e15)) bad("max_memory must be >= 0 bytes and finite", "use 0 (half the physical memory)");
  if (!(o.evolution.solver_tolerance > 0.0 && o.evolution.solver_tolerance < 1.0)) bad("solver_tolerance must be in (0, 1)", "use 1e-6");
  if (o.start.initial_front != InitialFront::inside && o.evolution.alpha < 0.0) {
    bad("alpha < 0 makes a front that encloses the data grow away from it",
        "use alpha > 0 (e.g. 2) with the enclosing start, or start inside");
  }
  if (o.evolution.two_sided && o.evolution.alpha < 0.0) {
    bad("two-sided attraction moves the front towards the data from both sides with alpha > 0",
        "use alpha > 0 (e.g. 2) or 0 (automatic)");
  }
  if (o.start.initial_front == InitialFront::inside && o.evolution.alpha > 0.0) {
    bad("alpha > 0 makes a front that starts inside the data shrink away from it",
        "use alpha < 0 (e.g. -2) with the inside start");
  }
}


}  // namespace lsr::detail
