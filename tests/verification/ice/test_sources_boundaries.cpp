// Energy sources, heat exchange, inflow/outflow boundaries and the Mie-Gruneisen / JWL equations
// of state in running scenes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "ice_test_scenes.h"
#include "core/material/solid_bulk_eos.h"
#include "test_comm.h"

using namespace mpmice;

namespace {
// A step's phases from its start to the face pressure (after the equilibrium pressure).
void toFacePressure(ice::IceSolver& sol, double dt) {
  sol.beginStep(dt);
  sol.computeFaceVelocities();
  sol.computePressureIncrement();
  sol.computeFacePressure();
}
}  // namespace

namespace {
// Energy an air-filled 10 x 10 box (0.1 m cells, unit depth, slip walls) gains in 1 ms from a
// source of 1e8 W/m^3 on the box [lo, hi] switched on for 5e-4 s.
double heatedBoxEnergy(const char* name, core::RealVect lo, core::RealVect hi) {
  core::Scene s;
  s.name = name;
  s.mesh = core::Mesh(2, {0, 0, 0}, {0.1, 0.1, 1}, {10, 10, 1});
  for (auto& b : s.boundary) b.type = core::BoundaryType::SlipWall;
  s.time.end = 1e-3;
  s.materials = {test::idealGas("air")};
  s.geometry = {test::region("air", test::box({0, 0, 0}, {1, 1, 1}), {{"air", 1.0}}, 1e5, 1.2)};
  core::SourceSpec src;
  src.material = "air";
  src.shape = test::box(lo, hi);
  src.power_density = 1e8;
  src.start = 0;
  src.end = 5e-4;
  s.sources = {src};
  ice::IceSolver sol(s, test::comm());
  const double e0 = sol.totals().energy;
  test::runToEnd(sol, s.time.end);
  return sol.totals().energy - e0;
}
}  // namespace

TEST(IceSources, EnergySourceAddsPowerTimesVolumeTimesDuration) {
  // 4 x 4 cells = 0.16 m^3 (unit depth)
  const double added = heatedBoxEnergy("heated", {0.3, 0.3, 0}, {0.7, 0.7, 1});
  std::printf("  energy added %.6e J (expected %.6e J)\n", added, 1e8 * 0.16 * 5e-4);
  EXPECT_NEAR(added, 1e8 * 0.16 * 5e-4, 1e-9 * added);
}

// A shape whose edge cuts cells: each cut cell takes the fraction of its volume inside, so the
// energy added is power x the shape's own volume, not x the cells whose centre is inside (which
// for the box below is 0.16 m^3, 14 % more than its 0.140625 m^3).
TEST(IceSources, ACellTheShapesEdgeCutsTakesItsShareInside) {
  // 0.375^2 = 0.140625 m^3 (unit depth)
  const double added = heatedBoxEnergy("heated_cut", {0.3, 0.3, 0}, {0.675, 0.675, 1});
  const double expected = 1e8 * 0.140625 * 5e-4;
  std::printf("  energy added %.6e J (expected %.6e J; by cell centres %.6e J)\n", added, expected, 1e8 * 0.16 * 5e-4);
  EXPECT_NEAR(added, expected, 1e-9 * expected);
}

TEST(IceExchange, HeatExchangeEqualisesTemperaturesAndConservesEnergy) {
  core::Scene s;
  s.name = "heat";
  s.mesh = core::Mesh(1, {0, 0, 0}, {0.1, 1, 1}, {4, 1, 1});
  for (auto& b : s.boundary) b.type = core::BoundaryType::Periodic;
  s.materials = {test::idealGas("a", 1.4, 717.5), test::idealGas("b", 1.67, 3116)};
  s.geometry = {test::region("all", test::box({0, 0, 0}, {1, 1, 1}), {{"a", 0.5}, {"b", 0.5}}, 1e5, 0.0)};
  s.geometry[0].density.reset();
  s.ice.exchange_heat = 1e15;
  ice::IceSolver sol(s, test::comm());
  core::forEach(sol.ownedBox(), [&](int i, int j, int k) { sol.state().mat[1].eint(i, j, k) *= 2.0; });
  sol.computeEquilibriumPressure();
  const double e0 = sol.totals().energy;
  sol.step();
  const auto& a = sol.state().mat[0];
  const auto& b = sol.state().mat[1];
  const double Ta = a.eos->temperature(1.0 / a.spvol(0, 0, 0), a.eint(0, 0, 0));
  const double Tb = b.eos->temperature(1.0 / b.spvol(0, 0, 0), b.eint(0, 0, 0));
  EXPECT_NEAR(Ta, Tb, 1e-8 * Ta);
  EXPECT_NEAR(sol.totals().energy, e0, 1e-13 * e0);
}

TEST(IceBoundaries, InflowAddsMassAtRhoUA) {
  core::Scene s;
  s.name = "inflow";
  s.mesh = core::Mesh(1, {0, 0, 0}, {0.01, 1, 1}, {100, 1, 1});
  s.boundary[0].type = core::BoundaryType::Inflow;
  s.boundary[0].velocity = {50, 0, 0};
  s.boundary[0].density = 1.2;
  s.boundary[0].pressure = 1e5;
  s.boundary[1].type = core::BoundaryType::Outflow;
  s.boundary[1].pressure = 1e5;
  s.time.end = 1e-3;
  s.materials = {test::idealGas("air")};
  s.geometry = {test::region("air", test::box({0, 0, 0}, {1, 1, 1}), {{"air", 1.0}}, 1e5, 1.2, {50, 0, 0})};
  ice::IceSolver sol(s, test::comm());
  const double m0 = sol.totals().mass;
  test::runToEnd(sol, s.time.end);
  // Uniform flow through: inflow = outflow, the state stays uniform.
  EXPECT_NEAR(sol.totals().mass, m0, 1e-9 * m0);
  double du = 0;
  core::forEach(sol.ownedBox(), [&](int i, int j, int k) {
    du = std::max(du, std::abs(sol.state().mat[0].vel(i, j, k, 0) - 50.0));
  });
  EXPECT_LT(du, 1e-6);
}

