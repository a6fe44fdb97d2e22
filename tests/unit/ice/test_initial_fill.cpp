// A fluid region fills the cells it cuts by its share of their volume (initial_regions.h
// cellShares, kFillSamples sub-cell points per direction, Uintah's way), not all or nothing by the
// cell's centre: the underwater scenes' charge, its box faces on cell centres at 4 mm, held 25 %
// more products than its box when a cell went to the region holding its centre.
#include <gtest/gtest.h>

#include <cmath>

#include "../../verification/ice/ice_test_scenes.h"
#include "ice/ice_constants.h"
#include "test_comm.h"

using namespace mpmice;

namespace {

// 1D [0, 1] in n cells: light gas everywhere, heavy gas in [a, b], both at 1e5 Pa.
core::Scene twoGases(int n, double a, double b) {
  core::Scene s = test::shockTube(n, {1, 0, 1e5}, {1, 0, 1e5}, 0.5, 1.0);
  s.materials = {test::idealGas("light"), test::idealGas("heavy", 1.4, 300.0)};
  s.geometry = {test::region("light", test::box({0, -1, -1}, {1, 2, 2}), {{"light", 1.0}}, 1e5, 1.2),
                test::region("heavy", test::box({a, -1, -1}, {b, 2, 2}), {{"heavy", 1.0}}, 1e5, 8.0)};
  return s;
}

double sumOver(const ice::IceSolver& s, int m, bool volume) {
  double sum = 0;
  const double V = s.mesh().cellVolume();
  core::forEach(s.ownedBox(), [&](int i, int j, int k) {
    sum += volume ? s.state().mat[m].theta(i, j, k) * V : s.state().mat[m].mass(i, j, k);
  });
  return s.comm().sum(sum);
}

}  // namespace

TEST(IceInitialFill, ARegionCuttingCellsHoldsItsShapesVolume) {
  // Faces at 0.23 and 0.61 of 0.1 m cells: by centres the region held 0.4 m (+5 %); by shares
  // 0.375 m (the samples' 1/16 of a cell at each face), its mass with it.
  const ice::IceSolver s(twoGases(10, 0.23, 0.61), test::comm());
  const double h = 0.1 / (2 * ice::kFillSamples);
  EXPECT_NEAR(sumOver(s, 1, true), 0.38, 2 * h);
  EXPECT_NEAR(sumOver(s, 0, true), 0.62, 2 * h);
  EXPECT_NEAR(sumOver(s, 1, false), 8.0 * sumOver(s, 1, true), 1e-12);
  EXPECT_NEAR(sumOver(s, 0, false), 1.2 * sumOver(s, 0, true), 1e-12);
  // The cut cells hold both gases at the one pressure; the cells inside one region, one gas.
  if (s.ownedBox().contains(2, 0, 0)) {
    EXPECT_NEAR(s.state().mat[1].theta(2, 0, 0), 0.75, 1e-12);  // 6 of 8 samples above 0.23
    EXPECT_NEAR(s.state().mat[0].theta(2, 0, 0), 0.25, 1e-12);
    EXPECT_NEAR(s.pressure()(2, 0, 0), 1e5, 1e-6 * 1e5);
  }
  if (s.ownedBox().contains(4, 0, 0)) {
    EXPECT_EQ(s.state().mat[0].theta(4, 0, 0), 0.0);
  }
}

TEST(IceInitialFill, AContactOnACellCentreSplitsThatCellsMassAndEnergy) {
  // Sod's states with the contact at 0.55 on 10 cells: cell 5 holds half of each.
  const ice::IceSolver s(test::shockTube(10, {1, 0, 1}, {0.125, 0, 0.1}, 0.55, 0.2), test::comm());
  const ice::Totals t = s.totals();
  EXPECT_NEAR(t.mass, 0.55 * 1.0 + 0.45 * 0.125, 1e-12);
  EXPECT_NEAR(t.energy, (0.55 * 1.0 + 0.45 * 0.1) / 0.4, 1e-10);  // p / (gamma - 1) per unit length
}

