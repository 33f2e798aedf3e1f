// SPDX-License-Identifier: BSD-3-Clause
/// @file lsrecon_outputs_test.cpp
/// @brief Outputs are a transaction: all are written, or none is touched; temporaries never
/// follow a planted link nor replace a user's file; colliding or impossible names are refused
/// before the run.
#include "cli_fixture.h"

#include <gtest/gtest.h>

#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <string>
#include <thread>

namespace {

using lsr_test::Cli;
using lsr_test::CliRun;
using lsr_test::expect_closed_mesh;
namespace fs = std::filesystem;

class Outputs : public Cli {
 protected:
  void expect_no_temporary_file() const {
    for (const auto& entry : fs::directory_iterator(dir_)) {
      EXPECT_EQ(entry.path().filename().string().find(".partial-"), std::string::npos) << entry.path();
    }
  }
  void keep(const std::string& name) const { std::ofstream(path(name)) << "precious"; }
};

// A file size limit (as a full disk would): the surface fits, the volume mesh does not. The
// run fails, and the surface already written to its temporary never replaces the old one.
TEST_F(Outputs, AFailedSecondOutputLeavesTheFirstUntouched) {
  keep("t.ply");
  const std::string command = "ulimit -f 2048; " + std::string(LSRECON_CLI) + " --demo torus --points 3000 --quiet " + path("t.ply") +
                              " --volume-mesh " + path("t.vtu") + " --report " + path("t.json") + " > " + path("log.txt") + " 2>&1";
  const int raw = std::system(("bash -c '" + command + "'").c_str());
  ASSERT_TRUE(WIFEXITED(raw));
  EXPECT_EQ(WEXITSTATUS(raw), 1) << read("log.txt");
  EXPECT_NE(read("log.txt").find("writing " + path("t.vtu") + " failed"), std::string::npos) << read("log.txt");
  EXPECT_EQ(read("t.ply"), "precious");
  EXPECT_FALSE(fs::exists(path("t.vtu")));
  EXPECT_FALSE(fs::exists(path("t.json")));
  expect_no_temporary_file();
}

// SIGINT, SIGTERM and SIGHUP during --levels: exit 130, no level written, earlier files kept.
TEST_F(Outputs, AnInterruptedLevelsRunWritesNoLevel) {
  for (int signal_number : {SIGINT, SIGHUP}) {
    keep("l.l0.ply");
    const std::string out = path("l.ply");
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      execl(LSRECON_CLI, LSRECON_CLI, "--demo", "torus", "--points", "100000", "--levels", "3", "--quiet", out.c_str(), nullptr);
      _exit(127);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2500));
    kill(child, signal_number);
    int status = 0;
    waitpid(child, &status, 0);
    ASSERT_TRUE(WIFEXITED(status)) << signal_number;
    EXPECT_EQ(WEXITSTATUS(status), 130) << signal_number;
    EXPECT_EQ(read("l.l0.ply"), "precious") << signal_number;
    EXPECT_FALSE(fs::exists(path("l.l1.ply"))) << signal_number;
    EXPECT_FALSE(fs::exists(path("l.l2.ply"))) << signal_number;
    expect_no_temporary_file();
  }
}

TEST_F(Outputs, TemporariesNeitherFollowPlantedLinksNorReplaceAUsersFiles) {
  keep("victim.txt");
  // The names earlier versions wrote to, planted as links to the victim, and a user's own file.
  fs::create_symlink(path("victim.txt"), path("o.partial.ply"));
  fs::create_symlink(path("victim.txt"), path("o.partial-aaaaaa.ply"));
  std::ofstream(path("mine.partial.ply")) << "mine";
  ASSERT_EQ(run("--demo sphere --points 2000 --quiet " + path("o.ply")).status, 0);
  expect_closed_mesh(path("o.ply"));
  EXPECT_EQ(read("victim.txt"), "precious");
  EXPECT_EQ(read("mine.partial.ply"), "mine");
  EXPECT_TRUE(fs::is_symlink(path("o.partial.ply")));
}

TEST_F(Outputs, AnOutputThatIsALinkStaysALinkAndItsFileKeepsItsMode) {
  fs::create_directories(path("real"));
  keep("real/mesh.ply");
  ASSERT_EQ(::chmod(path("real/mesh.ply").c_str(), 0600), 0);
  fs::create_symlink(path("real/mesh.ply"), path("link.ply"));
  ASSERT_EQ(run("--demo sphere --points 2000 --quiet " + path("link.ply")).status, 0);
  EXPECT_TRUE(fs::is_symlink(path("link.ply")));
  expect_closed_mesh(path("real/mesh.ply"));
  struct stat s {};
  ASSERT_EQ(::stat(path("real/mesh.ply").c_str(), &s), 0);
  EXPECT_EQ(s.st_mode & 07777, 0600u);
}

TEST_F(Outputs, CollidingOrOverlongNamesAreRefusedBeforeTheRun) {
  keep("b.ply");
  for (const std::string& options : {" --report " + path("b.ply"), " --save-points " + path("./b.ply"),
                                    " --volume-mesh " + path("b.vtu") + " --report " + path("b.vtu")}) {
    const CliRun r = run("--demo sphere --points 2000 " + path("b.ply") + options);
    EXPECT_EQ(r.status, 1) << options << ": " << r.output;
    EXPECT_NE(r.output.find("is named for two outputs"), std::string::npos) << options << ": " << r.output;
    EXPECT_EQ(r.output.find("[read"), std::string::npos) << "refused only after reading: " << r.output;
    EXPECT_EQ(read("b.ply"), "precious");
  }
  // --levels' own files collide too.
  CliRun r = run("--demo sphere --points 2000 --levels 2 " + path("c.ply") + " --report " + path("c.l1.ply"));
  EXPECT_NE(r.output.find("is named for two outputs"), std::string::npos) << r.output;
  // A name the file system cannot hold fails before the run, not after it.
  r = run("--demo sphere --points 2000 " + path(std::string(300, 'n') + ".ply"));
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("longer than the file system allows"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("[read"), std::string::npos) << r.output;
  // 250 bytes fit, and so must the temporary beside it.
  const std::string longest = std::string(246, 'n') + ".ply";
  r = run("--demo sphere --points 2000 --quiet " + path(longest));
  EXPECT_EQ(r.status, 0) << r.output;
  expect_closed_mesh(path(longest));
  expect_no_temporary_file();
}

}  // namespace
