// SPDX-License-Identifier: BSD-3-Clause
/// @file lsrecon_bad_input_test.cpp
/// @brief The bad-input table: what users feed lsrecon from scanners and the web, each row
/// asserting the exit code, the message, and that no output was created or clobbered.
#include "cli_fixture.h"

#include <gtest/gtest.h>

#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <functional>
#include <random>
#include <string>
#include <thread>
#include <vector>

namespace {

using lsr_test::Cli;
using lsr_test::CliRun;
using lsr_test::expect_closed_mesh;
namespace fs = std::filesystem;

struct Row {
  std::string name;                             // the input file written into the scratch directory
  std::function<void(std::ofstream&)> content;  // its bytes
  std::string message;                          // what the error must say
};

void lines(std::ofstream& f, const std::vector<std::string>& text) {
  for (const auto& l : text) f << l << '\n';
}

// A binary PLY / PCD / STL whose header declares far more than the file holds: it must be
// refused from its header, before any reader reserves memory for the count.
std::vector<Row> lying_headers() {
  return {
      {"lies.ply", [](std::ofstream& f) { f << "ply\nformat binary_little_endian 1.0\nelement vertex 1000000000\n"
                                               "property float x\nproperty float y\nproperty float z\nend_header\n"
                                            << std::string(36, '\0'); }, "declares 1e+09 elements"},
      {"huge.ply", [](std::ofstream& f) { f << "ply\nformat ascii 1.0\nelement vertex 2147483648\nproperty float x\n"
                                               "property float y\nproperty float z\nend_header\n0 0 0\n"; }, "declares"},
      {"lies.pcd", [](std::ofstream& f) { f << "VERSION .7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n"
                                               "WIDTH 1000000000\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 1000000000\n"
                                               "DATA binary\n" << std::string(36, '\0'); }, "declares 1e+09 points"},
      {"lies.off", [](std::ofstream& f) { f << "OFF\n500000000 0 0\n0 0 0\n1 0 0\n"; }, "declares"},
      {"lies.stl", [](std::ofstream& f) {
         f << std::string(80, ' ');
         const std::uint32_t n = 1u << 31;
         f.write(reinterpret_cast<const char*>(&n), 4);
         f << std::string(100, '\0'); }, "declares"},
      {"huge.pgm", [](std::ofstream& f) { f << "P5\n99999 99999\n255\n" << std::string(64, '\0'); }, "declares"},
      {"cut.pgm", [](std::ofstream& f) { f << "P5\n128 128\n255\n" << std::string(100, '\0'); }, "declares"},
      {"zero.pgm", [](std::ofstream& f) { f << "P5\n0 0\n255\n"; }, "empty"},
      {"cut.png", [](std::ofstream& f) { f << "\x89PNG\r\n"; }, "not a PNG"},
  };
}

// Text a user can get wrong, and point sets that cannot make a closed surface.
std::vector<Row> bad_points() {
  return {
      {"empty.xyz", [](std::ofstream& f) { f << "# nothing\n"; }, "holds no points: it is empty"},
      {"header-only.xyz", [](std::ofstream& f) { lines(f, {"garbage here"}); }, "holds no points"},
      {"one.xyz", [](std::ofstream& f) { lines(f, {"1 2 3"}); }, "1 distinct point"},
      {"same.xyz", [](std::ofstream& f) { lines(f, {"1 2 3", "1 2 3", "1 2 3", "1 2 3", "1 2 3"}); }, "1 distinct point"},
      {"three.xyz", [](std::ofstream& f) { lines(f, {"0 0 0", "1 0 0", "0 1 0"}); }, "3 distinct point"},
      {"nan.xyz", [](std::ofstream& f) { lines(f, {"nan 0 0", "0 inf 0", "0 0 -inf"}); }, "empty"},
      {"some-nan.xyz", [](std::ofstream& f) { lines(f, {"nan 0 0", "0 0 0", "1 0 0", "0 1 0", "0 0 inf"}); }, "3 distinct point"},
      {"far.xyz", [](std::ofstream& f) { lines(f, {"1e300 0 0", "0 0 0", "1 0 0", "0 1 0", "0 0 1"}); }, "thinner than 1e-6"},
      {"line.xyz", [](std::ofstream& f) { for (int i = 0; i < 100; ++i) f << i << ' ' << 2 * i << ' ' << 3 * i << '\n'; }, "colinear"},
      {"words.xyz", [](std::ofstream& f) { lines(f, {"1 2 3", "4 five 6"}); }, "words.xyz:2: 'five'"},
      {"decimal-comma.xyz", [](std::ofstream& f) { lines(f, {"1,5 2,5 3,5"}); }, "'.' as the decimal point"},
      {"junk.pcd", [](std::ofstream& f) { f << "this is not a point cloud\n"; }, "no PCD header"},
      {"junk.ply", [](std::ofstream& f) { f << "ply\nformat nonsense\n"; }, "no PLY header"},
      {"in.unknown", [](std::ofstream& f) { f << "1 2 3\n"; }, "unknown input format"},
      {"mixed.xyz", [](std::ofstream& f) { lines(f, {"0 0 0", "1 0 0", "1 0"}); }, "mixed.xyz:3: 2 coordinates where the first point has 3"},
      {"cut.stl", [](std::ofstream& f) { lines(f, {"solid " + std::string(80, 'x'), "facet normal 0 0 1", "outer loop", "vertex 0 0 0", "vertex 1 0 0"}); },
       "ends inside a facet"},
      // Bytes from the file reach the message as text: no NUL to cut it, no escape for the terminal.
      {"escape.xyz", [](std::ofstream& f) { lines(f, {"1 2 3", "\x1b]0;title\a 5 6"}); }, "'\\x1b]0;title\\x07' is not a number"},
      {"nul.xyz", [](std::ofstream& f) { f << "1 2 3\n4" << '\0' << "x 5 6\n"; }, "'4\\x00x' is not a number ["},
  };
}

class BadInput : public Cli {
 protected:
  // Runs lsrecon on `input` towards an existing keep.ply and asserts: exit 1, the message with
  // a hint, keep.ply untouched, no temporary file left.
  void expect_refused(const std::string& input, const std::string& message) {
    std::ofstream(path("keep.ply")) << "precious";
    const CliRun r = run(input + " " + path("keep.ply") + " --quiet");
    EXPECT_EQ(r.status, 1) << input << ": " << r.output;
    EXPECT_NE(r.output.find(message), std::string::npos) << input << ": " << r.output;
    EXPECT_NE(r.output.find("[hint: "), std::string::npos) << input << ": " << r.output;
    EXPECT_EQ(read("keep.ply"), "precious") << input;
    expect_no_temporary_file();
  }

