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

TEST(MpmHealthCheck, ANegativeVolumeIsNamedWithItsJacobian) {
  MpmSolver s(blockScene(), self());
  s.advance();
  auto& p = s.particles();
  p.vol[6] = -0.5 * p.vol0[6];
  expectNames(healthMessage(s), {"volume [m^3] of solid 'block' = ", "J = det F = V / V0 = -0.5", where(s, 6)});
}

TEST(MpmHealthCheck, ANonFiniteStressWorkIsNamed) {
  MpmSolver s(blockScene(), self());
  s.advance();
  s.particles().work[2] = std::numeric_limits<double>::infinity();
  expectNames(healthMessage(s), {"stress work [J] of solid 'block' = inf", "expected finite", where(s, 2)});
}

TEST(MpmHealthCheck, ATemperatureAtZeroKelvinIsNamed) {
  MpmSolver s(blockScene(), self());
  s.advance();
  s.particles().temperature[4] = -0.1;
  expectNames(healthMessage(s), {"temperature [K] of solid 'block' = -0.1", "expected in (0, 1e9]", where(s, 4)});
}

// The stored stress work of a material may go below 0 by the time integration's error, at most
// by its kinetic energy and the elastic energy of a 1 % strain; beyond, the run stops naming the
// material's total and the particle holding the most negative work.
TEST(MpmHealthCheck, StoredStressWorkFarBelowZeroStopsTheRunNamingTheMostNegativeParticle) {
  MpmSolver s(blockScene(), self());
  s.advance();
  auto& p = s.particles();
  const Energies e = s.energies();
  const auto [b, end] = p.materialRange(0);
  double mass = 0, rhoMin = 1e300;
  for (std::size_t i = b; i < end; ++i) {
    mass += p.mass[i];
    rhoMin = std::min(rhoMin, p.mass[i] / p.vol[i]);
  }
  const double c = s.model(0).waveSpeed(rhoMin);
  const double bound = e.kinetic + 0.5 * 1e-4 * mass * c * c;
  // Within the bound: passes (a small negative book is a time-integration error, not a violation).
  for (std::size_t i = b; i < end; ++i) p.work[i] = 0;
  p.work[9] = -0.9 * bound;
  EXPECT_EQ(healthMessage(s), "");
  // Beyond it: stops.
  p.work[9] = -1.1 * bound;
  std::ostringstream total;
  total.precision(6);
  total << "of solid 'block' = " << -1.1 * bound << " over its " << end - b << " particles here";
  expectNames(healthMessage(s), {"mpm: non-physical state: stored stress work [J] (elastic + dissipated)", total.str(),
                                 "expected >= 0", "lower time.cfl", where(s, 9), "t = "});
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
  expectNames(msg, {"time step collapsed", "(step 2)", "below time.dt_collapse_fraction = 0.001",
                    "the MPM CFL bound", "particle " + std::to_string(p.id[4]) + " of solid 'block'",
                    "x = " + core::formatPoint(x, 2) + " m", "|v| = 1e+12 m/s"});
}
