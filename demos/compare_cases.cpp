// SPDX-License-Identifier: BSD-3-Clause
/// @file compare_cases.cpp
#include "compare_cases.h"

namespace lsr::demos {

std::vector<std::string> case_names() { return test_shape_names(); }

CompareCase make_case(const std::string& name, int n, const SamplingVariant& variant, unsigned seed) {
  const TestShape shape = make_test_shape(name);
  const SampledShape sample = sample_test_shape(shape, n, variant, seed);
  CompareCase c;
  c.name = name;
  c.points = sample.points;
  c.normals = sample.normals;
  c.sdf = shape.sdf;
  Points<3> truth_normals;
  sample_shape_surface(shape, 100000, 7, c.truth, truth_normals);
  c.diagonal = sample.diagonal;
  c.genus = shape.genus;
  return c;
}

}  // namespace lsr::demos
