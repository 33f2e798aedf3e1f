// SPDX-License-Identifier: BSD-3-Clause
/// @file shape_corpus.h
/// @brief Test shapes with known topology and their random samplings: what the tests and
/// benchmarks judge reconstructions on. Each shape is an exact (or, at creases of unions, a
/// lower-bound) signed distance; samples are i.i.d. and area-uniform, as a scanner's are
/// irregular, with optional noise, holes and a density gradient.
#pragma once

#include "lsrecon/core/types.h"

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace lsr {

/// @brief A closed surface given by its signed distance (< 0 inside).
struct TestShape {
  std::string name;
  std::function<double(const Vec<3>&)> sdf;
  Vec<3> lo, hi;            ///< a box containing the surface
  std::vector<int> genus;   ///< per component, sorted ascending: the topology to recover
  std::string description;
  /// For a shape given as a closed triangle mesh (sdf is then its signed distance): the mesh,
  /// sampled directly. Empty for implicit shapes.
  Points<3> mesh_vertices;
  std::vector<std::array<Index, 3>> mesh_triangles;
};

/// @brief sphere, torus, double-torus (genus 2), triple-torus (genus 3: two tori crossing
/// twice), trefoil (a knotted tube), linked-rings (two components, genus 1 each), cup (a
/// thin-walled cup, genus 0), limb (a ball with a 10:1 thin limb), two-spheres (two components
/// 4% of the diagonal apart), bunny (the Stanford bunny's closed mesh: thin ears, genus 0).
/// @throw InvalidInput for an unknown name (the message lists the names).
TestShape make_test_shape(const std::string& name);

/// @brief The names make_test_shape() knows.
std::vector<std::string> test_shape_names();

/// @brief How a sample departs from the clean, uniform one. Lengths relative to the diagonal
/// of the shape's surface bounding box.
struct SamplingVariant {
  double noise = 0.0;          ///< Gaussian deviation per coordinate
  int holes = 0;               ///< number of caps left unsampled
  double hole_radius = 0.04;   ///< radius of each cap
  double density_ratio = 1.0;  ///< densest / sparsest, varying linearly along x
};

/// @brief A sampled cloud with its ground truth.
struct SampledShape {
  Points<3> points;   ///< what a reconstructor sees
  Points<3> normals;  ///< true outward unit normals at the clean positions
  double diagonal = 1.0;  ///< diagonal of the bounding box of the clean surface sample
};

/// @brief n i.i.d. points of the surface, area-uniform before the variant's changes (which keep
/// n points). Deterministic for a given seed.
SampledShape sample_test_shape(const TestShape& shape, int n, const SamplingVariant& variant = {},
                               std::uint64_t seed = 1);

/// @brief n i.i.d. area-uniform points of {sdf = 0} inside [lo, hi]: uniform points of the shell
/// |sdf| < delta projected onto the surface along grad sdf; for an exact signed distance the
/// shell's volume per area is 2 delta (1 + delta^2 K / 3), uniform to O(delta^2 K).
Points<3> sample_implicit_surface(const std::function<double(const Vec<3>&)>& sdf, const Vec<3>& lo,
                                  const Vec<3>& hi, int n, std::uint64_t seed);

/// @brief n i.i.d. area-uniform points of the shape's surface with their true outward normals:
/// from its triangles for a mesh shape, else sample_implicit_surface() and sdf_normal().
/// Deterministic for a given seed.
void sample_shape_surface(const TestShape& shape, int n, std::uint64_t seed, Points<3>& points, Points<3>& normals);

/// @brief Unit outward normal of {sdf = 0} at p (central differences).
Vec<3> sdf_normal(const std::function<double(const Vec<3>&)>& sdf, const Vec<3>& p);

}  // namespace lsr
