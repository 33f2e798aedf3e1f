// SPDX-License-Identifier: BSD-3-Clause
#include "lsrecon/core/resolution_hierarchy.h"

#include "geometry/facet_mesh_distance.h"
#include "lsrecon/core/errors.h"
#include "sampling/local_sampling.h"
#include "sampling/unit_box_transform.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace lsr {
namespace {

// The resolution the data asks for: one mesh cell per median sampling spacing, in the unit
// box the pipeline maps the data into (its bounding ball of radius 0.4).
template <int D>
double data_resolution(const Points<D>& input, int threads) {
  Points<D> points;
  for (const auto& p : input) {
    if (p.allFinite()) points.push_back(p);
  }
  if (points.size() < std::size_t(D + 2)) return 4.0;  // reconstruct() will say what is wrong
  const auto box = UnitBoxTransform<D>::fit_ball(points, 0.4);
  const double spacing = median(estimate_local_sampling(NearestPointIndex<D>(box.to_unit(points)), threads).spacing);
  return spacing > 0.0 ? 1.0 / spacing : 4.0;
}

}  // namespace

template <int D>
std::vector<ReconstructionResult<D>> reconstruct_levels(const Points<D>& points, int levels,
                                                        const ReconstructionOptions& options, bool warm_start,
                                                        const ProgressCallback& progress) {
  if (levels < 1 || levels > 8) throw InvalidInput("levels must be between 1 and 8", "use e.g. 3");
  // The levels' resolutions are set in the unit box, where the solver works.
  if (options.lengths != LengthUnit::unit_box) {
    throw InvalidInput("levels of detail take their lengths in the unit box", "set ReconstructionOptions::lengths to unit_box");
  }
  const double cap = options.mesh.max_resolution > 0.0 ? options.mesh.max_resolution : automatic_defaults(D).max_resolution;
  const double finest = std::min(cap, options.mesh.h_min > 0.0 ? 1.0 / options.mesh.h_min : data_resolution(points, options.limits.threads));
  std::vector<ReconstructionResult<D>> out;
  for (int k = 0; k < levels; ++k) {
    ReconstructionOptions o = options;
    if (k < levels - 1) {
      o.mesh.max_resolution = std::max(4.0, finest / std::pow(2.0, levels - 1 - k));
      o.mesh.h_min = 0.0;
    }
    const std::string prefix = "l" + std::to_string(k) + " ";
    const ProgressCallback level_progress = [&](const std::string& stage, double fraction) {
      return !progress || progress(prefix + stage, fraction);
    };
    const bool from_previous = warm_start && k > 0 && !out.back().surface.facets.empty();
    if (from_previous) {
      const ReconstructionResult<D>& previous = out.back();
      const FacetMeshDistance<D> surface(previous.surface.vertices, previous.surface.facets);
      const double offset = o.sampling.gap_factor * previous.spacing;
      const SignedDistance<D> start = [&surface, offset](const Vec<D>& p) { return surface.signed_distance(p) - offset; };
      o.evolution.alpha = o.evolution.alpha != 0.0 ? std::abs(o.evolution.alpha) : automatic_defaults(D).alpha;  // the start encloses the data
      out.push_back(reconstruct_from<D>(points, start, o, level_progress));
    } else {
      out.push_back(reconstruct<D>(points, o, level_progress));
    }
    if (out.back().status == ReconstructionStatus::cancelled) break;
  }
  return out;
}

template std::vector<ReconstructionResult<2>> reconstruct_levels<2>(const Points<2>&, int, const ReconstructionOptions&,
                                                                    bool, const ProgressCallback&);
template std::vector<ReconstructionResult<3>> reconstruct_levels<3>(const Points<3>&, int, const ReconstructionOptions&,
                                                                    bool, const ProgressCallback&);

}  // namespace lsr