TEST(IceInitialFill, PointsInASolidDoNotDiluteTheRegionBesideIt) {
  // Air everywhere, water in [0, 0.37], a steel block on [0.37, 0.6] declared last. Cell 3 (0.3 ..
  // 0.4, centre in the water) has 6 samples in the water and 2 in the steel: its fluid is water
  // alone (the steel's part arrives from the solid), not 1/4 air.
  core::Scene s = twoGases(10, 0.0, 0.37);
  s.materials.push_back(test::externalSteel());
  core::RegionSpec block;
  block.name = "block";
  block.shape = test::box({0.37, -1, -1}, {0.6, 2, 2});
  block.fill = {{"steel", 1.0}};
  s.geometry.push_back(block);
  const ice::IceSolver sol(s, test::comm());
  if (sol.ownedBox().contains(3, 0, 0)) {
    EXPECT_NEAR(sol.state().mat[1].theta(3, 0, 0), 1.0, 1e-12);
    EXPECT_EQ(sol.state().mat[0].mass(3, 0, 0), 0.0);
  }
  if (sol.ownedBox().contains(4, 0, 0)) {  // centre in the steel: traces only
    EXPECT_LT(sol.state().mat[1].mass(4, 0, 0), 1e-9);
  }
}

TEST(IceInitialFill, ADiskHoldsItsAreaOnACoarseMesh) {
  // A water disk of radius 0.3 in air, 2D, 10 x 10 cells of 0.1 m: by centres 0.32 m^2 (+13 %
  // against pi 0.09 = 0.2827); by shares within 1 %.
  core::Scene s = twoGases(10, 0, 0);
  s.mesh = core::Mesh(2, {0, 0, 0}, {0.1, 0.1, 1}, {10, 10, 1});
  core::ShapeSpec disk;
  disk.type = "circle";
  disk.center = {0.5, 0.5, 0};
  disk.radius = 0.3;
  s.geometry[1].shape = disk;
  const ice::IceSolver sol(s, test::comm());
  EXPECT_NEAR(sumOver(sol, 1, true) / (M_PI * 0.09), 1.0, 0.01);
}

TEST(IceInitialFill, ASharedCellKeepsTheRegionsMomentumAndTotalEnergy) {
  // One gas: at rest, 1.2 kg/m^3 on [0, 1]; a jet of it at 100 m/s, 8 kg/m^3 on [0.225, 0.6125],
  // both at 1e5 Pa. The faces fall between sub-cell samples, so the shares are exact (cell 2: 3/4
  // jet, cell 6: 1/8): the cells hold the drawn mass, momentum and total energy (the kinetic
  // energy the mass-weighted velocity of a shared cell does not carry is its internal energy,
  // as when the two streams mix), and a shared cell moves at the mass-weighted velocity.
  core::Scene s = twoGases(10, 0.225, 0.6125);
  s.materials = {test::idealGas("gas")};
  s.geometry[0].fill = {{"gas", 1.0}};
  s.geometry[1].fill = {{"gas", 1.0}};
  s.geometry[1].velocity = {100, 0, 0};
  const ice::IceSolver sol(s, test::comm());
  const ice::Totals t = sol.totals();
  const double L = 0.6125 - 0.225;
  EXPECT_NEAR(t.mass, 1.2 * (1 - L) + 8.0 * L, 1e-12);
  EXPECT_NEAR(t.momentum[0], 8.0 * L * 100.0, 1e-9);
  EXPECT_NEAR(t.energy, 1e5 / 0.4 + 0.5 * 8.0 * L * 1e4, 1e-6);
  if (sol.ownedBox().contains(2, 0, 0)) {
    const double mj = 8.0 * 0.75, mr = 1.2 * 0.25;
    EXPECT_NEAR(sol.state().mat[0].vel(2, 0, 0, 0), 100.0 * mj / (mj + mr), 1e-9);
  }
}
