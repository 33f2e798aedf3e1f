// SPDX-License-Identifier: BSD-3-Clause
/// @file point_files_test.cpp
/// @brief lsrecon's own PCD and PLY point readers: every encoding and numeric type, headers
/// that lie or continue past DATA, truncation, and every mesh format lsrecon writes read back.
#include "lsrecon/adapters/openmesh_mesh.h"
#include "lsrecon/adapters/point_files.h"
#include "lsrecon/testdata/analytic_shapes.h"
#include "lsrecon/core/errors.h"

#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

namespace lsr::adapters {
namespace {

namespace fs = std::filesystem;

class PointFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("lsrecon_points_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string file(const std::string& name, const std::function<void(std::ofstream&)>& content) const {
    const std::string p = (dir_ / name).string();
    std::ofstream f(p, std::ios::binary);
    content(f);
    return p;
  }

  // Points whose coordinates need double precision: a float would round them by up to 6e-8.
  static Points<3> points() {
    Points<3> p;
    for (int i = 0; i < 50; ++i) p.emplace_back(1.0 / 3.0 + i, 1e6 + 0.1 * i, -2.0 / 7.0 * i);
    return p;
  }

  static void expect_points(const PointFile& read, const Points<3>& expected) {
    ASSERT_EQ(read.points.size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_EQ(read.points[i], expected[i]) << i;
  }

  // The error message of read_point_file on `path` ("" if it reads).
  static std::string refusal(const std::string& path) {
    try {
      (void)read_point_file(path);
    } catch (const Error& e) {
      return e.what();
    }
    return "";
  }

  fs::path dir_;
};

template <class T>
void put(std::ofstream& f, T v, bool big_endian = false) {
  unsigned char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  if (big_endian) std::reverse(b, b + sizeof(T));
  f.write(reinterpret_cast<const char*>(b), sizeof(T));
}

// A PCD header for `fields` (each "name size type"), n points, and DATA `data`.
std::string pcd(const std::vector<std::string>& names, const std::vector<int>& sizes, const std::string& types, std::size_t n,
                const std::string& data) {
  std::string f = "FIELDS", s = "SIZE", t = "TYPE", c = "COUNT";
  for (std::size_t i = 0; i < names.size(); ++i) {
    f += " " + names[i];
    s += " " + std::to_string(sizes[i]);
    t += std::string(" ") + types[i];
    c += " 1";
  }
  return "# .PCD v0.7\nVERSION 0.7\n" + f + "\n" + s + "\n" + t + "\n" + c + "\nWIDTH " + std::to_string(n) +
         "\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS " + std::to_string(n) + "\nDATA " + data + "\n";
}

TEST_F(PointFiles, PclWrittenPcdIsReadInEveryEncoding) {
  pcl::PointCloud<pcl::PointNormal> cloud;  // extra fields around x, y, z
  for (const auto& p : Sphere{Vec<3>(1, 2, 3), 2.0}.sample(500)) {
    pcl::PointNormal q;
    q.x = float(p.x());
    q.y = float(p.y());
    q.z = float(p.z());
    q.normal_x = 1.0f;
    cloud.push_back(q);
  }
  Points<3> expected;
  for (const auto& q : cloud) expected.emplace_back(double(q.x), double(q.y), double(q.z));
  const std::string ascii = (dir_ / "a.pcd").string(), binary = (dir_ / "b.pcd").string(), packed = (dir_ / "c.pcd").string();
  ASSERT_EQ(pcl::io::savePCDFileASCII(ascii, cloud), 0);
  ASSERT_EQ(pcl::io::savePCDFileBinary(binary, cloud), 0);
  ASSERT_EQ(pcl::io::savePCDFileBinaryCompressed(packed, cloud), 0);
  expect_points(read_point_file(binary), expected);
  expect_points(read_point_file(packed), expected);
  // ASCII at PCL's 8 significant digits, read back as the declared float: 5e-8 relative for the
  // decimal rounding, 2^-24 (6e-8) for the float's.
  const PointFile text = read_point_file(ascii);
  ASSERT_EQ(text.points.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(text.points[i][k], expected[i][k], 1.1e-7 * std::abs(expected[i][k])) << i;
  }
}

TEST_F(PointFiles, DoubleAndIntegerPcdCoordinatesAreRead) {
  const Points<3> p = points();
  const std::string binary = file("d.pcd", [&](std::ofstream& f) {
    f << pcd({"x", "y", "z", "intensity"}, {8, 8, 8, 2}, "FFFU", p.size(), "binary");
    for (const auto& q : p) {
      for (int k = 0; k < 3; ++k) put(f, q[k]);
      put(f, std::uint16_t(7));
    }
  });
  expect_points(read_point_file(binary), p);
  const std::string ascii = file("d-ascii.pcd", [&](std::ofstream& f) {
    f << pcd({"x", "y", "z"}, {8, 8, 8}, "FFF", p.size(), "ascii");
    f.precision(17);
    for (const auto& q : p) f << q.x() << ' ' << q.y() << ' ' << q.z() << '\n';
  });
  expect_points(read_point_file(ascii), p);
  // Integer coordinates (a depth camera's millimetres): signed 16-bit x, unsigned 8-bit y, signed 32-bit z.
  const std::string integers = file("i.pcd", [&](std::ofstream& f) {
    f << pcd({"x", "y", "z"}, {2, 1, 4}, "IUI", 3, "binary");
    for (int i = 0; i < 3; ++i) {
      put(f, std::int16_t(-1000 * i));
      put(f, std::uint8_t(200 + i));
      put(f, std::int32_t(-70000 * i));
    }
  });
  expect_points(read_point_file(integers), {Vec<3>(0, 200, 0), Vec<3>(-1000, 201, -70000), Vec<3>(-2000, 202, -140000)});
}

// PCL 1.13's reader goes on parsing header keywords after DATA: this body took it to 11.5 GiB
// (WIDTH / POINTS) or to reading past its buffer (SIZE 8 8 8). Here the body is a body.
TEST_F(PointFiles, HeaderKeywordsAfterDataAreBodyBytesNotHeader) {
  for (const std::string body : {"WIDTH 1000000000\nPOINTS 1000000000\n", "SIZE 8 8 8\nTYPE F F F\n"}) {
    for (const std::string data : {"ascii", "binary"}) {
      const std::string path = file("after-data-" + data + ".pcd", [&](std::ofstream& f) {
        f << pcd({"x", "y", "z"}, {4, 4, 4}, "FFF", 3, data) << body << std::string(64, '\0');
      });
      rusage before{}, after{};
      getrusage(RUSAGE_SELF, &before);
      if (data == "ascii") {
        EXPECT_NE(refusal(path).find("is not a number"), std::string::npos) << body;
      } else {
        // 36 bytes of the body are the 3 declared points' floats; nothing else is read.
        const PointFile read = read_point_file(path);
        EXPECT_EQ(read.points.size() + read.skipped, 3u);
      }
      getrusage(RUSAGE_SELF, &after);
      EXPECT_LT(double(after.ru_maxrss - before.ru_maxrss) * 1024.0, 1e8) << body << data;
    }
  }
}

TEST_F(PointFiles, PcdHeadersThatDisagreeOrLieAreRefused) {
  struct Case {
    std::string name, content, message;
  };
  const std::vector<Case> cases = {
      {"lies", pcd({"x", "y", "z"}, {4, 4, 4}, "FFF", 1000000000, "binary") + std::string(36, '\0'), "declares 1e+09 points"},
      {"lies-ascii", pcd({"x", "y", "z"}, {4, 4, 4}, "FFF", 1000000000, "ascii") + "0 0 0\n", "declares 1e+09 points"},
      {"float-size-2", pcd({"x", "y", "z"}, {2, 4, 4}, "FFF", 1, "binary") + std::string(10, '\0'), "has TYPE F, SIZE 2"},
      {"no-z", pcd({"x", "y"}, {4, 4}, "FF", 1, "binary") + std::string(8, '\0'), "no x, y and z"},
      {"cut", pcd({"x", "y", "z"}, {4, 4, 4}, "FFF", 2, "ascii") + "0.0 0.0 0.0\n1.0 1.0\n", "ends after 1 of its points"},
      {"extra", pcd({"x", "y", "z"}, {4, 4, 4}, "FFF", 1, "ascii") + "0 0 0\n1 1 1\n", "more values"},
      {"unknown-data", pcd({"x", "y", "z"}, {4, 4, 4}, "FFF", 1, "lz4") + std::string(12, '\0'), "unknown PCD DATA type 'lz4'"},
      {"repeated", "FIELDS x y z\nFIELDS x y z\nDATA ascii\n", "unknown or repeated PCD header line 'FIELDS'"},
      {"escape", "\x1b]0;owned\a\nDATA ascii\n", "unknown or repeated PCD header line '\\x1b]0;owned\\x07'"},
      {"compressed-lies", pcd({"x", "y", "z"}, {4, 4, 4}, "FFF", 4, "binary_compressed") + std::string("\x10\0\0\0\x30\0\0\0", 8) +
                              std::string(16, '\x01'), "does not decompress"},
  };
  for (const Case& c : cases) {
    const std::string path = file(c.name + ".pcd", [&](std::ofstream& f) { f << c.content; });
    EXPECT_NE(refusal(path).find(c.message), std::string::npos) << c.name << ": " << refusal(path);
  }
}

std::string ply_header(const std::string& format, std::size_t n, const std::string& type, const std::string& before = "",
                       const std::string& extra = "") {
  return "ply\nformat " + format + " 1.0\ncomment made by a test\n" + before + "element vertex " + std::to_string(n) +
         "\nproperty " + type + " x\nproperty " + type + " y\nproperty " + type + " z\n" + extra + "element face 0\n"
         "property list uchar int vertex_indices\nend_header\n";
}

TEST_F(PointFiles, PlyOfEveryEncodingAndTypeIsRead) {
  const Points<3> p = points();
  for (const bool big : {false, true}) {
    const std::string path = file(big ? "be.ply" : "le.ply", [&](std::ofstream& f) {
      // A face element first, with one triangle, and a list in the vertex element.
      f << ply_header(big ? "binary_big_endian" : "binary_little_endian", p.size(), "double",
                      "element face 1\nproperty list uchar int vertex_indices\n", "property list uchar float extra\n");
      put(f, std::uint8_t(3), big);
      for (int i = 0; i < 3; ++i) put(f, std::int32_t(i), big);
      for (const auto& q : p) {
        for (int k = 0; k < 3; ++k) put(f, q[k], big);
        put(f, std::uint8_t(2), big);
        put(f, 1.5f, big);
        put(f, 2.5f, big);
      }
    });
    expect_points(read_point_file(path), p);
  }
  const std::string ascii = file("a.ply", [&](std::ofstream& f) {
    f << ply_header("ascii", p.size(), "float64", "element camera 1\nproperty float focal\n");
    f.precision(17);
    f << "35.0\n";
    for (const auto& q : p) f << q.x() << ' ' << q.y() << ' ' << q.z() << '\n';
  });
  expect_points(read_point_file(ascii), p);
  const std::string shorts = file("s.ply", [&](std::ofstream& f) {
    f << ply_header("binary_little_endian", 2, "short");
    for (const std::int16_t v : {-1, 2, -3, 32767, -32768, 0}) put(f, v);
  });
  expect_points(read_point_file(shorts), {Vec<3>(-1, 2, -3), Vec<3>(32767, -32768, 0)});
}

TEST_F(PointFiles, PlyThatLiesOrEndsEarlyIsRefused) {
  struct Case {
    std::string name, content, message;
  };
  const std::vector<Case> cases = {
      {"lies", ply_header("binary_little_endian", 1000000000, "float") + std::string(36, '\0'), "declares 1e+09 elements"},
      {"cut", ply_header("ascii", 3, "float") + "0.0 0.0 0.0\n1.0 1.0 1.0\n2.0 2.0\n", "ends before the last vertex"},
      {"word", ply_header("ascii", 1, "float") + "0 zero 0\n", "'zero' in the PLY data is not a number"},
      {"no-format", "ply\nelement vertex 1\nproperty float x\nend_header\n0\n", "no format line"},
      {"type", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float128 x\nend_header\n0\n", "unknown PLY property type 'float128'"},
      {"no-xyz", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n0\n", "no x, y and z"},
      {"no-vertex", "ply\nformat ascii 1.0\nelement face 1\nproperty float x\nend_header\n0\n", "no vertex element"},
      // Found by fuzzing: 6.7e13 rows of an element without properties, read one by one.
      {"empty-rows", "ply\nformat ascii 1.0\nelement dH 66666666666662\nend_header\n34s?", "no vertex element"},
      // Found by fuzzing: a list length of 6.9e79 in text, converted to an integer (undefined).
      {"huge-list", ply_header("ascii", 2, "float", "", "property list uchar short l\n") + "0 0 0 1 2\n0 0 0 6.9e79\n" +
                        std::string(64, ' '), "impossible length"},
  };
  for (const Case& c : cases) {
    const std::string path = file(c.name + ".ply", [&](std::ofstream& f) { f << c.content; });
    EXPECT_NE(refusal(path).find(c.message), std::string::npos) << c.name << ": " << refusal(path);
  }
}

// What lsrecon writes, lsrecon reads: its double-precision PLY among them.
// Saved points come back bit for bit: binary doubles in a .ply, 17 significant digits in text.
TEST_F(PointFiles, SavedPointsAreReadBackExactly) {
  const Points<3> points = {Vec<3>(1.0 / 3.0, -2e-300, 7.0), Vec<3>(1e6 + 0.1, std::nextafter(1.0, 2.0), -0.0),
                            Vec<3>(M_PI, -M_E, 1e300)};
  for (const std::string name : {"p.ply", "p.xyz"}) {
    const std::string path = (dir_ / name).string();
    write_points(path, points);
    const PointFile read = read_point_file(path);
    ASSERT_EQ(read.points.size(), points.size()) << name;
    for (std::size_t i = 0; i < points.size(); ++i) EXPECT_EQ(read.points[i], points[i]) << name << " " << i;
  }
}

// lsrecon-mpi's ranks each read a part: the parts, in order, are the file's points, and each
// knows how many rows the others hold. Binary PLY (a seek past the rows before, and a face
// element before the vertices), text PLY (rows before parsed and dropped) and a text file (read
// whole and cut), with a NaN row.
TEST_F(PointFiles, ThePartsOfAFileAreItsPointsInOrder) {
  Points<3> p = points();
  p.resize(10);
  p[4] = Vec<3>(std::nan(""), 0, 0);
  const std::string binary = file("parts.ply", [&](std::ofstream& f) {
    f << ply_header("binary_little_endian", p.size(), "double", "element face 1\nproperty list uchar int vertex_indices\n");
    put(f, std::uint8_t(3));
    for (int i = 0; i < 3; ++i) put(f, std::int32_t(i));
    for (const auto& q : p) {
      for (int k = 0; k < 3; ++k) put(f, q[k]);
    }
  });
  const std::string ascii = file("parts-ascii.ply", [&](std::ofstream& f) {
    f << ply_header("ascii", p.size(), "float64");
    f.precision(17);
    for (const auto& q : p) f << q.x() << ' ' << q.y() << ' ' << q.z() << '\n';
  });
  const std::string text = file("parts.xyz", [&](std::ofstream& f) {
    f.precision(17);
    for (const auto& q : p) f << q.x() << ' ' << q.y() << ' ' << q.z() << '\n';
  });
  Points<3> finite;
  for (const auto& q : p) {
    if (q.allFinite()) finite.push_back(q);
  }
  for (const std::string& path : {binary, ascii, text}) {
    for (const std::size_t parts : {1, 3, 4}) {
      Points<3> all;
      std::size_t skipped = 0;
      for (std::size_t part = 0; part < parts; ++part) {
        const PointFile f = read_point_file(path, {part, parts});
        EXPECT_EQ(f.points.size() + f.skipped + f.other_rows, p.size()) << path << " " << part << "/" << parts;
        all.insert(all.end(), f.points.begin(), f.points.end());
        skipped += f.skipped;
      }
      EXPECT_EQ(skipped, 1u) << path;
      expect_points(PointFile{all, 0, false, 0}, finite);
    }
  }
}

TEST_F(PointFiles, EveryMeshFormatLsreconWritesIsReadBack) {
  LevelSetMesh<3> tetrahedron;
  tetrahedron.vertices = {Vec<3>(1.0 / 3.0, 0, 0), Vec<3>(1e6 + 0.1, 0, 0), Vec<3>(0, 1, 0), Vec<3>(0, 0, 1)};
  tetrahedron.facets = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  const TriMesh mesh = to_openmesh(tetrahedron, {});
  for (const std::string ext : {"ply", "obj", "off", "stl"}) {
    const std::string path = (dir_ / ("t." + ext)).string();
    write_mesh_file(mesh, path);
    const PointFile read = read_point_file(path);
    ASSERT_GE(read.points.size(), 4u) << ext;  // STL repeats a vertex per triangle
    for (const auto& v : tetrahedron.vertices) {
      // STL stores floats: within float rounding of the coordinates (relative 2^-24).
      const double tolerance = ext == "stl" ? v.norm() * 6e-8 : 0.0;
      double nearest = 1e300;
      for (const auto& q : read.points) nearest = std::min(nearest, (q - v).norm());
      EXPECT_LE(nearest, tolerance) << ext;
    }
  }
}

}  // namespace
}  // namespace lsr::adapters

namespace lsr::adapters {
namespace {

// Range scans registered by a Stanford .conf: each scan's points p become R(q)^T p + t. A
// quarter turn about z (q = (0, 0, sin 45, cos 45)) maps (1, 0, 0) to R^T (1, 0, 0) = (0, -1, 0);
// the identity leaves the other scan where it is. Relative paths are the .conf's folder's.
TEST_F(PointFiles, RangeScansAreReadRegisteredByTheirConf) {
  file("a.xyz", [](std::ofstream& f) { f << "1 0 0\n0 2 0\n"; });
  fs::create_directories(dir_ / "views");
  file("views/b.xyz", [](std::ofstream& f) { f << "0 0 3\n"; });
  const double s = std::sqrt(0.5);
  const std::string conf = file("scans.conf", [&](std::ofstream& f) {
    f.precision(17);
    f << "camera 0 0 0 0 0 0 1\nbmesh a.xyz 10 20 30 0 0 " << s << ' ' << s << "\nbmesh views/b.xyz 0 0 0 0 0 0 1\n";
  });
  const PointFile read = read_point_file(conf);
  ASSERT_EQ(read.points.size(), 3u);
  const Points<3> expected = {Vec<3>(10, 19, 30), Vec<3>(12, 20, 30), Vec<3>(0, 0, 3)};
  for (std::size_t i = 0; i < 3; ++i) EXPECT_LT((read.points[i] - expected[i]).norm(), 1e-12) << i << ": " << read.points[i].transpose();
  // Bad lines and bad scans: refused, naming the file and line.
  const std::string short_line = file("short.conf", [](std::ofstream& f) { f << "bmesh a.xyz 1 2 3\n"; });
  EXPECT_NE(refusal(short_line).find("short.conf:1: expected a file name and 7 numbers"), std::string::npos) << refusal(short_line);
  const std::string zero = file("zero.conf", [](std::ofstream& f) { f << "bmesh a.xyz 0 0 0 0 0 0 0\n"; });
  EXPECT_NE(refusal(zero).find("quaternion"), std::string::npos) << refusal(zero);
  const std::string missing = file("missing.conf", [](std::ofstream& f) { f << "bmesh none.xyz 0 0 0 0 0 0 1\n"; });
  EXPECT_NE(refusal(missing).find("none.xyz"), std::string::npos) << refusal(missing);
  const std::string nested = file("nested.conf", [](std::ofstream& f) { f << "bmesh scans.conf 0 0 0 0 0 0 1\n"; });
  EXPECT_NE(refusal(nested).find("not other .conf files"), std::string::npos) << refusal(nested);
  const std::string empty = file("empty.conf", [](std::ofstream& f) { f << "camera 0 0 0 0 0 0 1\n"; });
  EXPECT_NE(refusal(empty).find("lists no scan"), std::string::npos) << refusal(empty);
}

}  // namespace
}  // namespace lsr::adapters
