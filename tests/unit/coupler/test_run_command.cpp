// `coupler run`: the composed MPMD line and the translation of failed world ranks to participants.
#include <gtest/gtest.h>

#include <sstream>

#include "coupler/cli/openfoam_case.h"
#include "coupler/cli/run_command.h"
#include "core/scene/scene.h"

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

namespace {
core::Scene flapScene(const std::string& caseDir) {
  return core::parseScene(R"(
scene: flap
mesh: {dim: 2, lower: [-0.5, 0], upper: [0.5, 1.2], cells: [20, 24]}
time: {end: 0.5}
materials:
  - {name: flap, kind: solid, density: 3000, model: {type: neo_hookean, youngs_modulus: 4.0e6, poissons_ratio: 0.3}}
geometry:
  - {shape: {type: box, lo: [-0.05, 0], hi: [0.05, 1]}, material: flap}
coupling:
  schedule: explicit_serial
  fluid: openfoam
  ranks: {mpm: 2}
  interface: {solid: flap, patch: flap, case: ")" + caseDir + R"(", solver: pisoFoam}
)", "flap.yaml");
}
}  // namespace

TEST(CoupleRun, ComposesTheOpenFoamLaunchWithASerialFluid) {
  const auto s = flapScene("fluid");
  const auto plan = coupler::composeLaunch(s, "flap.yaml", "/b", "/x/mpirun", 2, 4, "/o/fluid");
  EXPECT_EQ(plan.commandLine(), "/x/mpirun -x WM_PROJECT_DIR -np 2 /b/mpm_solver/mpm_solver flap.yaml : -np 1 "
                                "pisoFoam -case /o/fluid");
  EXPECT_EQ(plan.describeWorldRank(2), "pisoFoam rank 0");
  ASSERT_EQ(plan.executables.size(), 1u);
}

TEST(CoupleRun, AddsTheAdapterInsideTheFunctionsDictionary) {
  const std::string entry = coupler::adapterEntry("/b/lib.so", "/s/flap.yaml");
  EXPECT_NE(entry.find("type    mpmiceAdapter;"), std::string::npos);
  EXPECT_NE(entry.find("scene   \"/s/flap.yaml\";"), std::string::npos);
  // An existing functions dictionary keeps its objects; the adapter goes first inside it.
  const std::string withFunctions = "endTime 5;\nfunctions\n{\n    forces { type forces; }\n}\n";
  const std::string a = coupler::withFunctionObject(withFunctions, entry);
  EXPECT_EQ(a, "endTime 5;\nfunctions\n{\n" + entry + "\n    forces { type forces; }\n}\n");
  // Without one, a functions dictionary is appended; `functionsOther` is not a match.
  const std::string b = coupler::withFunctionObject("functionsOther 1;\n", entry);
  EXPECT_EQ(b, "functionsOther 1;\n\nfunctions\n{\n" + entry + "}\n");
}

TEST(CoupleRun, AMissingOpenFoamCaseNamesTheSceneKey) {
  const auto s = flapScene("no/such/case");
  std::ostringstream out;
  try {
    (void)coupler::prepareOpenFoamCase(s, "flap.yaml", "/b", out);
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("flap.yaml:"), std::string::npos) << msg;
    EXPECT_NE(msg.find("coupling.interface.case: 'no/such/case'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("no system/controlDict"), std::string::npos) << msg;
  }
}
