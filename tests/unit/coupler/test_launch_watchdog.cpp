// The launch watchdog (src/coupler/launch/launch_watchdog.h): after the join, no progress for
// twice coupling.timeout ends the process naming the program and the step; progress keeps it
// quiet; the end of the run is bounded too. Death tests: each case runs in a child process.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <thread>

#include "coupler/launch/launch_watchdog.h"

using namespace mpmice::coupler;

namespace {
void sleepFor(double s) { std::this_thread::sleep_for(std::chrono::duration<double>(s)); }
}  // namespace

TEST(LaunchWatchdog, NoProgressAfterTheJoinEndsTheProcessNamingTheProgramAndTheStep) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
      {
        LaunchWatchdog::start("ice_solver", 0.2);
        LaunchWatchdog::joined();
        LaunchWatchdog::step(7);
        sleepFor(30);  // a main thread that never comes back
        std::exit(0);
      },
      testing::ExitedWithCode(1),
      "ice_solver: error: no progress for 0.4 s \\(twice coupling.timeout\\) after step 7: ice_solver hangs");
}

TEST(LaunchWatchdog, ProgressKeepsItQuietAndStopEndsIt) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
      {
        LaunchWatchdog::start("mpm_solver", 0.2);
        LaunchWatchdog::joined();
        for (int i = 0; i < 20; ++i) {  // 1 s of steps, each well inside the bound
          sleepFor(0.05);
          LaunchWatchdog::step(i);
        }
        LaunchWatchdog::stop();
        sleepFor(1);
        std::exit(3);
      },
      testing::ExitedWithCode(3), "");
}

TEST(LaunchWatchdog, TheEndOfTheRunIsBounded) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
      {
        LaunchWatchdog::start("mpm_solver", 0.2);
        LaunchWatchdog::joined();
        LaunchWatchdog::ending();
        sleepFor(30);  // MPI_Finalize waiting for a process that stopped
        std::exit(0);
      },
      testing::ExitedWithCode(1), "mpm_solver: error: the end of the run \\(MPI_Finalize");
}

TEST(LaunchWatchdog, TheStartIsBoundedByTheTimeout) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
      {
        LaunchWatchdog::start("mpm_solver", 0.2);
        sleepFor(30);  // the join never completes
        std::exit(0);
      },
      testing::ExitedWithCode(1), "mpm_solver: error: the launch did not start within 0.2 s \\(coupling.timeout\\)");
}