TEST(IceEos, MieGruneisenWaterAndJwlProductsRun) {
  core::Scene s;
  s.name = "blast_in_water";
  s.mesh = core::Mesh(1, {0, 0, 0}, {0.0025, 1, 1}, {400, 1, 1});
  for (auto& b : s.boundary) b.type = core::BoundaryType::Outflow;
  s.time.end = 50e-6;
  core::MaterialSpec water;
  water.name = "water";
  water.eos.type = "mie_gruneisen";
  water.eos.params = {{"reference_density", 998}, {"sound_speed", 1483}, {"slope", 1.75}, {"gruneisen", 0.28},
                      {"reference_pressure", 1e5}};
  water.specific_heat = 4186;
  core::MaterialSpec tnt;
  tnt.name = "products";
  tnt.eos.type = "jwl";
  tnt.eos.params = {{"A", 371.2e9}, {"B", 3.231e9}, {"R1", 4.15}, {"R2", 0.95}, {"omega", 0.3},
                    {"reference_density", 1630}};
  tnt.specific_heat = 1000;
  s.materials = {water, tnt};
  s.geometry = {test::region("water", test::box({0, 0, 0}, {1, 1, 1}), {{"water", 1.0}}, 1e5, 998),
                // Products expanded to 1.5 times their reference volume at 2 GPa (about 2100 K): at
                // their reference density 2 GPa lies below the law's pressure at 0 K (6.28 GPa,
                // -8760 K), a start refused since 6 Dec 2026 (docs/ice.md "What a fluid region fills").
                test::region("charge", test::box({0, -1, -1}, {0.1, 2, 2}), {{"products", 1.0}}, 2e9, 1630 / 1.5)};
  ice::IceSolver sol(s, test::comm());
  test::runToEnd(sol, s.time.end);
  double shock = 0, minP = 1e300;
  core::forEach(sol.ownedBox(), [&](int i, int j, int k) {
    minP = std::min(minP, sol.pressure()(i, j, k));
    if (sol.pressure()(i, j, k) > 1e7) shock = sol.mesh().cellCenter(0, i);
  });
  const double speed = (shock - 0.1) / s.time.end;
  std::printf("  %ld steps, water shock at %.4f m: mean speed %.0f m/s, min p %.3e\n", sol.steps(), shock, speed, minP);
  // Mie-Gruneisen water may go into tension behind the products' rarefaction (no cavitation
  // model); the run must stay finite and bounded.
  EXPECT_TRUE(std::isfinite(minP));
  EXPECT_GT(minP, -1e9);
  EXPECT_GT(speed, 1483.0);  // a shock outruns sound
  EXPECT_LT(speed, 4000.0);
}


// The coupling phases with an external (solid) material: the solid's cell state comes in before
// the pressure, ICE returns the pressure force on it, takes its Lagrangian momentum and returns
// the exchange increments. A steel block at rest in a gas that moves at 10 m/s: the equilibrium
// pressure stays at the gas pressure, the exchange drags gas and steel to a common velocity, and
// the increments balance the gas's momentum change. The steel fills 30% of the block's cells,
// which hold gas as well: the equilibrium compresses the gas there to 1 / 0.7 of its pressure.
TEST(IceExternal, CouplingPhasesWithASolidBlock) {
  core::Scene s;
  s.name = "external";
  s.mesh = core::Mesh(1, {0, 0, 0}, {0.1, 1, 1}, {10, 1, 1});
  for (auto& b : s.boundary) b.type = core::BoundaryType::Periodic;
  const core::MaterialSpec steel = test::externalSteel();
  s.materials = {test::idealGas("air"), steel};
  s.geometry = {test::region("air", test::box({0, 0, 0}, {1, 1, 1}), {{"air", 1.0}}, 1e5, 1.2, {10, 0, 0})};
  ice::IceSolver sol(s, test::comm());
  const auto& owned = sol.ownedBox();
  const std::size_t n = static_cast<std::size_t>(owned.numPts());
  const double V = sol.mesh().cellVolume();
  const core::SolidBulkEos law(117e9, 101325, 8900);
  const double v0 = 1.0 / law.density(1e5);
  std::vector<double> mass(n, 0.0), vel(3 * n, 0.0), T(n, 300.0), sv(n, v0);
  core::forEach(owned, [&](int i, int j, int k) {
    const double x = sol.mesh().cellCenter(0, i);
    if (x > 0.4 && x < 0.6) mass[static_cast<std::size_t>(owned.index(i, j, k))] = 0.3 * V / v0;
  });
  sol.setExternalMaterialState(1, mass, vel, T, sv);
  sol.computeEquilibriumPressure();
  core::forEach(owned, [&](int i, int j, int k) {
    const double x = sol.mesh().cellCenter(0, i);
    const double expect = x > 0.4 && x < 0.6 ? 1e5 / 0.7 : 1e5;  // the steel barely compresses
    EXPECT_NEAR(sol.pressure()(i, j, k), expect, 1e-4 * expect) << i;
  });
  toFacePressure(sol, 1e-5);
  const core::Field force = sol.pressureForce(1);
  EXPECT_EQ(force.box(), owned);
  sol.computeSourcesAndLagrangian();
  std::vector<double> mom(3 * n, 0.0);  // the solid stays at rest before the exchange
  sol.setExternalLagrangianMomentum(1, mom);
  sol.exchange();
  const core::Field& dm = sol.exchangeMomentum(1);
  double solidGain = 0, gasVelInBlock = 0;
  core::forEach(owned, [&](int i, int j, int k) {
    solidGain += dm(i, j, k, 0);
    const double x = sol.mesh().cellCenter(0, i);
    if (x > 0.45 && x < 0.55) gasVelInBlock = sol.state().mat[0].lagVel()(i, j, k, 0);
  });
  EXPECT_GT(solidGain, 0.0);              // the gas pushes the steel along
  EXPECT_LT(std::abs(gasVelInBlock), 1e-3);  // and is stopped by it (K = 1e15)
  sol.advectFluids();
  EXPECT_NEAR(sol.time(), 1e-5, 1e-18);
}