  void expect_no_temporary_file() const {
    for (const auto& entry : fs::directory_iterator(dir_)) {
      EXPECT_EQ(entry.path().string().find(".partial"), std::string::npos) << entry.path();
    }
  }

  void write(const Row& row) const {
    std::ofstream f(path(row.name), std::ios::binary);
    row.content(f);
  }
};

TEST_F(BadInput, EachPointFileRowIsRefusedWithItsMessage) {
  for (const Row& row : bad_points()) {
    write(row);
    expect_refused(path(row.name), row.message);
  }
  expect_refused(path("missing.xyz"), "cannot open");
  // A FIFO without a writer: refused at once, not waited on.
  ASSERT_EQ(::mkfifo(path("pipe.xyz").c_str(), 0600), 0);
  expect_refused(path("pipe.xyz"), "not a regular file");
  expect_refused(dir_.string(), "is a directory");
}

TEST_F(BadInput, HeadersThatLieAboutTheirCountsAreRefusedBeforeAnyAllocation) {
  for (const Row& row : lying_headers()) {
    write(row);
    expect_refused(path(row.name), row.message);
  }
  // And it is the header check, not a later failure: the peak memory of the refused runs is
  // that of an empty process plus the libraries (well below a 1e9-point reservation of 12 GB).
  rusage usage{};
  getrusage(RUSAGE_CHILDREN, &usage);
  EXPECT_LT(double(usage.ru_maxrss) * 1024.0, 1e9);
}

TEST_F(BadInput, ScannerTextVariantsAreRead) {
  // CSV with a header line, CRLF line ends, every point twice, extra columns (normals).
  const lsr::Points<3> points = sphere();
  std::ofstream csv(path("s.csv.txt")), crlf(path("s-crlf.xyz")), twice(path("s-twice.xyz")), extra(path("s-extra.xyz"));
  csv << "x,y,z\n";
  for (const auto& p : points) {
    csv << p.x() << ',' << p.y() << ',' << p.z() << '\n';
    crlf << p.x() << ' ' << p.y() << ' ' << p.z() << "\r\n";
    twice << p.x() << ' ' << p.y() << ' ' << p.z() << '\n' << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
    extra << p.x() << '\t' << p.y() << '\t' << p.z() << "\t0 0 1\n";
  }
  csv.close();
  crlf.close();
  twice.close();
  extra.close();
  for (const char* in : {"s.csv.txt", "s-crlf.xyz", "s-twice.xyz", "s-extra.xyz"}) {
    const CliRun r = run(path(in) + " " + path("out.ply") + " --quiet");
    EXPECT_EQ(r.status, 0) << in << ": " << r.output;
    expect_closed_mesh(path("out.ply"));
  }
}

TEST_F(BadInput, FewPointsThatSpanSpaceGiveAClosedSurface) {
  // Four points (a tetrahedron's corners): a closed surface, never one cut open by the box.
  std::ofstream(path("four.xyz")) << "0 0 0\n1 0 0\n0 1 0\n0 0 1\n";
  const CliRun r = run(path("four.xyz") + " " + path("four.ply") + " --quiet");
  ASSERT_EQ(r.status, 0) << r.output;
  expect_closed_mesh(path("four.ply"));
}

TEST_F(BadInput, OutputsThatCannotBeWrittenAreRefusedBeforeTheRun) {
  std::ofstream in(path("in.xyz"));
  for (const auto& p : sphere()) in << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  in.close();
  const std::string original = read("in.xyz");
  struct Case {
    std::string output, message;
  };
  fs::create_directories(path("sub.ply"));
  for (const Case& c : {Case{path("missing-dir/out.ply"), "does not exist"}, Case{path("sub.ply"), "is a directory"}}) {
    const CliRun r = run(path("in.xyz") + " " + c.output + " --quiet");
    EXPECT_EQ(r.status, 1) << c.output << ": " << r.output;
    EXPECT_NE(r.output.find(c.message), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("[read"), std::string::npos) << "refused only after reading: " << r.output;
  }
  // Output == input (a point PLY read and a mesh PLY written to the same path).
  std::ofstream ply(path("both.ply"));
  ply << "ply\nformat ascii 1.0\nelement vertex " << sphere().size() << "\nproperty float x\nproperty float y\nproperty float z\nend_header\n";
  for (const auto& p : sphere()) ply << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  ply.close();
  const std::string cloud = read("both.ply");
  CliRun r = run(path("both.ply") + " " + path("both.ply") + " --quiet");
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("is the input file"), std::string::npos) << r.output;
  EXPECT_EQ(read("both.ply"), cloud);
  // A read-only directory (root may write anywhere: nothing to test then).
  if (::geteuid() != 0) {
    fs::create_directories(path("ro"));
    fs::permissions(path("ro"), fs::perms::owner_read | fs::perms::owner_exec);
    r = run(path("in.xyz") + " " + path("ro/out.ply") + " --quiet");
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("permission denied"), std::string::npos) << r.output;
    fs::permissions(path("ro"), fs::perms::owner_all);
  }
  EXPECT_EQ(read("in.xyz"), original);
}

