// SPDX-License-Identifier: BSD-3-Clause
/// @file drives.h
/// @brief What drives the front besides curvature: the one-sided data term at rest past the
/// data, and the two-sided convection towards it.
#pragma once

#include "evolution/p1_operators.h"
#include "geometry/nearest_point_index.h"
#include "lsrecon/core/simplex_geometry.h"
#include "lsrecon/core/types.h"
#include "sampling/local_sampling.h"

#include <Eigen/Core>

#include <vector>

namespace lsr::detail {

// The data term of Zhao, Osher and Fedkiw's convection towards the data, in the form the step
// takes: u_t = alpha d grad d . grad u = |grad u| alpha d cos(theta), theta between the normal
// and the direction away from the data. The front moves towards the data from either side at
// the speed alpha d of the one-sided term (same CFL), and stops on it.
template <int D>
Eigen::VectorXd two_sided_drive(const P1Operators<D>& ops, const Eigen::VectorXd& d, const Points<D>& away,
                                const Eigen::VectorXd& u);

// The one-sided drive, with d := 0 where the front has passed its nearest data point (faces
// away from it: alpha grad d . grad u < 0, alpha's sign the way it moves) by more than `gap`:
// the one-sided term would go on pulling it on, into a pit under one of the widest empty discs
// of a random sample, which the stopping test's front side then never accepts. Not `near_hole`
// (empty: nowhere): a front that crept past a hole's rim is the fit's to correct (attach_fit),
// and resting it there leaves handles.
template <int D>
Eigen::VectorXd drive_resting_past_data(const P1Operators<D>& ops, const Eigen::VectorXd& d, const Points<D>& away,
                                        const Eigen::VectorXd& u, const std::vector<double>& dist, const Eigen::VectorXd& gap,
                                        const std::vector<char>& near_hole, double alpha);

/// @brief The attraction d(x) and where spanned holes take it over.
struct Attraction {
  Eigen::VectorXd d;           ///< #V: what drives the front (zeroed where it is pinned, later)
  std::vector<char> over_hole; ///< #V: the discs nearer than the points; empty without discs
};

/// @brief d = the distance to the data (`distance`, #V); with holes spanned (`hole_radius` > 0),
/// the distance to the rims' tangent discs (tangent_discs.h) wherever a hole's discs can reach
/// and the start's gap (plus a margin) beyond. Within the gap of the data the points themselves
/// attract: there the discs add nothing over a hole, and at a concave crease the tilted PCA
/// planes of the points next to it span the groove less than a gap from its tip (a lid that
/// stalls the front).
template <int D>
Attraction attraction(const NearestPointIndex<D>& data, const LocalSampling<D>& sampling, const SimplexMesh<D>& mesh,
                      const std::vector<double>& dist, const Eigen::VectorXd& distance, const Eigen::VectorXd& scale,
                      double gap_factor, double hole_radius, bool rims_only, int threads);

}  // namespace lsr::detail