// The solid's own volume change (its solver's figure, setExternalVolumeChange): the cell's fluids
// fill the rest of the cell's volume change, so the p dV work of the difference between it and the
// solid's share of the cell's change is theirs, taken in proportion to the volume they fill; the
// rest of the energy correction is shared by heat capacity as before. The block of
// IceExternal.CouplingPhasesWithASolidBlock (steel 30 % of two cells, air around it) run to the
// end of the Lagrangian phase twice, the second time with the steel compressing by 1e-3 of its
// volume: in the block's cells the air's energy changes by theta_air p dV (m_s c_s / C), the steel's
// by minus that (the total is kept), elsewhere nothing changes. Without the volume change (before
// the solid reported it) the air's energy did not depend on it.
TEST(IceExternal, TheSolidsOwnVolumeChangeIsWorkOfTheFluidsThatFillTheRest) {
  core::Scene s;
  s.name = "volume_change";
  s.mesh = core::Mesh(1, {0, 0, 0}, {0.1, 1, 1}, {10, 1, 1});
  for (auto& b : s.boundary) b.type = core::BoundaryType::Periodic;
  s.materials = {test::idealGas("air"), test::externalSteel()};
  s.geometry = {test::region("air", test::box({0, 0, 0}, {1, 1, 1}), {{"air", 1.0}}, 1e5, 1.2, {10, 0, 0})};
  const double v0 = 1.0 / core::SolidBulkEos(117e9, 101325, 8900).density(1e5);
  struct Out {
    std::vector<double> air, steel, p, thAir, mAir, mSteel, dV;
  };
  auto run = [&](bool given) {
    ice::IceSolver sol(s, test::comm());
    const auto& owned = sol.ownedBox();
    const std::size_t n = static_cast<std::size_t>(owned.numPts());
    const double V = sol.mesh().cellVolume();
    std::vector<double> mass(n, 0.0), vel(3 * n, 0.0), T(n, 300.0), sv(n, v0), dV(n, 0.0), work(n, 0.0);
    core::forEach(owned, [&](int i, int j, int k) {
      const auto q = static_cast<std::size_t>(owned.index(i, j, k));
      const double x = sol.mesh().cellCenter(0, i);
      if (x > 0.4 && x < 0.6) mass[q] = 0.3 * V / v0, dV[q] = -1e-3 * 0.3 * V;
    });
    sol.setExternalMaterialState(1, mass, vel, T, sv);
    sol.computeEquilibriumPressure();
    toFacePressure(sol, 1e-5);
    sol.setExternalCouplingWork(1, work);
    if (given) sol.setExternalVolumeChange(1, dV);
    Out o;
    o.dV = dV;
    const auto& air = sol.state().mat[0];
    sol.computeSourcesAndLagrangian();
    sol.setExternalLagrangianMomentum(1, std::vector<double>(3 * n, 0.0));
    sol.exchange();  // the correction's heat-capacity share is given there, with the drag heat
    core::forEach(owned, [&](int i, int j, int k) {
      o.air.push_back(air.mass(i, j, k) * air.lagEint()(i, j, k));
      o.steel.push_back(sol.exchangeEnergy(1)(i, j, k));
      o.p.push_back(sol.pressure()(i, j, k));
      o.thAir.push_back(air.theta(i, j, k));
      o.mAir.push_back(air.mass(i, j, k));
      o.mSteel.push_back(sol.state().mat[1].mass(i, j, k));
    });
    return o;
  };
  const Out a = run(false), b = run(true);
  const double cvAir = 717.5, cvSteel = 450;  // test::idealGas("air"), test::externalSteel()
  double total = 0, scale = 0;
  for (std::size_t q = 0; q < a.air.size(); ++q) {
    const double dAir = b.air[q] - a.air[q], dSteel = b.steel[q] - a.steel[q];
    total += dAir + dSteel;
    scale += std::abs(dAir);
    if (b.mSteel[q] == 0) {
      EXPECT_EQ(dAir, 0.0) << q;
      EXPECT_EQ(dSteel, 0.0) << q;
      continue;
    }
    const double C = b.mAir[q] * cvAir + b.mSteel[q] * cvSteel;
    const double expect = b.thAir[q] * b.p[q] * b.dV[q] * b.mSteel[q] * cvSteel / C;  // < 0: the air expands
    EXPECT_LT(dAir, 0.0) << q;
    EXPECT_NEAR(dAir, expect, 1e-4 * std::abs(expect)) << q;
    EXPECT_NEAR(dSteel, -expect, 1e-4 * std::abs(expect)) << q;
  }
  EXPECT_GT(scale, 0.0);
  EXPECT_LT(std::abs(total), 1e-12 * scale);
}

// Near-vacuum gas (1e-9 kg/m^3, specific volume 1e9 m^3/kg) in the cells of a steel block beside
// gas at 1 atm: the face pressure at the block's edge accelerates it by dt v grad p ~ 1e9 m/s in a
// step and the Lagrangian correction takes that kinetic energy back (D ~ -1e8 J, a -3000 K share
// for every material of the cell), which the drag heat returns. Given apart, the gas refused its
// share and then took the drag heat: energy out of nothing, which the audit counted (the
// strengthless foam model to 1 ms stopped at 201 us on it, docs/slides.md). Given together after
// the exchange, the cell's net: no fallback, nothing audited, the gas's temperature in range.
TEST(IceExternal, AcceleratedVacuumGasInASolidCellTakesItsNetEnergy) {
  core::Scene s;
  s.name = "vacuum_in_solid";
  s.mesh = core::Mesh(1, {0, 0, 0}, {0.1, 1, 1}, {10, 1, 1});
  for (auto& b : s.boundary) b.type = core::BoundaryType::Periodic;
  s.materials = {test::idealGas("air"), test::externalSteel()};
  s.geometry = {test::region("air", test::box({0, 0, 0}, {1, 1, 1}), {{"air", 1.0}}, 1e5, 1.2),
                test::region("vacuum", test::box({0.4, 0, 0}, {0.6, 1, 1}), {{"air", 1.0}}, 1e-4, 1e-9)};
  ice::IceSolver sol(s, test::comm());
  const auto& owned = sol.ownedBox();
  const std::size_t n = static_cast<std::size_t>(owned.numPts());
  const double V = sol.mesh().cellVolume();
  const double v0 = 1.0 / core::SolidBulkEos(117e9, 101325, 8900).density(1e-4);
  std::vector<double> mass(n, 0.0), vel(3 * n, 0.0), T(n, 300.0), sv(n, v0), work(n, 0.0);
  core::forEach(owned, [&](int i, int j, int k) {
    const double x = sol.mesh().cellCenter(0, i);
    if (x > 0.4 && x < 0.6) mass[static_cast<std::size_t>(owned.index(i, j, k))] = 0.7 * V / v0;
  });
  sol.setExternalMaterialState(1, mass, vel, T, sv);
  sol.computeEquilibriumPressure();
  toFacePressure(sol, 1e-5);
  sol.setExternalCouplingWork(1, work);
  sol.computeSourcesAndLagrangian();
  double uMax = 0;  // the gas's largest Lagrangian speed in the block
  const auto& air = sol.state().mat[0];
  core::forEach(owned, [&](int i, int j, int k) {
    const double x = sol.mesh().cellCenter(0, i);
    if (x > 0.4 && x < 0.6) uMax = std::max(uMax, std::abs(air.lagVel()(i, j, k, 0)));
  });
  EXPECT_GT(uMax, 1e8);  // the case: the explicit acceleration of the near-vacuum gas
  sol.setExternalLagrangianMomentum(1, std::vector<double>(3 * n, 0.0));
  sol.exchange();
  EXPECT_EQ(sol.energyAudit().stepCreated, 0.0);
  EXPECT_EQ(sol.energyFallbacks(), 0);
  core::forEach(owned, [&](int i, int j, int k) {
    const double x = sol.mesh().cellCenter(0, i);
    if (!(x > 0.4 && x < 0.6)) return;
    const double Tg = air.lagEint()(i, j, k) / 717.5, Ts = 300.0 + sol.exchangeEnergy(1)(i, j, k) / (mass[static_cast<std::size_t>(owned.index(i, j, k))] * 450.0);
    EXPECT_NEAR(Tg, 1e-4 / (0.4 * 1e-9) / 717.5, 1.0) << i;  // 348 K (1953 K when given apart)
    EXPECT_NEAR(Ts, 300.0, 1.0) << i;  // the steel's net share: a fraction of a kelvin
  });
}

