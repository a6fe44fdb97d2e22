// `coupler run`: the composed MPMD line and the translation of failed world ranks to participants.
#include <gtest/gtest.h>

#include "cli/run_command.h"
#include "scene/scene.h"

using namespace mpmice;

namespace {
core::Scene tinyScene() {
  return core::parseScene(R"(
scene: tiny
mesh: {dim: 2, lower: [0, 0], upper: [1, 1], cells: [4, 4]}
time: {end: 1.0e-3}
materials:
  - {name: air, kind: fluid, eos: {type: ideal_gas, gamma: 1.4}}
geometry:
  - {shape: {type: box, lo: [0, 0], hi: [1, 1]}, material: air, pressure: 1.0e5, density: 1.2}
coupling: {ranks: {mpm: 2, ice: 3}}
)", "tiny.yaml");
}
}  // namespace

TEST(CoupleRun, ComposesMpmdLineFromSceneRanks) {
  const auto s = tinyScene();
  const auto plan = coupler::composeLaunch(s, "tiny.yaml", "/b", "/x/mpirun", s.coupling.mpm_ranks,
                                           s.coupling.ice_ranks);
  EXPECT_EQ(plan.commandLine(),
            "/x/mpirun -np 2 /b/mpm_solver/mpm_solver tiny.yaml : -np 3 /b/ice_solver/ice_solver tiny.yaml");
  EXPECT_EQ(plan.describeWorldRank(0), "mpm_solver rank 0");
  EXPECT_EQ(plan.describeWorldRank(2), "ice_solver rank 0");
  EXPECT_EQ(plan.describeWorldRank(4), "ice_solver rank 2");
  EXPECT_EQ(plan.describeWorldRank(5), "");
}

TEST(CoupleRun, ExplainsFailedRanksFromMpirunText) {
  const auto s = tinyScene();
  const auto plan = coupler::composeLaunch(s, "tiny.yaml", "/b", "mpirun", 1, 2);
  const std::string text =
      "mpirun noticed that process rank 2 with PID 123 on node vm exited on signal 9 (Killed).\n"
      "  Process name: [[4242,1],2]\n";
  const auto lines = coupler::explainFailure(plan, text);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0], "coupler: world rank 2 is ice_solver rank 1");
}

TEST(CoupleRun, RejectsBadRankCounts) {
  const auto s = tinyScene();
  EXPECT_THROW(coupler::composeLaunch(s, "tiny.yaml", "/b", "mpirun", 0, 1), std::invalid_argument);
}