TEST_F(BadInput, AbsurdOptionsExitWithTwoNamingTheOption) {
  for (const std::string option : {"--resolution 1e9", "--resolution -3", "--resolution nan", "--time-step 1e300",
                                    "--max-iterations 2.7", "--threads -1", "--alpha inf", "--max-memory -1",
                                    "--resolution=abc"}) {
    const CliRun r = run("--demo sphere " + path("o.ply") + " --quiet " + option);
    EXPECT_EQ(r.status, 2) << option << ": " << r.output;
    const std::string flag = option.substr(0, option.find_first_of(" ="));
    EXPECT_NE(r.output.find("lsrecon: " + flag), std::string::npos) << option << ": " << r.output;
    EXPECT_FALSE(fs::exists(path("o.ply"))) << option;
  }
}

TEST_F(BadInput, AThousandThreadsGiveTheSameMeshAsOne) {
  const std::string common = "--demo torus --points 3000 --quiet ";
  ASSERT_EQ(run(common + path("one.off") + " --threads 1").status, 0);
  ASSERT_EQ(run(common + path("many.off") + " --threads=1000").status, 0);
  EXPECT_EQ(read("one.off"), read("many.off"));
}

TEST_F(BadInput, AMeshBeyondTheMemoryLimitIsRefusedBeforeItIsBuilt) {
  // 0.25 GiB cannot hold a resolution-2000 mesh (tens of millions of vertices at 3 KB).
  const CliRun r = run("--demo sphere --points 3000 --resolution 2000 --max-memory 0.25 --quiet " + path("o.ply"));
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("resolution of at most"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("max_memory"), std::string::npos) << r.output;
  rusage usage{};
  getrusage(RUSAGE_CHILDREN, &usage);
  EXPECT_LT(double(usage.ru_maxrss) * 1024.0, 0.25 * double(1 << 30));
  EXPECT_FALSE(fs::exists(path("o.ply")));
  // The points alone: 2 million at 1 KB each exceed 1 GiB.
  const CliRun points = run("--demo sphere --points 2000000 --max-memory 1 --quiet " + path("o.ply"));
  EXPECT_EQ(points.status, 1) << points.output;
  EXPECT_NE(points.output.find("2000000 points need about"), std::string::npos) << points.output;
}