namespace {
// Steel (external material `material`, 8900 kg/m^3, at rest at 300 K) filling share(i) of each
// owned cell i, as the coupler's solid side hands it over.
template <class Share>
void placeSteel(ice::IceSolver& sol, int material, Share share) {
  const auto& owned = sol.ownedBox();
  const std::size_t n = static_cast<std::size_t>(owned.numPts());
  const double V = sol.mesh().cellVolume(), v0 = 1.0 / 8900.0;
  std::vector<double> mass(n, 0.0), vel(3 * n, 0.0), T(n, 300.0), sv(n, v0);
  core::forEach(owned, [&](int i, int j, int k) { mass[static_cast<std::size_t>(owned.index(i, j, k))] = share(i) * V / v0; });
  sol.setExternalMaterialState(material, mass, vel, T, sv);
}
}  // namespace

// Solids smeared over cells by the node-to-cell average: a cell may receive more solid mass than
// fits (m v0 > V). The equilibrium clips the solid to the cell, so the pressure stays the solid's
// own (p_ref at its reference specific volume) instead of compressing it by the overfill (GPa).
// Then the start-up fit: fluids scaled to fill the volume the solid leaves free at the scene's
// pressure, so partly covered cells start at that pressure.
TEST(IceExternal, OverfullSolidCellsKeepTheSolidPressureAndFluidsFitTheFreeVolume) {
  core::Scene s;
  s.name = "overfull";
  s.mesh = core::Mesh(1, {0, 0, 0}, {0.1, 1, 1}, {10, 1, 1});
  for (auto& b : s.boundary) b.type = core::BoundaryType::Periodic;
  const core::MaterialSpec steel = test::externalSteel();
  s.materials = {test::idealGas("air"), steel};
  s.geometry = {test::region("air", test::box({0, 0, 0}, {1, 1, 1}), {{"air", 1.0}}, 101325, 1.2)};
  ice::IceSolver sol(s, test::comm());
  // Solid volume / cell volume per cell: cell 4 overfilled, cell 5 half covered.
  auto share = [](int i) { return i == 4 ? 1.3 : i == 5 ? 0.5 : 0.0; };
  placeSteel(sol, 1, share);
  sol.fitFluidsToExternalVolume();
  sol.computeEquilibriumPressure();
  core::forEach(sol.ownedBox(), [&](int i, int j, int k) {
    // Cell 4: the solid's own pressure at v0 (p_ref) up to the trace of air it squeezes;
    // cell 5 and the open cells: the scene's pressure, the air having been fitted.
    EXPECT_NEAR(sol.pressure()(i, j, k), 101325.0, 1e-3 * 101325.0) << "cell " << i << " share " << share(i);
    const double thetaSolid = sol.state().mat[1].theta(i, j, k);
    EXPECT_NEAR(thetaSolid, std::min(share(i), 1.0), 1e-6) << "cell " << i;
  });
}

// Cells whose centre lies in a solid object start with a trace of every fluid; the coupled start's
// fit lets the fluids of the region around the solid fill what the solid leaves free, not every
// fluid alike. Air around a steel block (cells 4-5, the steel 60 % of each), water in cells 8-9:
// after the fit the block's cells hold air at the scene's pressure in 40 % of their volume and
// water only as a trace. Before, each fluid took an equal share (air and water 20 % each): the
// filled lattices' buffer gas took half of the polymer's surface cells (docs/slides.md).
TEST(IceExternal, TheFluidAroundASolidFillsItsFreeVolumeNotEveryFluidAlike) {
  core::Scene s;
  s.name = "fill";
  s.mesh = core::Mesh(1, {0, 0, 0}, {0.1, 1, 1}, {10, 1, 1});
  for (auto& b : s.boundary) b.type = core::BoundaryType::Periodic;
  s.materials = {test::idealGas("air"), test::stiffenedGas("water", 4.4, 6e8), test::externalSteel()};
  s.geometry = {test::region("air", test::box({0, 0, 0}, {1, 1, 1}), {{"air", 1.0}}, 101325, 1.2),
                test::region("water", test::box({0.8, 0, 0}, {1, 1, 1}), {{"water", 1.0}}, 101325, 1000),
                test::region("block", test::box({0.4, 0, 0}, {0.6, 1, 1}), {{"steel", 1.0}}, 101325, 8900)};
  ice::IceSolver sol(s, test::comm());
  placeSteel(sol, 2, [](int i) { return i == 4 || i == 5 ? 0.6 : 0.0; });
  sol.fitFluidsToExternalVolume();
  sol.computeEquilibriumPressure();
  const auto& st = sol.state();
  core::forEach(sol.ownedBox(), [&](int i, int j, int k) {
    const double air = st.mat[0].theta(i, j, k), water = st.mat[1].theta(i, j, k);
    if (i == 4 || i == 5) {
      EXPECT_NEAR(air, 0.4, 1e-4) << "cell " << i;
      EXPECT_LT(water, 1e-6) << "cell " << i;
      EXPECT_NEAR(sol.pressure()(i, j, k), 101325.0, 1e-3 * 101325.0) << "cell " << i;
    } else if (i >= 8) {
      EXPECT_NEAR(water, 1.0, 1e-6) << "cell " << i;
    } else {
      EXPECT_NEAR(air, 1.0, 1e-6) << "cell " << i;
    }
  });
}

