// The health check of MPM (mpm/solver/health_check.h) and its time-step collapse rule: a planted
// NaN, a negative mass or volume and a collapsed step each stop the run with a message naming the
// quantity, the material, the particle, its position and the time; a healthy state passes.
#include <gtest/gtest.h>

#include <limits>
#include <sstream>
#include <string>

#include "core/health/health.h"
#include "core/parallel/comm.h"
#include "mpm/solver/health_check.h"
#include "mpm_problems.h"
#include "serial_mpi.h"

using namespace mpmice;
using namespace mpmice::mpm;
namespace pr = mpmice::mpm::problems;

namespace {
core::Comm self() { return core::Comm(MPI_COMM_SELF); }

core::Scene blockScene() {
  core::Scene s = pr::smallBlock();
  s.name = "block";
  s.time.end = 1.0;
  return s;
}

std::string healthMessage(const MpmSolver& s) {
  try {
    checkHealth(s);
  } catch (const core::HealthError& e) {
    return e.what();
  }
  return "";
}

// "particle <id>, x = (<x>, <y>) m" of particle i.
std::string where(const MpmSolver& s, std::size_t i) {
  const auto& p = s.particles();
  const double x[3] = {p.x[0][i], p.x[1][i], p.x[2][i]};
  return "particle " + std::to_string(p.id[i]) + ", x = " + core::formatPoint(x, 2) + " m";
}

void expectNames(const std::string& msg, const std::vector<std::string>& parts) {
  for (const auto& p : parts) EXPECT_NE(msg.find(p), std::string::npos) << "'" << p << "' not in: " << msg;
}
}  // namespace

TEST(MpmHealthCheck, AHealthyRunPassesEveryStep) {
  MpmSolver s(blockScene(), self());
  for (int n = 0; n < 10; ++n) {
    s.advance();
    EXPECT_EQ(healthMessage(s), "") << "step " << n + 1;
  }
}

TEST(MpmHealthCheck, APlantedNanVelocityIsNamedWithMaterialParticlePositionAndTime) {
  MpmSolver s(blockScene(), self());
  s.advance();
  s.advance();
  const std::size_t i = 5;
  s.particles().v[1][i] = std::numeric_limits<double>::quiet_NaN();
  std::ostringstream t;
  t.precision(6);
  t << "t = " << s.time() << " s (step 2)";
  expectNames(healthMessage(s), {"mpm: non-physical state: velocity [m/s] of solid 'block' = nan", where(s, i),
                                 t.str()});
}

TEST(MpmHealthCheck, ANegativeMassIsNamed) {
  MpmSolver s(blockScene(), self());
  s.advance();
  s.particles().mass[3] = -1.0;
  expectNames(healthMessage(s), {"mass [kg] of solid 'block' = -1", "expected finite, > 0", where(s, 3), "t = "});
}

TEST(MpmHealthCheck, AZeroVolumeIsNamed) {
  MpmSolver s(blockScene(), self());
  s.advance();
  s.particles().vol[7] = 0.0;
  expectNames(healthMessage(s), {"volume [m^3] of solid 'block' = 0", where(s, 7)});
}

TEST(MpmHealthCheck, ACollapsedTimeStepStopsTheRunNamingTheParticleAndTheLimit) {
  MpmSolver s(blockScene(), self());
  s.advance();  // the first stable step is the reference
  s.particles().v[0][4] = 1e12;  // the CFL step falls ~1e10-fold
  std::string msg;
  try {
    s.advance();
  } catch (const core::HealthError& e) {
    msg = e.what();
  }
  const auto& p = s.particles();
  const double x[3] = {p.x[0][4], p.x[1][4], p.x[2][4]};
  expectNames(msg, {"time step collapsed", "(step 2)", "below time.dt_collapse_fraction = 1e-06",
                    "the MPM CFL bound", "particle " + std::to_string(p.id[4]) + " of solid 'block'",
                    "x = " + core::formatPoint(x, 2) + " m", "|v| = 1e+12 m/s"});
}
