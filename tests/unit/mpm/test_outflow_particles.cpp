// Particles that leave the mesh through an `outflow` face (mpm.outflow_particles, default
// "remove"): they leave the simulation, counted, their mass, momentum and energy booked as outflow
// (MpmSolver::outflow(), Energies::outflow), and the run goes on; with "error", or through any
// other face, the run stops with a message naming the face. A free elastic block in uniform
// motion towards the x+ face (outflow) moves rigidly, so every particle leaves with the block's
// velocity: after it has crossed the face, no particle of it is left, the second (resting) block
// is untouched, and mass, momentum and the energy balance (what is left + what left) are the
// initial ones. Run on 1 and 4 ranks (the moving block crosses rank borders; the figures agree).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "mpm_problems.h"
#include "test_comm.h"

using namespace mpmice;
using namespace mpmice::mpm;
namespace pr = mpmice::mpm::problems;

namespace {

constexpr double kV = 2.0;  // [m/s] the moving block's velocity along x

// 16 x 16 cells on the unit square; x+ outflow, the other faces free. Block "runner" (4 x 4 cells,
// 2 x 2 particles per cell) moving at kV towards x+; block "rest" (2 x 2 cells) at rest far from
// every face.
core::Scene twoBlocks(const std::string& outflowParticles) {
  core::Scene s;
  s.name = "outflow_particles";
  s.mesh = core::Mesh(2, {0, 0, 0}, {1.0 / 16, 1.0 / 16, 1}, {16, 16, 1});
  for (auto& f : s.boundary) f.type = core::BoundaryType::Free;
  s.boundary[1].type = core::BoundaryType::Outflow;
  s.materials = {pr::solid("runner", 1000, pr::elastic("linear_elastic", 1e4, 0.3)),
                 pr::solid("rest", 2000, pr::elastic("linear_elastic", 1e4, 0.3))};
  core::ShapeSpec a, b;
  a.type = b.type = "box";
  a.lo = {0.5, 0.375, 0};
  a.hi = {0.75, 0.625, 0};
  b.lo = {0.125, 0.125, 0};
  b.hi = {0.25, 0.25, 0};
  s.geometry = {pr::region("runner", a, "runner", {2, 2, 1}), pr::region("rest", b, "rest", {2, 2, 1})};
  s.geometry[0].velocity = {kV, 0, 0};
  s.mpm.shape_function = "gimp";
  s.mpm.outflow_particles = outflowParticles;
  s.time.cfl = 0.4;
  return s;
}

struct Totals {
  double mass = 0, px = 0, py = 0;
  long long count = 0, runners = 0;
};

Totals totals(const MpmSolver& solver) {
  const auto& p = solver.particles();
  std::vector<double> s(5, 0.0);
  for (std::size_t i = 0; i < p.size(); ++i) {
    s[0] += p.mass[i];
    s[1] += p.mass[i] * p.v[0][i];
    s[2] += p.mass[i] * p.v[1][i];
    s[3] += 1;
    s[4] += p.material[i] == 0 ? 1 : 0;
  }
  solver.comm().sumInPlace(s);
  return {s[0], s[1], s[2], static_cast<long long>(s[3]), static_cast<long long>(s[4])};
}

}  // namespace