namespace {
// Steel (external, 300 K, at rest) fills 4 periodic cells of 0.025 m with a trace of air moving at
// airU; the step of 1e-6 s run to the end of the Lagrangian phase (the exchange is next).
std::unique_ptr<ice::IceSolver> airTraceInSteel(double airU) {
  core::Scene s;
  s.name = "trace";
  s.mesh = core::Mesh(1, {0, 0, 0}, {0.1, 1, 1}, {4, 1, 1});
  for (auto& b : s.boundary) b.type = core::BoundaryType::Periodic;
  s.materials = {test::idealGas("air"), test::externalSteel()};
  s.geometry = {test::region("air", test::box({0, 0, 0}, {1, 1, 1}), {{"air", 1.0}}, 101325, 1.2, {airU, 0, 0})};
  s.ice.exchange_momentum = 1e15;
  auto solver = std::make_unique<ice::IceSolver>(s, test::comm());
  ice::IceSolver& sol = *solver;
  const std::size_t n = static_cast<std::size_t>(sol.ownedBox().numPts());
  const double v0 = 1.0 / 8900.0;
  std::vector<double> mass(n, sol.mesh().cellVolume() / v0), vel(3 * n, 0.0), T(n, 300.0), sv(n, v0);
  sol.setExternalMaterialState(1, mass, vel, T, sv);
  sol.fitFluidsToExternalVolume();  // the air becomes a trace in the filled cells
  sol.computeEquilibriumPressure();
  toFacePressure(sol, 1e-6);
  sol.computeSourcesAndLagrangian();
  return solver;
}
}  // namespace

// The drag of the momentum exchange turns kinetic energy into heat; that heat is shared so that
// every material of the cell warms by the same temperature, not given to the lightest one. Here
// steel fills every cell and only a trace of air (volume fraction ~1e-9) moves through it at
// 1000 m/s: the exchange stops the trace, and the 0.5 (1000 m/s)^2 = 5e5 J/kg it loses must not
// all land on the trace (+700 K per step). That was the runaway of the seed cylinder: in the
// wall's solid cells the trace air's specific volume ~ T / p grows, so its Lagrangian velocity
// u - dt v grad p and the heat it received grew with it, until the trace took the cell's volume.
TEST(IceExchange, DragHeatIsSharedAtOneTemperatureRiseNotGivenToATrace) {
  const auto solver = airTraceInSteel(1000.0);
  ice::IceSolver& sol = *solver;
  const auto& owned = sol.ownedBox();
  const std::size_t n = static_cast<std::size_t>(owned.numPts());
  const auto& air = sol.state().mat[0];
  auto airT = [&](int i) { return air.eos->temperature(1.0 / air.lagSpvol()(i, 0, 0), air.lagEint()(i, 0, 0)); };
  std::vector<double> T0(n);
  core::forEach(owned, [&](int i, int j, int k) { T0[static_cast<std::size_t>(owned.index(i, j, k))] = airT(i); });
  std::vector<double> mom(3 * n, 0.0);
  sol.setExternalLagrangianMomentum(1, mom);
  sol.exchange();
  core::forEach(owned, [&](int i, int j, int k) {
    const double ma = air.mass(i, j, k), ms = sol.state().mat[1].mass(i, j, k);
    const double dTair = airT(i) - T0[static_cast<std::size_t>(owned.index(i, j, k))];
    EXPECT_LT(ma, 1e-8 * ms) << "cell " << i << ": air is a trace";
    EXPECT_LT(std::abs(air.lagVel()(i, j, k, 0)), 1e-3) << "cell " << i << ": the steel stops the trace";
    const double dTsteel = sol.exchangeEnergy(1)(i, j, k) / (ms * 450.0);
    EXPECT_GT(dTsteel, 0.0) << "cell " << i;
    EXPECT_NEAR(dTair, dTsteel, 1e-6 * dTsteel + 1e-12) << "cell " << i << ": one temperature rise";
    EXPECT_LT(dTair, 1e-3) << "cell " << i << ": the trace is not heated by the drag";
    // The heat is the kinetic energy lost: 0.5 m_a (1000^2 - u_a^2) - 0.5 m_s u_s^2, u_s = m_a 1000 / m.
    const double us = sol.exchangeMomentum(1)(i, j, k, 0) / ms;
    const double lost = 0.5 * ma * (1e6 - air.lagVel()(i, j, k, 0) * air.lagVel()(i, j, k, 0)) - 0.5 * ms * us * us;
    const double heat = sol.exchangeEnergy(1)(i, j, k) + ma * air.eos->cv() * dTair;
    EXPECT_NEAR(heat, lost, 1e-6 * lost) << "cell " << i << ": energy conserved";
  });
}

// A fluid embedded in a solid follows the solid's temperature change (trace_temperature.cpp), but
// never below 0 K: a trace the Lagrangian ratchet has cooled towards 0 K (a buffer gas carried into a
// filled lattice's polymer, docs/slides.md) took the polymer's per-step cooling of its cell and
// went below 0 K at step 1899. Steel fills every cell with a trace of air at rest; the steel's
// Lagrangian energy says it cooled by 0.1 K this step. Air at 300 K follows (-0.1 K, the steel
// paying the heat it takes); air at 0.05 K does not take a change that would leave it less than
// kMinEnergyShare of its thermal energy, and keeps its own (energy conserved either way).
TEST(IceExchange, AnEmbeddedTraceFollowsTheSolidsCoolingButNotBelowZeroKelvin) {
  for (const double airT : {300.0, 0.05}) {
    const auto solver = airTraceInSteel(0.0);
    ice::IceSolver& sol = *solver;
    const auto& owned = sol.ownedBox();
    const std::size_t n = static_cast<std::size_t>(owned.numPts());
    const double cvSteel = 450.0;
    auto& air = sol.state().mat[0];
    const double cvAir = air.eos->cv();
    core::forEach(owned, [&](int i, int j, int k) {  // the air at airT, no change of its own this step
      air.eint(i, j, k) = cvAir * airT;
      air.eintStart(i, j, k) = cvAir * airT;
      air.tempCycle(i, j, k) = airT;  // as the step found it (before the equilibrium pressure)
    });
    std::vector<double> E(n), mom(3 * n, 0.0);
    const auto& steel = sol.state().mat[1];
    core::forEach(owned, [&](int i, int j, int k) {
      const auto q = static_cast<std::size_t>(owned.index(i, j, k));
      E[q] = steel.mass(i, j, k) * (steel.eint(i, j, k) - cvSteel * 0.1);  // the steel cooled by 0.1 K
    });
    sol.setExternalLagrangianMomentum(1, mom);
    sol.setExternalLagrangianEnergy(1, E);
    sol.exchange();
    core::forEach(owned, [&](int i, int j, int k) {
      const double Tair = air.eint(i, j, k) / cvAir, ma = air.mass(i, j, k);
      EXPECT_LT(ma, 1e-8 * steel.mass(i, j, k)) << "cell " << i << ": air is a trace";
      EXPECT_GT(Tair, 0.0) << "air at " << airT << " K, cell " << i;
      if (airT > 1) {
        EXPECT_NEAR(Tair, airT - 0.1, 1e-3) << "cell " << i << ": the trace follows the steel's cooling (w ~ 1)";
      } else {
        EXPECT_EQ(Tair, airT) << "cell " << i << ": a change to below 0 K is not taken";
      }
      // The heat the air took came from the steel.
      const double airHeat = ma * cvAir * (Tair - airT);
      EXPECT_NEAR(sol.exchangeEnergy(1)(i, j, k) + airHeat, 0.0, 1e-12 * std::abs(airHeat) + 1e-30) << "cell " << i;
    });
  }
}

