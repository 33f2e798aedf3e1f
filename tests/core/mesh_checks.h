// SPDX-License-Identifier: BSD-3-Clause
/// @file mesh_checks.h
/// @brief Test helpers: conformity and shape checks of simplicial meshes of the unit box.
#pragma once

#include "checks/exact_self_intersections.h"
#include "lsrecon/core/level_set_extraction.h"
#include "lsrecon/core/simplex_geometry.h"
#include "mesh/adaptive_refinement.h"
#include "surface/surface_topology.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

namespace lsr::testing {

/// A mesh refined towards samples down to h_min, and f at its vertices.
template <int D>
struct SampledField {
  AdaptiveMesh<D> adaptive;
  std::vector<double> values;
};

template <int D, class F>
SampledField<D> sampled_field(const Points<D>& samples, double h_min, F f) {
  AdaptiveMeshOptions o;
  o.h_min = h_min;
  SampledField<D> s{build_adaptive_mesh(NearestPointIndex<D>(samples), o), {}};
  for (const auto& x : s.adaptive.mesh.vertices) s.values.push_back(f(x));
  return s;
}

/// Empty when every facet is shared by exactly two simplices, or by one on the box boundary.
template <int D>
std::string conformity_error(const SimplexMesh<D>& mesh) {
  std::map<std::array<Index, D>, int> facets;
  for (const auto& s : mesh.simplices) {
    for (int skip = 0; skip <= D; ++skip) {
      std::array<Index, D> f{};
      for (int k = 0, j = 0; k <= D; ++k) {
        if (k != skip) f[j++] = s[k];
      }
      std::sort(f.begin(), f.end());
      ++facets[f];
    }
  }
  for (const auto& [f, count] : facets) {
    bool on_boundary = false;
    for (int d = 0; d < D; ++d) {
      for (double wall : {0.0, 1.0}) {
        bool all = true;
        for (Index v : f) all = all && mesh.vertices[v][d] == wall;
        on_boundary = on_boundary || all;
      }
    }
    if (count != (on_boundary ? 1 : 2)) {
      return "facet starting at vertex " + std::to_string(f[0]) + " is shared by " +
             std::to_string(count) + " simplices";
    }
  }
  return {};
}

/// Shape quality D! |K| / L_max^D: 1/sqrt(D)^D for a Kuhn simplex, 0 when flat.
template <int D>
double shape_quality(const SimplexMesh<D>& mesh, Index s) {
  double longest = 0.0;
  const auto& v = mesh.simplices[s];
  for (int i = 0; i <= D; ++i) {
    for (int j = i + 1; j <= D; ++j) {
      longest = std::max(longest, (mesh.vertices[v[i]] - mesh.vertices[v[j]]).norm());
    }
  }
  const double factorial = D == 2 ? 2.0 : 6.0;
  return factorial * signed_measure(mesh, s) / std::pow(longest, D);
}

/// A closed, manifold, outward-oriented surface with these components and genera (any order).
inline void expect_closed_surface(const LevelSetMesh<3>& s, int components, std::vector<int> genus) {
  const SurfaceTopology t = analyze_surface(s.vertices, s.facets);
  EXPECT_TRUE(t.watertight);
  EXPECT_TRUE(t.edge_manifold);
  EXPECT_TRUE(t.vertex_manifold);
  EXPECT_TRUE(t.oriented);
  EXPECT_EQ(t.degenerate_triangles, 0);
  EXPECT_EQ(t.components, components);
  std::vector<int> sorted = t.genus;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(sorted, genus);
  EXPECT_GT(t.signed_volume, 0.0);  // outward normals: towards u > 0
  EXPECT_EQ(cgal_self_intersections(s.vertices, s.facets), 0u);  // embedded
}

}  // namespace lsr::testing
