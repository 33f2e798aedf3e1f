// SPDX-License-Identifier: BSD-3-Clause
/// @file test_main.cpp
/// @brief GoogleTest entry point; debug builds trap floating-point errors so a NaN or a
/// division by zero stops the test where it happens.
#include <gtest/gtest.h>

#ifndef NDEBUG
#include <cfenv>
#endif

int main(int argc, char** argv) {
#ifndef NDEBUG
  feenableexcept(FE_DIVBYZERO | FE_INVALID | FE_OVERFLOW);
#endif
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