// A liquid that is a real phase of a solid's cell keeps its own adiabat over the whole step: the
// embedded-fluid rule (trace_temperature.cpp) measures its temperature change from where the step
// found it, before the equilibrium pressure moved its volume at fixed energy. For a stiffened gas
// (T = (e - p_inf v) / cv) that volume change moves its temperature by p_inf dv / cv, which the
// Lagrangian phase's expansion back, with work, takes away again: over the cycle the liquid
// changed by -p dv / cv only. Measured over the Lagrangian phase alone (as before 7 Dec 2026) the
// rule saw -(p + p_inf) dv / cv and paid the liquid that from the solid, every step: in the
// layered column's mixed cells (tests/verification/coupled) 55,700 J of the polymer's heat in
// 20 us. Here a polymer-like solid (K 2.78 GPa, 1180 kg/m^3) fills 0.8 of each cell, silicone the
// rest at 50 MPa (the filled lattices' materials); the step finds the silicone 1e-4 above its
// equilibrium volume (0.1 %), the equilibrium takes that back, and its Lagrangian phase is set to the
// adiabatic expansion to the found volume: the solid may pay at most the cycle's own work, m p dv
// (measured 0.25 times it; before, 4.3 times), and the silicone ends between its found temperature
// less p dv / cv and its found temperature (-0.026 K, the cycle's -0.034 K moved part way to the
// solid's 0; before, +0.113 K).
TEST(IceExchange, AnEmbeddedLiquidKeepsItsOwnAdiabatOverTheWholeStep) {
  core::Scene s;
  s.name = "liquid_in_polymer";
  s.mesh = core::Mesh(1, {0, 0, 0}, {0.1, 1, 1}, {4, 1, 1});
  for (auto& b : s.boundary) b.type = core::BoundaryType::Periodic;
  core::MaterialSpec polymer = test::externalSteel();
  polymer.name = "polymer";
  polymer.eos.params = {{"bulk_modulus", 2.78e9}, {"threshold_pressure", 5e7}, {"reference_density", 1180}};
  polymer.specific_heat = 1500;
  s.materials = {test::stiffenedGas("silicone", 1.62, 548765432.0987654, 1500.0), polymer};
  s.geometry = {test::region("silicone", test::box({0, 0, 0}, {1, 1, 1}), {{"silicone", 1.0}}, 5e7, 970.0)};
  s.ice.exchange_momentum = 1e15;
  ice::IceSolver sol(s, test::comm());
  const auto& owned = sol.ownedBox();
  const std::size_t n = static_cast<std::size_t>(owned.numPts());
  const double V = sol.mesh().cellVolume(), v0 = 1.0 / 1180.0;
  std::vector<double> mass(n, 0.8 * V / v0), vel(3 * n, 0.0), T(n, 300.0), sv(n, v0);
  sol.setExternalMaterialState(1, mass, vel, T, sv);
  sol.fitFluidsToExternalVolume();
  sol.computeEquilibriumPressure();
  auto& liq = sol.state().mat[0];
  const auto& eos = *liq.eos;
  const double veq = liq.spvol(0, 0, 0), dv = 1e-3 * veq, e0 = liq.eint(0, 0, 0), p = sol.pressure()(0, 0, 0);
  ASSERT_GT(liq.theta(0, 0, 0), 0.15) << "the silicone is a real phase of the cell";
  core::forEach(owned, [&](int i, int j, int k) { liq.spvol(i, j, k) = veq + dv; });  // as the step found it
  const double Tfound = eos.temperature(1.0 / (veq + dv), e0);
  sol.computeEquilibriumPressure();  // back to veq at e0: the cold energy's share warms it
  EXPECT_NEAR(liq.spvol(0, 0, 0), veq, 1e-9 * veq);
  EXPECT_GT(eos.temperature(1.0 / veq, e0) - Tfound, 0.3) << "the equilibrium's fixed-energy compression";
  toFacePressure(sol, 1e-8);
  sol.computeSourcesAndLagrangian();  // at rest: no volume change of its own
  const double eL = e0 - p * dv;      // the Lagrangian expansion back to the found volume, with work
  core::forEach(owned, [&](int i, int j, int k) {
    liq.lagSpvol()(i, j, k) = veq + dv;
    liq.eint(i, j, k) = eL;
  });
  const auto& solid = sol.state().mat[1];
  std::vector<double> E(n), mom(3 * n, 0.0);
  core::forEach(owned, [&](int i, int j, int k) {
    E[static_cast<std::size_t>(owned.index(i, j, k))] = solid.mass(i, j, k) * solid.eint(i, j, k);  // no change
  });
  sol.setExternalLagrangianMomentum(1, mom);
  sol.setExternalLagrangianEnergy(1, E);
  sol.exchange();
  core::forEach(owned, [&](int i, int j, int k) {
    const double m = liq.mass(i, j, k), Tend = eos.temperature(1.0 / (veq + dv), liq.eint(i, j, k));
    const double cycle = p * dv / eos.cv();  // the cycle's own cooling [K]
    EXPECT_LT(std::abs(sol.exchangeEnergy(1)(i, j, k)), m * p * dv) << "cell " << i << ": the solid pays at most the cycle's work";
    EXPECT_GE(Tend, Tfound - cycle - 1e-9) << "cell " << i;
    EXPECT_LE(Tend, Tfound + 1e-9) << "cell " << i << ": found at " << Tfound << " K";
    // Energy conserved: what the silicone took, the solid gave.
    EXPECT_NEAR(sol.exchangeEnergy(1)(i, j, k) + m * (liq.eint(i, j, k) - eL), 0.0, 1e-9 * m * p * dv) << "cell " << i;
  });
}