// SIGINT (Ctrl-C) and SIGTERM mid-run: exit 130, nothing written, no temporary file.
TEST_F(BadInput, InterruptedRunsWriteNothing) {
  for (int signal_number : {SIGINT, SIGTERM}) {
    const std::string out = path("interrupted.ply");
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      execl(LSRECON_CLI, LSRECON_CLI, "--demo", "torus", "--points", "200000", "--quiet", out.c_str(), nullptr);
      _exit(127);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(1500));
    kill(child, signal_number);
    int status = 0;
    waitpid(child, &status, 0);
    ASSERT_TRUE(WIFEXITED(status)) << signal_number;
    EXPECT_EQ(WEXITSTATUS(status), 130) << signal_number;
    EXPECT_FALSE(fs::exists(out)) << signal_number;
    expect_no_temporary_file();
  }
}

// Each hint of a run that stops short names the cause it measured.
TEST_F(BadInput, NotConvergedHintsNameTheMeasuredCause) {
  CliRun r = run("--demo sphere --points 3000 --max-iterations 2 --quiet " + path("a.ply"));
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("still improving at the last step: raise --max-iterations"), std::string::npos) << r.output;
  // Gaussian noise of 3% of the radius on 5,000 points (spacing about 5%).
  std::ofstream noisy(path("noisy.xyz"));
  std::mt19937 rng(5);
  std::normal_distribution<double> gauss(0.0, 1.0);
  for (const auto& p : lsr::Sphere{lsr::Vec<3>(0, 0, 0), 1.0}.sample(5000)) {
    const lsr::Vec<3> q = p * (1.0 + 0.03 * gauss(rng));
    noisy << q.x() << ' ' << q.y() << ' ' << q.z() << '\n';
  }
  noisy.close();
  r = run(path("noisy.xyz") + " " + path("b.ply") + " --quiet");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("noisy or fill a volume"), std::string::npos) << r.output;
  // A tight cluster deep inside a sphere: never reached.
  std::ofstream cluster(path("cluster.xyz"));
  for (const auto& p : lsr::Sphere{lsr::Vec<3>(0, 0, 0), 1.0}.sample(3000)) cluster << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  for (int i = 0; i < 50; ++i) cluster << 1e-3 * (i % 5) << ' ' << 1e-3 * (i / 5 % 5) << ' ' << 1e-3 * (i / 25) << '\n';
  cluster.close();
  r = run(path("cluster.xyz") + " " + path("c.ply") + " --quiet");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("point(s) stay beyond the tolerance"), std::string::npos) << r.output;
  // Planar input to a mesh: curves, not a circular hint to --dim 3.
  std::ofstream flat(path("flat.xyz"));
  for (const auto& p : lsr::Circle{lsr::Vec<2>(0, 0), 1.0}.sample(500)) flat << p.x() << ' ' << p.y() << " 0\n";
  flat.close();
  r = run(path("flat.xyz") + " " + path("d.ply") + " --quiet");
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("write .svg or .txt"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("--dim 3"), std::string::npos) << r.output;
  r = run(path("flat.xyz") + " " + path("d.ply") + " --quiet --dim 3");
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("an .svg or .txt output"), std::string::npos) << r.output;
}

// Rows whose answer is a documented result rather than an error (docs/bad-input.md).
TEST_F(BadInput, DegenerateButReadableInputsGiveTheDocumentedResult) {
  // Denormal coordinates: coincide at double precision once mapped to the unit box.
  std::ofstream(path("denormal.xyz")) << "1e-320 0 0\n0 1e-320 0\n0 0 1e-320\n0 0 0\n2e-320 2e-320 2e-320\n";
  expect_refused(path("denormal.xyz"), "coincide");
  // Images: all white has no point; all black is one block, whose outline is one closed curve.
  for (const auto& [name, value] : {std::pair<std::string, int>{"white.pgm", 255}, {"black.pgm", 0}}) {
    std::ofstream pgm(path(name), std::ios::binary);
    pgm << "P5\n48 48\n255\n" << std::string(48 * 48, char(value));
  }
  expect_refused(path("white.pgm"), "no dark pixel");
  CliRun r = run(path("black.pgm") + " " + path("black.txt") + " --quiet");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(read("black.txt").find("1 loops"), std::string::npos) << read("black.txt").substr(0, 200);
  // Uniform random points in a cube are no surface: a closed result in seconds, reported as not
  // converged, never a hang.
  std::ofstream cube(path("cube.xyz"));
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < 3000; ++i) cube << unit(rng) << ' ' << unit(rng) << ' ' << unit(rng) << '\n';
  cube.close();
  r = run(path("cube.xyz") + " " + path("cube.ply") + " --quiet");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("NOT converged"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("noisy or fill a volume"), std::string::npos) << r.output;
}

}  // namespace
