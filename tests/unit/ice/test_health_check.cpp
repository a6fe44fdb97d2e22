// The health check of ICE (ice/solver/health_check.h) and its time-step collapse rule: a planted
// NaN, a negative mass, volume fractions that do not sum to 1 and a collapsed step each stop the
// run on every rank with a message naming the quantity, the material, the cell, its centre and
// the time; a healthy state passes. Runs on 1 and 2 ranks (the rank that does not hold the cell
// throws the same message).
#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "../../verification/ice/ice_test_scenes.h"
#include "core/health/health.h"
#include "ice/solver/health_check.h"
#include "test_comm.h"

using namespace mpmice;

namespace {
// 20 cells of gas on [0, 1] with a pressure jump; cell 13 (centre x = 0.675) is where we plant.
core::Scene tube() { return test::shockTube(20, {1, 0, 1e5}, {0.125, 0, 1e4}, 0.5, 1.0); }
constexpr int kCell = 13;

bool owns(const ice::IceSolver& s, int i) { return i >= s.ownedBox().lo[0] && i <= s.ownedBox().hi[0]; }

// The message every rank gets from checkHealth ("" when it passes).
std::string healthMessage(const ice::IceSolver& s) {
  try {
    ice::checkHealth(s);
  } catch (const core::HealthError& e) {
    return e.what();
  }
  return "";
}

void expectNames(const std::string& msg, const std::vector<std::string>& parts) {
  for (const auto& p : parts) EXPECT_NE(msg.find(p), std::string::npos) << "'" << p << "' not in: " << msg;
}
}  // namespace

TEST(IceHealthCheck, AHealthyRunPassesEveryStep) {
  ice::IceSolver s(tube(), test::comm());
  for (int n = 0; n < 20; ++n) {
    s.step();
    EXPECT_EQ(healthMessage(s), "") << "step " << n + 1;
  }
}

TEST(IceHealthCheck, APlantedNanVelocityIsNamedWithMaterialCellPositionAndTime) {
  ice::IceSolver s(tube(), test::comm());
  s.step();
  s.step();
  if (owns(s, kCell)) s.state().mat[0].vel(kCell, 0, 0, 0) = std::numeric_limits<double>::quiet_NaN();
  std::ostringstream t;
  t.precision(6);
  t << "t = " << s.time() << " s (step 2)";
  expectNames(healthMessage(s), {"non-physical state", "velocity component 0", "fluid 'gas'", "= nan",
                                 "cell (13,0,0)", "x = (0.675) m", t.str()});
}

TEST(IceHealthCheck, ANegativeMassIsNamed) {
  ice::IceSolver s(tube(), test::comm());
  s.step();
  if (owns(s, kCell)) s.state().mat[0].mass(kCell, 0, 0) = -1e-3;
  expectNames(healthMessage(s), {"mass [kg] of fluid 'gas' = -0.001", "expected finite, >= 0", "cell (13,0,0)",
                                 "x = (0.675) m", "t = "});
}

TEST(IceHealthCheck, VolumeFractionsNotSummingToOneAreNamed) {
  ice::IceSolver s(tube(), test::comm());
  s.step();
  if (owns(s, kCell)) s.state().mat[0].theta(kCell, 0, 0) = 0.9;
  expectNames(healthMessage(s), {"sum of the volume fractions of all materials = 0.9", "1 within 1e-06",
                                 "cell (13,0,0)", "x = (0.675) m", "t = "});
}

TEST(IceHealthCheck, ATemperatureOutOfRangeIsNamed) {
  ice::IceSolver s(tube(), test::comm());
  s.step();
  if (owns(s, kCell)) s.state().mat[0].eint(kCell, 0, 0) = -1.0;
  expectNames(healthMessage(s), {"temperature [K] of fluid 'gas'", "expected in (0, 1e9]", "cell (13,0,0)"});
}

TEST(IceHealthCheck, ACollapsedTimeStepStopsTheRunNamingTheCellAndTheLimit) {
  core::Scene sc = tube();
  ice::IceSolver s(sc, test::comm());
  s.step();  // the first stable step is the reference
  // A cell moving at 1e12 m/s: the CFL step falls ~1e9-fold, below 1e-6 of the first one.
  if (owns(s, kCell)) s.state().mat[0].vel(kCell, 0, 0, 0) = 1e12;
  std::string msg;
  try {
    s.step();
  } catch (const core::HealthError& e) {
    msg = e.what();
  }
  expectNames(msg, {"time step collapsed", "(step 2)", "below time.dt_collapse_fraction = 1e-06",
                    "the ICE CFL bound (convective + acoustic)", "in cell (13,0,0)", "x = (0.675) m", "'gas'"});
}

TEST(IceHealthCheck, ACollapseFractionOfZeroLetsTheRunGoOn) {
  core::Scene sc = tube();
  sc.time.dt_collapse_fraction = 0;
  ice::IceSolver s(sc, test::comm());
  s.step();
  if (owns(s, kCell)) s.state().mat[0].vel(kCell, 0, 0, 0) = 1e12;
  s.computeEquilibriumPressure();
  EXPECT_LT(s.stableTimeStep(), 1e-6 * s.dt());
  EXPECT_NO_THROW(s.step());
}