namespace {
// Air (mu = 0.01 Pa s, 1.2 kg/m^3, 1e5 Pa, cv 717.5) on 16 x 1 cells of the unit square, periodic, or
// with no-slip walls at x = 0 and 1; the shear tests set u_y.
core::Scene viscousAirStrip(const char* name, double end, bool walls = false) {
  core::Scene s;
  s.name = name;
  const int n = 16;
  s.mesh = core::Mesh(2, {0, 0, 0}, {1.0 / n, 1.0 / n, 1}, {n, 1, 1});
  for (auto& b : s.boundary) b.type = core::BoundaryType::Periodic;
  if (walls) s.boundary[0].type = s.boundary[1].type = core::BoundaryType::NoSlipWall;
  s.time.end = end;
  s.materials = {test::idealGas("air", 1.4, 717.5)};
  s.materials[0].viscosity = 0.01;
  s.geometry = {test::region("air", test::box({0, 0, 0}, {1, 1, 1}), {{"air", 1.0}}, 1e5, 1.2)};
  return s;
}
}  // namespace

// Viscosity: a shear wave u_y = U sin(2 pi x) in a periodic box decays as exp(-nu k^2 t).
TEST(IceViscosity, ShearWaveDecaysAtTheViscousRate) {
  const core::Scene s = viscousAirStrip("shear_wave", 0.25);
  const int n = 16;
  ice::IceSolver sol(s, test::comm());
  const double k = 2 * M_PI;
  core::forEach(sol.ownedBox(), [&](int i, int j, int kk) {
    sol.state().mat[0].vel(i, j, kk, 1) = std::sin(k * sol.mesh().cellCenter(0, i));
  });
  sol.computeEquilibriumPressure();
  test::runToEnd(sol, s.time.end);
  double num = 0, den = 0;  // projection on sin(k x)
  core::forEach(sol.ownedBox(), [&](int i, int j, int kk) {
    const double sx = std::sin(k * sol.mesh().cellCenter(0, i));
    num += sol.state().mat[0].vel(i, j, kk, 1) * sx;
    den += sx * sx;
  });
  const double amp = test::comm().sum(num) / test::comm().sum(den);
  // Discrete rate: the 3-point Laplacian's eigenvalue 4 sin^2(k dx / 2) / dx^2.
  const double dx = 1.0 / n, nu = 0.01 / 1.2;
  const double exact = std::exp(-nu * 4 * std::pow(std::sin(k * dx / 2), 2) / (dx * dx) * s.time.end);
  std::printf("  amplitude %.6f, exact (discrete Laplacian) %.6f, continuous %.6f\n", amp, exact,
              std::exp(-nu * k * k * s.time.end));
  EXPECT_NEAR(amp, exact, 1e-3 * exact);
}

// Viscous heating: the kinetic energy a shear wave loses becomes heat where the shear is, and the
// total energy is conserved. u_y = U sin(k x) in a periodic box (U = 20 m/s: the heat is 7e-5 of the
// total energy, 1e9 times its round-off here): the kinetic energy decays at twice the velocity's
// discrete rate; the internal energy takes what it loses to round-off; the entropy rises as the
// discrete dissipation's pattern, each cell half of its two faces' nu (du / dx)^2 ~ cos^2(k x_face):
// mean + cos(k dx) of it in cos(2 k x).
TEST(IceViscosity, ShearWaveHeatsTheGasByTheKineticEnergyItLoses) {
  const core::Scene s = viscousAirStrip("shear_wave_heat", 0.25);
  const int n = 16;
  const double U = 20.0, mu = 0.01, rho = 1.2, cv = 717.5;
  ice::IceSolver sol(s, test::comm());
  const double k = 2 * M_PI;
  core::forEach(sol.ownedBox(), [&](int i, int j, int kk) {
    sol.state().mat[0].vel(i, j, kk, 1) = U * std::sin(k * sol.mesh().cellCenter(0, i));
  });
  sol.computeEquilibriumPressure();
  const auto& air = sol.state().mat[0];
  auto entropy = [&](int i, int j, int kk) {  // ideal gas: cv ln(T / rho^(gamma - 1))
    const double r = air.mass(i, j, kk) / sol.mesh().cellVolume();
    return cv * std::log(air.eos->temperature(r, air.eint(i, j, kk)) / std::pow(r, 0.4));
  };
  std::vector<double> s0(static_cast<std::size_t>(sol.ownedBox().numPts()));
  core::forEach(sol.ownedBox(), [&](int i, int j, int kk) {
    s0[static_cast<std::size_t>(sol.ownedBox().index(i, j, kk))] = entropy(i, j, kk);
  });
  const ice::Totals a = sol.totals();
  test::runToEnd(sol, s.time.end);
  const ice::Totals b = sol.totals();
  const double dx = 1.0 / n, nu = mu / rho;
  const double rate = nu * 4 * std::pow(std::sin(k * dx / 2), 2) / (dx * dx);
  const double lost = a.kinetic - b.kinetic;
  std::printf("  kinetic %.9e -> %.9e (exact decay %.9e), internal +%.9e, total %.12e -> %.12e\n", a.kinetic,
              b.kinetic, a.kinetic * std::exp(-2 * rate * s.time.end), (b.energy - b.kinetic) - (a.energy - a.kinetic),
              a.energy, b.energy);
  EXPECT_NEAR(b.kinetic, a.kinetic * std::exp(-2 * rate * s.time.end), 2e-3 * lost);
  EXPECT_NEAR(b.energy, a.energy, 1e-6 * lost) << "total energy conserved (the loss was " << lost << " J)";
  EXPECT_NEAR((b.energy - b.kinetic) - (a.energy - a.kinetic), lost, 1e-6 * lost) << "the heat is the kinetic energy lost";
  double mean = 0, c2 = 0, s2 = 0, ds = HUGE_VAL;  // entropy change: mean, its cos(2kx) part, smallest
  core::forEach(sol.ownedBox(), [&](int i, int j, int kk) {
    const double d = entropy(i, j, kk) - s0[static_cast<std::size_t>(sol.ownedBox().index(i, j, kk))];
    const double cx = std::cos(2 * k * sol.mesh().cellCenter(0, i));
    mean += d;
    c2 += d * cx;
    s2 += cx * cx;
    ds = std::min(ds, d);
  });
  mean = test::comm().sum(mean) / n;
  c2 = test::comm().sum(c2) / test::comm().sum(s2);
  std::printf("  entropy rise: mean %.6e J/(kg K), cos(2kx) part %.6e (ratio %.4f, expected cos(k dx) %.4f)\n", mean,
              c2, c2 / mean, std::cos(k * dx));
  EXPECT_GE(test::comm().min(ds), 0.0) << "no cell loses entropy";
  EXPECT_NEAR(c2 / mean, std::cos(k * dx), 0.02);
}

