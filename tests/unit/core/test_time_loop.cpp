// The clock of every program (src/core/time/time_loop.h): when a run has reached its end, how
// the last step lands on it, and when output is due, for ordinary, tiny and absent intervals.
#include <gtest/gtest.h>

#include <chrono>
#include <limits>
#include <vector>

#include "core/time/time_loop.h"

namespace mpmice::core {
namespace {

TEST(TimeLoop, AClockWithinRoundOffOfTheEndHasReachedIt) {
  double t = 0;
  for (int i = 0; i < 10; ++i) t += 0.1;  // 0.9999999999999999
  EXPECT_TRUE(reached(t, 1.0));
  EXPECT_FALSE(reached(0.999, 1.0));
  EXPECT_TRUE(goesOn(0.5, 3, 1.0, 0));
  EXPECT_FALSE(goesOn(0.5, 3, 1.0, 3));  // max_steps
  EXPECT_FALSE(goesOn(t, 3, 1.0, 0));
  EXPECT_DOUBLE_EQ(landOn(0.9, 0.25, 1.0), 0.1);
  EXPECT_DOUBLE_EQ(landOn(0.5, 0.25, 1.0), 0.25);
}

std::vector<double> written(double interval, double end, double dt, long maxSteps) {
  OutputSchedule out(interval, end);
  std::vector<double> at;
  double t = 0;
  long n = 0;
  if (out.due(t)) at.push_back(t);
  while (goesOn(t, n, end, maxSteps)) {
    t += landOn(t, dt, end);
    ++n;
    if (out.due(t)) at.push_back(t);
  }
  if (!out.written(t) && out.due(t, true)) at.push_back(t);
  return at;
}

TEST(OutputSchedule, EveryIntervalAndTheEnd) {
  const auto at = written(0.25, 1.0, 0.1, 0);
  // 0, then the first step at or past 0.25, 0.5, 0.75, and the end.
  ASSERT_EQ(at.size(), 5u);
  EXPECT_NEAR(at[1], 0.3, 1e-12);
  EXPECT_NEAR(at[2], 0.5, 1e-12);
  EXPECT_NEAR(at[3], 0.8, 1e-12);
  EXPECT_NEAR(at[4], 1.0, 1e-12);
}

TEST(OutputSchedule, NoIntervalWritesTheStartAndTheEnd) {
  const auto at = written(0.0, 1.0, 0.3, 0);
  ASSERT_EQ(at.size(), 2u);
  EXPECT_NEAR(at[1], 1.0, 1e-12);
}

TEST(OutputSchedule, AnIntervalFarBelowTheStepWritesEveryStepAndEnds) {
  const auto start = std::chrono::steady_clock::now();
  const auto at = written(1e-20, 1.0, 0.1, 0);
  EXPECT_EQ(at.size(), 11u);  // t = 0 and every one of the ten steps
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
}

TEST(OutputSchedule, ASolverLandsOnOutputTimesUnlessTheyAreDenserThanItsSteps) {
  OutputSchedule out(0.25, 1.0);
  (void)out.due(0.0);
  EXPECT_DOUBLE_EQ(out.landingTarget(0.0, 0.1), 0.25);
  EXPECT_DOUBLE_EQ(out.landingTarget(0.0, 0.5), 1.0);  // interval below the step: never shortened
  OutputSchedule tiny(1e-20, 1.0);
  (void)tiny.due(0.0);
  EXPECT_DOUBLE_EQ(tiny.landingTarget(0.0, 1e-6), 1.0);
}

TEST(OutputSchedule, AHugeEndWithMaxStepsStopsAtMaxStepsAndWritesTheLastStep) {
  const auto at = written(0.0, 1e300, 1e-3, 4);
  ASSERT_EQ(at.size(), 2u);  // the start and the last step taken
  EXPECT_NEAR(at[1], 4e-3, 1e-15);
}

// What set a coupled step (the progress line's dt_by=): the end time, time.dt_max, a side run here,
// or, when the stable step is neither of this program's, the peer's side.
TEST(TimeLoop, StepSetByNamesTheBoundThatSetTheStep) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  EXPECT_STREQ(stepSetBy(0.5e-6, 1e-6, inf, 1e-6, 2e-6, true), "time.end");
  EXPECT_STREQ(stepSetBy(1e-6, 1e-6, 1e-6, 3e-6, 2e-6, true), "time.dt_max");
  EXPECT_STREQ(stepSetBy(1e-6, 1e-6, inf, 1e-6, 2e-6, true), "solid");   // mpmice, solid's step
  EXPECT_STREQ(stepSetBy(2e-6, 2e-6, inf, 3e-6, 2e-6, true), "fluid");   // mpmice, fluid's step
  EXPECT_STREQ(stepSetBy(2e-6, 2e-6, inf, 3e-6, inf, true), "fluid");    // MPMD solid: the peer's
  EXPECT_STREQ(stepSetBy(2e-6, 2e-6, inf, inf, 3e-6, false), "solid");   // MPMD fluid: the peer's
  EXPECT_STREQ(stepSetBy(3e-6, 3e-6, inf, inf, 3e-6, false), "fluid");   // MPMD fluid: its own
}

}  // namespace
}  // namespace mpmice::core
