// The output-directory lock (core/io/run_lock.h): a second run of a scene into one directory is
// refused naming the holder, a stale lock of a dead process is taken over with a note, the lock
// goes at a normal end, and conflicting names accept an ancestor's lock only.
#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

#include "core/io/run_lock.h"
#include "core/io/text_file.h"

using namespace mpmice::core;
namespace fs = std::filesystem;

namespace {

/// A fresh directory per test (gtest_discover_tests runs them at once).
fs::path scratch(const std::string& name) {
  const fs::path p = fs::path(MPMICE_IO_TEST_DIR) / name;
  fs::remove_all(p);
  return p;
}

std::string host() {
  char buf[256] = {};
  gethostname(buf, sizeof buf - 1);
  return buf;
}

/// The pid of a process that has ended (and been reaped).
pid_t deadPid() {
  const pid_t pid = fork();
  if (pid == 0) _exit(0);
  waitpid(pid, nullptr, 0);
  return pid;
}

}  // namespace

TEST(RunLock, ASecondRunOfTheSceneIsRefusedNamingTheHolder) {
  const fs::path dir = scratch("second_run");
  const RunLock first(dir.string(), "scene", "mpmice");
  EXPECT_EQ(readTextFile(dir / "scene.lock"), std::to_string(getpid()) + " " + host() + " mpmice\n");
  try {
    const RunLock second(dir.string(), "scene", "mpmice");
    FAIL() << "expected the second lock to be refused";
  } catch (const RunLockHeld& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("the output directory is in use: " + (dir / "scene.lock").string()), std::string::npos) << msg;
    EXPECT_NE(msg.find("held by pid " + std::to_string(getpid()) + " on host " + host() + " (mpmice)"),
              std::string::npos)
        << msg;
  }
  // Another name in the same directory is another run.
  const RunLock other(dir.string(), "scene.mpm_solver", "mpm_solver");
}

TEST(RunLock, IsReleasedAtANormalEnd) {
  const fs::path dir = scratch("released");
  { const RunLock lock(dir.string(), "scene", "mpmice"); }
  EXPECT_FALSE(fs::exists(dir / "scene.lock"));
  const RunLock again(dir.string(), "scene", "mpmice");
  EXPECT_TRUE(fs::exists(dir / "scene.lock"));
}

TEST(RunLock, AStaleLockOfADeadProcessIsTakenOverWithANote) {
  const fs::path dir = scratch("stale");
  fs::create_directories(dir);
  const pid_t dead = deadPid();
  std::ofstream(dir / "scene.lock") << dead << " " << host() << " mpmice\n";
  std::ostringstream log;
  const RunLock lock(dir.string(), "scene", "mpmice", {}, &log);
  EXPECT_NE(log.str().find("note: taking over the stale lock " + (dir / "scene.lock").string() + " of pid " +
                           std::to_string(dead) + " on host " + host() + " (mpmice), which is no longer running"),
            std::string::npos)
      << log.str();
  EXPECT_EQ(readTextFile(dir / "scene.lock"), std::to_string(getpid()) + " " + host() + " mpmice\n");
}

TEST(RunLock, AConflictingLockIsAcceptedFromAnAncestorOnly) {
  const fs::path dir = scratch("conflicts");
  fs::create_directories(dir);
  // The parent (the coupler of an MPMD launch) holds <scene>: its participant goes ahead.
  std::ofstream(dir / "scene.lock") << getppid() << " " << host() << " coupler\n";
  { const RunLock participant(dir.string(), "scene.mpm_solver", "mpm_solver", {"scene"}); }
  // A live process that is not an ancestor (a child here) holds <scene>: refused, naming it.
  const pid_t child = fork();
  if (child == 0) {
    pause();
    _exit(0);
  }
  std::ofstream(dir / "scene.lock") << child << " " << host() << " mpmice\n";
  try {
    const RunLock participant(dir.string(), "scene.mpm_solver", "mpm_solver", {"scene"});
    ADD_FAILURE() << "expected a refusal";
  } catch (const RunLockHeld& e) {
    EXPECT_NE(std::string(e.what()).find("held by pid " + std::to_string(child) + " on host " + host() + " (mpmice)"),
              std::string::npos)
        << e.what();
  }
  kill(child, SIGKILL);
  waitpid(child, nullptr, 0);
  // Dead now: no conflict.
  const RunLock participant(dir.string(), "scene.mpm_solver", "mpm_solver", {"scene"});
}

TEST(RunLock, CouplerAndMpmiceLockTheSceneEachParticipantItsProgram) {
  const fs::path dir = scratch("acquire");
  Scene scene;
  scene.name = "tiny";
  scene.output.directory = dir.string();
  {
    const auto mono = lockOutputDirectory(Comm(), scene, "mpmice", nullptr);
    ASSERT_TRUE(mono);
    EXPECT_EQ(mono->path(), (dir / "tiny.lock").string());
  }
  const auto solid = lockOutputDirectory(Comm(), scene, "mpm_solver", nullptr);
  const auto fluid = lockOutputDirectory(Comm(), scene, "ice_solver", nullptr);  // one launch: both go
  EXPECT_EQ(solid->path(), (dir / "tiny.mpm_solver.lock").string());
  EXPECT_EQ(fluid->path(), (dir / "tiny.ice_solver.lock").string());
  scene.output.enabled = false;
  EXPECT_EQ(lockOutputDirectory(Comm(), scene, "coupler", nullptr), nullptr);
}
