// SPDX-License-Identifier: BSD-3-Clause
/// @file vtu_writer_test.cpp
#include "lsrecon/adapters/atomic_file.h"
#include "lsrecon/adapters/vtu_writer.h"
#include "lsrecon/core/errors.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

namespace lsr {
namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

struct TempDir {
  TempDir() : path(fs::temp_directory_path() / ("lsrecon_vtu_" + std::to_string(::getpid()))) {
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
  fs::path path;
};

TEST(VtuWriter, WritesPointsCellsAndFields) {
  TempDir dir;
  const Points<3> p{Vec<3>(0, 0, 0), Vec<3>(1, 0, 0), Vec<3>(0, 1, 0), Vec<3>(0, 0, 1)};
  const std::vector<std::array<Index, 4>> cells{{0, 1, 2, 3}};
  const std::vector<double> u{0.5, -1, 2, 3};
  const auto file = dir.path / "tet.vtu";
  write_vtu<3, 4>(file.string(), p, cells, {{"u", &u}});
  const std::string text = read(file);
  EXPECT_NE(text.find("NumberOfPoints=\"4\" NumberOfCells=\"1\""), std::string::npos);
  EXPECT_NE(text.find("Name=\"u\""), std::string::npos);
  EXPECT_NE(text.find("\n10\n"), std::string::npos);  // VTK_TETRA
  for (const auto& e : fs::directory_iterator(dir.path)) EXPECT_EQ(e.path().string().find(".partial"), std::string::npos);
}

TEST(VtuWriter, AFailedWriteLeavesTheExistingFileAlone) {
  TempDir dir;
  const auto file = dir.path / "keep.vtu";
  std::ofstream(file) << "previous";
  const Points<2> p{Vec<2>(0, 0), Vec<2>(1, 0)};
  const std::vector<double> wrong{1.0};
  EXPECT_THROW((write_vtu<2, 2>(file.string(), p, {{0, 1}}, {{"u", &wrong}})), InvalidInput);
  EXPECT_THROW(write_file_atomically(file.string(),
                                     [](const std::string& tmp) {
                                       std::ofstream(tmp) << "half";
                                       throw Error("disk full", "");
                                     }),
               Error);
  EXPECT_EQ(read(file), "previous");
  for (const auto& e : fs::directory_iterator(dir.path)) EXPECT_EQ(e.path().string().find(".partial"), std::string::npos);
  EXPECT_THROW((write_vtu<2, 2>((dir.path / "missing" / "x.vtu").string(), p, {{0, 1}})), Error);
}

}  // namespace
}  // namespace lsr
