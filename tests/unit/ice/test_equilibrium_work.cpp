// ice.equilibrium: with_work (src/ice/pressure/equilibrium_work.cpp, docs/ice.md "Equilibrium with
// work"): a mixed cell out of pressure equilibrium (hot water beside air) relaxes to the pressure
// where each fluid has done the work p (v - v0) of its volume change from the volume it carried,
// e = e0 - p (v - v0). For a stiffened gas (ideal gas: p_inf = 0) that state has a closed form,
//   v(p) = (gamma - 1) (e0 + p v0) / (gamma (p + p_inf)),
// and the cell's pressure is the root of sum_r m_r v_r(p) = V, found here by bisection: the solver
// must reach it, keep the fluids' energy to round-off, and leave cells already in equilibrium and
// the default (fixed_energy) path untouched.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "../../verification/ice/ice_test_scenes.h"
#include "ice/solver/ice_solver.h"
#include "test_comm.h"

using namespace mpmice;

namespace {

struct Law {
  double gamma, pinf;
};
const Law kWater{4.4, 6e8}, kAir{1.4, 0};

// Water with 1 % of the volume air: hot water's expansion compresses the air strongly.
core::Scene mixScene(const std::string& equilibrium) {
  core::Scene s;
  s.name = "water_air_mix";
  s.mesh = core::Mesh(1, {0, 0, 0}, {0.1, 1, 1}, {10, 1, 1});
  for (auto& b : s.boundary) b.type = core::BoundaryType::Outflow;
  s.time.end = 1.0;
  s.materials = {test::stiffenedGas("water", kWater.gamma, kWater.pinf), test::idealGas("air")};
  s.geometry = {test::region("mix", test::box({0, 0, 0}, {1, 1, 1}), {{"water", 0.99}, {"air", 0.01}}, 1e5, 990)};
  s.ice.equilibrium = equilibrium;
  return s;
}

// The state of one cell: masses, carried specific volumes and energies of water (0) and air (1).
struct CellState {
  double m[2], v0[2], e0[2];
};

CellState read(const ice::IceSolver& sol, int i) {
  CellState c{};
  for (int r = 0; r < 2; ++r) {
    const auto& M = sol.state().mat[r];
    c.m[r] = M.mass(i, 0, 0), c.v0[r] = M.spvol(i, 0, 0), c.e0[r] = M.eint(i, 0, 0);
  }
  return c;
}

double workVolume(const Law& L, double e0, double v0, double p) {
  return (L.gamma - 1) * (e0 + p * v0) / (L.gamma * (p + L.pinf));
}

// The exact pressure with work: sum_r m_r v_r(p) = V (every v_r decreases with p).
double exactPressure(const CellState& c, double V) {
  auto excess = [&](double p) {
    return c.m[0] * workVolume(kWater, c.e0[0], c.v0[0], p) + c.m[1] * workVolume(kAir, c.e0[1], c.v0[1], p) - V;
  };
  double lo = 1.0, hi = 1e12;
  for (int k = 0; k < 200; ++k) {
    const double mid = std::sqrt(lo * hi);
    (excess(mid) > 0 ? lo : hi) = mid;
  }
  return std::sqrt(lo * hi);
}

}  // namespace

TEST(IceEquilibriumWork, HotWaterBesideAirReachesTheClosedFormWithWork) {
  ice::IceSolver sol(mixScene("with_work"), test::comm());
  const double V = sol.mesh().cellVolume();
  sol.state().mat[0].eint(4, 0, 0) *= 1.02;  // hot water in cell 4: its own pressure far above the air's
  const CellState before = read(sol, 4), neighbour = read(sol, 5);
  ASSERT_NEAR(before.m[0] * before.v0[0] + before.m[1] * before.v0[1], V, 1e-12 * V);  // carried volumes fill it
  const double pExact = exactPressure(before, V);
  sol.computeEquilibriumPressure();
  const double p = sol.pressure()(4, 0, 0);
  EXPECT_NEAR(p, pExact, 1e-8 * pExact);
  EXPECT_GT(p, 1e6);  // the relaxation is strong: the test is not a cell at rest
  const Law laws[2] = {kWater, kAir};
  double energyBefore = 0, energyAfter = 0;
  for (int r = 0; r < 2; ++r) {
    const auto& M = sol.state().mat[r];
    const double v = M.spvol(4, 0, 0), e = M.eint(4, 0, 0);
    EXPECT_NEAR(v, workVolume(laws[r], before.e0[r], before.v0[r], p), 1e-8 * v) << M.name;
    EXPECT_NEAR(e, before.e0[r] - p * (v - before.v0[r]), 1e-8 * std::abs(before.e0[r])) << M.name;
    energyBefore += before.m[r] * before.e0[r];
    energyAfter += M.mass(4, 0, 0) * e;
  }
  EXPECT_NEAR(energyAfter, energyBefore, 1e-13 * energyBefore);
  // The air was compressed and heated, the water expanded and cooled.
  EXPECT_GT(sol.state().mat[1].eint(4, 0, 0), before.e0[1]);
  EXPECT_LT(sol.state().mat[0].eint(4, 0, 0), before.e0[0]);
  // A neighbour already in equilibrium keeps its energies to round-off.
  for (int r = 0; r < 2; ++r)
    EXPECT_NEAR(sol.state().mat[r].eint(5, 0, 0), neighbour.e0[r], 1e-12 * neighbour.e0[r]);
}

TEST(IceEquilibriumWork, FixedEnergyKeepsEveryEnergy) {
  ice::IceSolver sol(mixScene("fixed_energy"), test::comm());
  sol.state().mat[0].eint(4, 0, 0) *= 1.02;
  const CellState before = read(sol, 4);
  sol.computeEquilibriumPressure();
  for (int r = 0; r < 2; ++r) EXPECT_EQ(sol.state().mat[r].eint(4, 0, 0), before.e0[r]);
  // Without work the air is compressed further than with it (it is not heated by the compression).
  ice::IceSolver withWork(mixScene("with_work"), test::comm());
  withWork.state().mat[0].eint(4, 0, 0) *= 1.02;
  withWork.computeEquilibriumPressure();
  EXPECT_LT(sol.state().mat[1].spvol(4, 0, 0), withWork.state().mat[1].spvol(4, 0, 0));
}

TEST(IceEquilibriumWork, AnUnknownChoiceIsAnErrorNamingTheKey) {
  try {
    ice::IceSolver sol(mixScene("isentropic"), test::comm());
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("ice.equilibrium"), std::string::npos) << msg;
    EXPECT_NE(msg.find("fixed_energy, with_work"), std::string::npos) << msg;
  }
}
