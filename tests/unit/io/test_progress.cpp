// Progress: line text, ETA arithmetic and when lines are printed, all with an injected clock.
#include <gtest/gtest.h>

#include <sstream>

#include "core/util/progress.h"

using namespace mpmice::core;

TEST(Progress, LineMatchesTheDocumentedFormat) {
  EXPECT_EQ(Progress::formatLine(1200, 1.2e-3, 0.0, 4.0e-3, 1.0e-6, 12.3),
            "step 1200  t = 1.200e-03 / 4.000e-03 s (30.0%)  dt = 1.0e-06  wall 12.3 s  ETA 28.7 s");
  EXPECT_EQ(Progress::formatLine(5, 0.5, 0.0, 1.0, 0.1, 2.0, {{"iters", 3}, {"res", 1.5e-7}}),
            "step 5  t = 5.000e-01 / 1.000e+00 s (50.0%)  dt = 1.0e-01  wall 2.0 s  ETA 2.0 s  iters=3  res=1.5e-07");
  // A coupled run ends its line with what set the step (couplings/volume/run/volume_run.cpp).
  EXPECT_EQ(Progress::formatLine(5, 0.5, 0.0, 1.0, 0.1, 2.0, {{"iters", 1}}, 0, 0, "dt_by=solid"),
            "step 5  t = 5.000e-01 / 1.000e+00 s (50.0%)  dt = 1.0e-01  wall 2.0 s  ETA 2.0 s  iters=1  dt_by=solid");
}

TEST(Progress, EtaIsElapsedTimesRemainingOverDone) {
  EXPECT_DOUBLE_EQ(Progress::eta(0.3, 0.0, 1.0, 6.0), 14.0);
  EXPECT_DOUBLE_EQ(Progress::eta(1.5, 1.0, 3.0, 10.0), 30.0);  // t_start = 1: 0.5 done, 1.5 to go
  EXPECT_DOUBLE_EQ(Progress::eta(3.0, 1.0, 3.0, 10.0), 0.0);
  EXPECT_LT(Progress::eta(1.0, 1.0, 3.0, 10.0), 0.0);  // nothing done yet: unknown
  EXPECT_NE(Progress::formatLine(0, 1.0, 1.0, 3.0, 0.1, 0.0).find("ETA --"), std::string::npos);
}

TEST(Progress, MaxStepsSetsTheFractionWhenItEndsTheRunFirst) {
  // time.end far away, time.max_steps = 100: 25 steps done is 25 %, not 0.0 %, and the ETA is 3x the wall.
  EXPECT_DOUBLE_EQ(Progress::fractionDone(1.0e-3, 0.0, 1.0e3, 25, 100), 0.25);
  EXPECT_EQ(Progress::formatLine(25, 1.0e-3, 0.0, 1.0e3, 4.0e-5, 2.0, {}, 100),
            "step 25  t = 1.000e-03 / 1.000e+03 s (25.0%)  dt = 4.0e-05  wall 2.0 s  ETA 6.0 s");
  // A restart from step 50 of 100: 75 is half of what this run does.
  EXPECT_DOUBLE_EQ(Progress::fractionDone(2.0, 1.0, 1.0e3, 75, 100, 50), 0.5);
  // The time ends the run first: the steps do not lower the fraction.
  EXPECT_DOUBLE_EQ(Progress::fractionDone(0.5, 0.0, 1.0, 2, 1000), 0.5);
  std::ostringstream os;
  const Comm serial;
  double now = 0.0;
  Progress p(os, serial, 0.0, 1.0e3, {.everySeconds = 0, .everySteps = 10, .maxSteps = 40}, [&] { return now; });
  p.start("long", "1D, 10 cells", 1);
  os.str("");
  now = 1.0;
  EXPECT_TRUE(p.step(10, 1.0e-3, 1.0e-4));
  EXPECT_EQ(os.str(), "step 10  t = 1.000e-03 / 1.000e+03 s (25.0%)  dt = 1.0e-04  wall 1.0 s  ETA 3.0 s\n");
}

TEST(Progress, PrintsEveryKStepsOrEveryNSecondsWithInjectedClock) {
  double now = 100.0;
  std::ostringstream os;
  const Comm serial;
  Progress p(os, serial, 0.0, 1.0, {.everySeconds = 5.0, .everySteps = 10}, [&] { return now; });
  p.start("dam_break", "2D, 8 x 4 cells", 2);
  EXPECT_EQ(os.str(), "scene dam_break: 2D, 8 x 4 cells, 2 ranks, t = 0.000e+00 .. 1.000e+00 s\n");
  os.str("");
  now = 101.0;
  EXPECT_FALSE(p.step(1, 0.01, 0.01));  // neither criterion
  now = 102.0;
  EXPECT_TRUE(p.step(10, 0.1, 0.01));  // every 10 steps
  EXPECT_EQ(os.str(), "step 10  t = 1.000e-01 / 1.000e+00 s (10.0%)  dt = 1.0e-02  wall 2.0 s  ETA 18.0 s\n");
  now = 106.9;
  EXPECT_FALSE(p.step(11, 0.11, 0.01));  // 4.9 s since the last line
  now = 107.0;
  EXPECT_TRUE(p.step(12, 0.25, 0.01, {{"iters", 4}}));  // 5 s since the last line
  EXPECT_NE(os.str().find("step 12  t = 2.500e-01 / 1.000e+00 s (25.0%)  dt = 1.0e-02  wall 7.0 s  ETA 21.0 s  iters=4\n"),
            std::string::npos)
      << os.str();
  EXPECT_TRUE(p.step(13, 0.26, 0.01, {}, true));  // forced
  os.str("");
  now = 120.0;
  p.finish(100, 1.0, 32.0);
  EXPECT_EQ(os.str(), "done: 100 steps, t = 1.000e+00 s, wall 20.0 s, 5 steps/s, 1.600e+02 cell-steps/s\n");
  EXPECT_DOUBLE_EQ(p.elapsed(), 20.0);
}

TEST(Progress, BothIntervalsOffMeansEveryStep) {
  double now = 0.0;
  std::ostringstream os;
  Progress p(os, Comm(), 0.0, 1.0, {.everySeconds = 0, .everySteps = 0}, [&] { return now; });
  EXPECT_TRUE(p.step(1, 0.1, 0.1));
  EXPECT_TRUE(p.step(2, 0.2, 0.1));
}
