// The layered column (tests/verification/coupled/layered_column.yaml): a 1D analog of the filled
// lattices of issue 16, polymer layers and silicone converging on a symmetry plane in a closed
// column. Nothing heats or cools the polymer in the exact problem (linear elastic, no heat
// exchange), so its heat m cv T is a measure of the coupling's energy bookkeeping: whatever the
// mixed cells' correction gives it or takes from it. With MPM's face transport of the solid's
// volume (the scene's `coupling.solid_transport: mpm`) the polymer's heat changes by less than 5
// times the column's initial kinetic energy and the total energy is conserved, on the scene
// (measured +372 J against 273 J; +725 J before the fixes below) and on its neighbours: 1, 2 and 4
// cells a layer at time.cfl 0.05, 0.1 and 0.2 (+243 .. +404 J, 7 Dec 2026).
// With ICE's face transport (`ice`, the default) the polymer's heat fed the silicone, -48,990 J
// (180 times the kinetic energy, -9.2 K), the drain that stopped the filled lattices
// (docs/slides.md). Two mechanisms: (1) the embedded-fluid rule (src/ice/exchange/
// trace_temperature.cpp) measured the silicone's temperature change over the Lagrangian phase
// alone, where the stiffened gas's cold energy showed a cooling the equilibrium pressure's
// compression had given back, and paid it from the polymer every step (+55,700 J summed over this
// scene's run); fixed 7 Dec 2026 (the change over the whole step; and the rule weighted by how far
// a fluid is pumped): +4,464 J here, asserted not below -5 and within 30 times the kinetic energy.
// (2) Not fixed: with ICE's face fluxes the mixed cells' liquid takes p dV work the flux form does
// not deliver (the solid's volume moved by upwinded fractions, solid_faces.h), the Lagrangian
// correction D takes it back by heat capacity, from the polymer: at 4 cells a layer -26,316 /
// -47,834 J at time.cfl 0.1 / 0.2 (D -51,700 J in the mixed cells at 0.2), at 2 cells a layer and
// time.cfl 0.05 +15,467 J. MPM's face transport removes both.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "coupled_run.h"
#include "serial_mpi.h"

namespace mpmice::test {
namespace {

struct ColumnBudget {
  double kinetic0 = 0, heatChange = 0, internalChange = 0, totalChange = 0, created = 0;
};

// The scene with `coupling.solid_transport` set and, where given, mesh.spacing and time.cfl
// replaced (the scene's 0.00015 m and 0.1).
ColumnBudget runColumn(const std::string& transport, const std::string& spacing = "", const std::string& cfl = "") {
  std::ifstream in(LAYERED_COLUMN_SCENE);
  std::stringstream text;
  text << in.rdbuf();
  std::string yaml = text.str();
  auto replace = [&](const std::string& from, const std::string& to) {
    const std::size_t at = yaml.find(from);
    ASSERT_NE(at, std::string::npos) << LAYERED_COLUMN_SCENE << " lacks '" << from << "'";
    yaml.replace(at, from.size(), to);
  };
  if (!spacing.empty()) replace("spacing: 0.00015", "spacing: " + spacing);
  if (!cfl.empty()) replace("cfl: 0.1", "cfl: " + cfl);
  core::Scene s = core::parseScene(yaml, LAYERED_COLUMN_SCENE);
  s.coupling.solid_transport = transport;
  s.output.enabled = false;
  CoupledRun run(std::move(s));
  const coupler::SideTotals s0 = run.solid.totals(), f0 = run.fluid.totals();
  run.runTo(run.scene.time.end);
  const coupler::SideTotals s1 = run.solid.totals(), f1 = run.fluid.totals();
  ColumnBudget b;
  b.kinetic0 = s0.kinetic + f0.kinetic;
  b.heatChange = s1.heat - s0.heat;
  b.internalChange = f1.internal - f0.internal;
  b.totalChange = (s1.energy() + f1.energy()) - (s0.energy() + f0.energy());
  b.created = s1.created() - s0.created();
  std::printf("  solid_transport %s, spacing %s, cfl %s: %ld steps; kinetic energy at the start %.1f J; polymer heat %+.1f J, silicone and "
              "buffer internal %+.1f J; total %+.3e J (MPM's own numerics %+.3e J)\n",
              transport.c_str(), spacing.empty() ? "0.00015" : spacing.c_str(), cfl.empty() ? "0.1" : cfl.c_str(),
              run.steps, b.kinetic0, b.heatChange, b.internalChange, b.totalChange, b.created);
  return b;
}

TEST(LayeredColumn, MpmFaceTransportKeepsThePolymersHeat) {
  const ColumnBudget mpm = runColumn("mpm");
  EXPECT_LT(std::abs(mpm.heatChange), 5 * mpm.kinetic0);
  // Closed: the energy changes only by what MPM's own numerics name (the monitor's balance).
  EXPECT_NEAR(mpm.totalChange, mpm.created, 1e-9 * (mpm.kinetic0 + std::abs(mpm.internalChange)) + 1e-6);
}

// The neighbours of the scene: 1 and 4 cells a layer, and time.cfl 0.05 and 0.2.
TEST(LayeredColumn, MpmFaceTransportKeepsThePolymersHeatOnOtherMeshesAndSteps) {
  for (const char* spacing : {"0.0003", "0.00015", "0.000075"})
    for (const char* cfl : {"0.05", "0.2"}) {
      const ColumnBudget mpm = runColumn("mpm", spacing, cfl);
      EXPECT_LT(std::abs(mpm.heatChange), 5 * mpm.kinetic0) << "spacing " << spacing << ", cfl " << cfl;
      EXPECT_NEAR(mpm.totalChange, mpm.created, 1e-9 * (mpm.kinetic0 + std::abs(mpm.internalChange)) + 1e-6)
          << "spacing " << spacing << ", cfl " << cfl;
    }
}

// ICE's face transport on the scene: the embedded-fluid rule's drain is gone (above); its own
// correction's (mechanism 2) is printed at 4 cells a layer, not asserted.
TEST(LayeredColumn, IcesFaceTransportLosesTheEmbeddedFluidRulesDrain) {
  const ColumnBudget ice = runColumn("ice");
  EXPECT_GT(ice.heatChange, -5 * ice.kinetic0) << "the polymer's heat drains into the silicone";
  EXPECT_LT(std::abs(ice.heatChange), 30 * ice.kinetic0);
  EXPECT_NEAR(ice.totalChange, ice.created, 1e-9 * (ice.kinetic0 + std::abs(ice.internalChange)) + 1e-6);
  runColumn("ice", "0.000075", "0.1");  // printed: mechanism 2
}

}  // namespace
}  // namespace mpmice::test