TEST(OutflowParticles, LeaveCountedWithTheirMassMomentumAndEnergy) {
  MpmSolver solver(twoBlocks("remove"), test::comm());
  const Totals t0 = totals(solver);
  const double balance0 = solver.energies().balance();
  const double kinetic0 = solver.energies().kinetic;
  ASSERT_EQ(t0.runners, 16 * 4);
  ASSERT_EQ(t0.count, 16 * 4 + 4 * 4);
  long long reported = 0;
  int reports = 0;
  // 0.5 m to the face and 0.25 m of block: gone after 0.375 s (0.4 s with margin).
  while (solver.time() < 0.4) {
    solver.advance();
    reported += solver.removedLastStep();
    if (solver.removedLastStep() > 0) {
      ++reports;
      if (solver.comm().root()) {
        const std::string& r = solver.removalReport();
        EXPECT_NE(r.find("of 'runner'"), std::string::npos) << r;
        EXPECT_NE(r.find("outflow face x+"), std::string::npos) << r;
      }
    }
  }
  const Totals t = totals(solver);
  const ParticleOutflow out = solver.outflow();
  const Energies e = solver.energies();
  if (solver.comm().root())
    std::printf("removed %g particles in %d steps with removals (reported %lld), mass out %.15g of %.15g, "
                "momentum out %.15g of %.15g, energy out %.15g (kinetic at the start %.15g), balance %.15g -> %.15g\n",
                out.count, reports, reported, out.mass, t0.mass, out.momentum[0], t0.px, e.outflow, kinetic0, balance0,
                e.balance());
  // Every particle of the runner left, none of the resting block; each was reported once.
  EXPECT_EQ(t.runners, 0);
  EXPECT_EQ(t.count, 16);
  EXPECT_EQ(out.count, 64.0);
  EXPECT_EQ(reported, 64);
  EXPECT_GT(reports, 1);  // the block leaves column by column, over several steps
  // Mass and momentum: what is left plus what left is what there was.
  EXPECT_NEAR(t.mass + out.mass, t0.mass, 1e-13 * t0.mass);
  EXPECT_NEAR(out.mass, 1000 * 0.25 * 0.25, 1e-12);
  EXPECT_NEAR(t.px + out.momentum[0], t0.px, 1e-10 * std::fabs(t0.px));
  EXPECT_NEAR(t.py + out.momentum[1], t0.py, 1e-10 * std::fabs(t0.px));
  // The rigidly moving block carried its kinetic energy out (and nothing else of note); the
  // energy balance, what is left plus what left less what the method created, holds.
  EXPECT_NEAR(out.kinetic, 0.5 * out.mass * kV * kV, 1e-6 * out.kinetic);
  EXPECT_NEAR(e.outflow, out.energy(), 1e-12 * std::fabs(out.energy()));
  EXPECT_NEAR(e.balance(), balance0, 1e-9 * kinetic0);
  // What is left is the resting block, at rest.
  EXPECT_NEAR(e.kinetic, 0.0, 1e-9 * kinetic0);
}

TEST(OutflowParticles, WithErrorTheRunStopsNamingTheFace) {
  MpmSolver solver(twoBlocks("error"), test::comm());
  try {
    while (solver.time() < 0.4) solver.advance();
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("outside the mesh"), std::string::npos) << m;
    EXPECT_NE(m.find("mpm.outflow_particles: remove"), std::string::npos) << m;
    if (solver.comm().size() == 1 || m.find("another rank") == std::string::npos) {
      EXPECT_NE(m.find("through the x+ face (outflow)"), std::string::npos) << m;
    }
  }
}

TEST(OutflowParticles, ThroughAFreeFaceItIsStillAnError) {
  auto s = twoBlocks("remove");
  s.boundary[1].type = core::BoundaryType::Free;
  MpmSolver solver(s, test::comm());
  try {
    while (solver.time() < 0.4) solver.advance();
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("outside the mesh"), std::string::npos) << m;
    if (solver.comm().size() == 1 || m.find("another rank") == std::string::npos) {
      EXPECT_NE(m.find("through the x+ face (free)"), std::string::npos) << m;
    }
  }
}

TEST(OutflowParticles, TheRecordSurvivesACheckpoint) {
  MpmSolver solver(twoBlocks("remove"), test::comm());
  while (solver.outflow().count < 10) solver.advance();
  const ParticleOutflow before = solver.outflow();
  core::CheckpointData data;
  solver.saveCheckpoint(data, "mpm");
  MpmSolver again(twoBlocks("remove"), test::comm());
  again.loadCheckpoint(data, "mpm");
  const ParticleOutflow after = again.outflow();
  EXPECT_EQ(after.count, before.count);
  EXPECT_EQ(after.mass, before.mass);
  EXPECT_EQ(after.kinetic, before.kinetic);
  EXPECT_EQ(again.energies().outflow, solver.energies().outflow);
  // The in-memory checkpoint (implicit coupling repeats a step) restores it too.
  const auto c = solver.checkpoint();
  solver.advance();
  solver.advance();
  solver.restore(c);
  EXPECT_EQ(solver.outflow().count, before.count);
}