// The same between no-slip walls (u_y = U sin(pi x), x = 0 and 1 walls): a wall at rest does no
// work, so the heat is again exactly the kinetic energy lost (the wall faces' shear included).
TEST(IceViscosity, NoSlipWallsAtRestDoNoWork) {
  const core::Scene s = viscousAirStrip("shear_walls", 0.1, true);
  ice::IceSolver sol(s, test::comm());
  core::forEach(sol.ownedBox(), [&](int i, int j, int kk) {
    sol.state().mat[0].vel(i, j, kk, 1) = 20.0 * std::sin(M_PI * sol.mesh().cellCenter(0, i));
  });
  sol.computeEquilibriumPressure();
  const ice::Totals a = sol.totals();
  test::runToEnd(sol, s.time.end);
  const ice::Totals b = sol.totals();
  const double lost = a.kinetic - b.kinetic;
  std::printf("  kinetic lost %.9e J, internal +%.9e J, total change %.3e J\n", lost,
              (b.energy - b.kinetic) - (a.energy - a.kinetic), b.energy - a.energy);
  ASSERT_GT(lost, 0.01 * a.kinetic) << "the walls and the viscosity slow the flow (1.6 % by 0.1 s)";
  EXPECT_NEAR(b.energy, a.energy, 1e-6 * lost) << "total energy conserved";
}

// The semi-implicit pressure with Eigen's BiCGSTAB gives the matrix-free CG's solution.
TEST(IceSemiImplicit, BicgstabMatchesCg) {
  const test::Primitive L{1, 0, 1}, R{0.125, 0, 0.1};
  core::Scene a = test::shockTube(200, L, R, 0.5, 0.2, {"second_order", "semi_implicit"});
  a.ice.solver_tolerance = 1e-13;
  core::Scene b = a;
  b.ice.linear_solver = "bicgstab";
  ice::IceSolver sa(a, test::comm()), sb(b, test::comm());
  test::runToEnd(sa, 0.2);
  test::runToEnd(sb, 0.2);
  double diff = 0;
  core::forEach(sa.ownedBox(), [&](int i, int j, int k) {
    diff = std::max(diff, std::abs(sa.density(0, i, j, k) - sb.density(0, i, j, k)));
  });
  EXPECT_EQ(sa.steps(), sb.steps());
  EXPECT_LT(diff, 1e-9);
}

// Heat conduction: a temperature wave at uniform pressure decays at the constant-pressure rate
// k / (rho cp) (not k / (rho cv): the acoustic time is 100 times shorter than the diffusion time,
// so the gas expands as it heats); total energy is conserved.
TEST(IceConduction, TemperatureWaveDecaysAndEnergyIsConserved) {
  core::Scene s;
  s.name = "thermal_wave";
  const int n = 16;
  const double L = 0.01;
  s.mesh = core::Mesh(1, {0, 0, 0}, {L / n, 1, 1}, {n, 1, 1});
  for (auto& b : s.boundary) b.type = core::BoundaryType::Periodic;
  s.time.end = 1.5e-3;
  s.materials = {test::idealGas("air", 1.4, 717.5)};
  s.materials[0].thermal_conductivity = 1.0;
  s.geometry = {test::region("air", test::box({0, 0, 0}, {1, 1, 1}), {{"air", 1.0}}, 1e5, 1.2)};
  ice::IceSolver sol(s, test::comm());
  const double k = 2 * M_PI / L, V = sol.mesh().cellVolume();
  core::forEach(sol.ownedBox(), [&](int i, int j, int kk) {  // T = T0 (1 + 0.01 sin kx) at p = 1e5
    auto& m = sol.state().mat[0];
    const double fac = 1.0 + 0.01 * std::sin(k * sol.mesh().cellCenter(0, i));
    m.eint(i, j, kk) *= fac;
    m.mass(i, j, kk) = 1.2 / fac * V;
  });
  sol.computeEquilibriumPressure();
  const double e0 = sol.totals().energy;
  auto amplitude = [&]() {
    double num = 0, den = 0;
    core::forEach(sol.ownedBox(), [&](int i, int j, int kk) {
      const auto& m = sol.state().mat[0];
      const double sx = std::sin(k * sol.mesh().cellCenter(0, i));
      num += m.eos->temperature(1.0 / m.spvol(i, j, kk), m.eint(i, j, kk)) * sx;
      den += sx * sx;
    });
    return test::comm().sum(num) / test::comm().sum(den);
  };
  const double a0 = amplitude();
  test::runToEnd(sol, s.time.end);
  const double ratio = amplitude() / a0;
  const double dx = L / n, lap = 4 * std::pow(std::sin(k * dx / 2), 2) / (dx * dx);
  const double rateV = 1.0 / (1.2 * 717.5) * lap, rateP = 1.0 / (1.2 * 1004.5) * lap;
  std::printf("  amplitude ratio %.4f; constant-volume %.4f, constant-pressure %.4f\n", ratio,
              std::exp(-rateV * s.time.end), std::exp(-rateP * s.time.end));
  EXPECT_NEAR(ratio, std::exp(-rateP * s.time.end), 2e-3);  // measured 0.6156 against 0.6157
  EXPECT_NEAR(sol.totals().energy, e0, 1e-12 * e0);
}

// Gravity: a periodic box falls freely: every velocity is g t, the pressure stays uniform.
TEST(IceGravity, PeriodicBoxFallsFreely) {
  core::Scene s;
  s.name = "free_fall";
  s.mesh = core::Mesh(2, {0, 0, 0}, {0.1, 0.1, 1}, {8, 8, 1});
  for (auto& b : s.boundary) b.type = core::BoundaryType::Periodic;
  s.time.end = 0.01;
  s.gravity = {0, -9.81, 0};
  s.materials = {test::idealGas("air"), test::stiffenedGas("water", 4.4, 6e8)};
  s.geometry = {test::region("air", test::box({0, 0, 0}, {1, 1, 1}), {{"air", 1.0}}, 1e5, 1.2),
                test::region("drop", test::box({0.3, 0.3, 0}, {0.5, 0.6, 1}), {{"water", 1.0}}, 1e5, 1000)};
  ice::IceSolver sol(s, test::comm());
  test::runToEnd(sol, s.time.end);
  double du = 0, dp = 0;
  core::forEach(sol.ownedBox(), [&](int i, int j, int k) {
    dp = std::max(dp, std::abs(sol.pressure()(i, j, k) - 1e5) / 1e5);
    for (int r = 0; r < 2; ++r)
      if (sol.state().mat[r].mass(i, j, k) > 0) du = std::max(du, std::abs(sol.state().mat[r].vel(i, j, k, 1) + 9.81 * 0.01));
  });
  EXPECT_LT(du, 1e-10);
  EXPECT_LT(dp, 1e-10);
}
