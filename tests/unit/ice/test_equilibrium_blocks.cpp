// The equilibrium pressure solves the cells in blocks (scratch of a block's size, not the mesh's).
// Each cell's iteration is its own, so the blocks must not change anything: several thousand cells
// (more than two blocks, at scattered indices as in a stored box with ghosts) of stiffened-gas water
// and ideal-gas air, some with a trace of air held by the trace rule, some without any admissible
// state, solved at once give bit for bit the pressures, micro densities, iteration counts, held
// traces and failures of the same cells solved one at a time.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "../../verification/ice/ice_test_scenes.h"
#include "ice/eos/eos.h"
#include "ice/pressure/equilibrium_pressure.h"

using namespace mpmice;

namespace {

struct Cells {
  std::vector<std::int64_t> list;
  std::vector<double> rho[2], e[2], carried[2];
};

// Cell a at index 3 a + 7 (the others are never read); material 0 water, 1 air, in equilibrium
// at p* from 5e4 to 5e5 Pa (m_r / V = theta_r rho_r(p*, e_r)). Every 37th cell holds a trace of air
// whose carried state's own pressure is 2 p* (held) or p* / 2 (not held); every 211th has air
// without an admissible state (e < 0).
Cells makeCells(std::size_t n, const ice::Eos& water, const ice::Eos& air) {
  Cells c;
  const std::size_t size = 3 * n + 10;
  for (int r = 0; r < 2; ++r) {
    c.rho[r].assign(size, 0.0);
    c.e[r].assign(size, 0.0);
    c.carried[r].assign(size, 0.0);
  }
  for (std::size_t a = 0; a < n; ++a) {
    const auto i = static_cast<std::size_t>(3 * a + 7);
    c.list.push_back(static_cast<std::int64_t>(i));
    const double x = static_cast<double>(a), s = x / static_cast<double>(n);
    const double pStar = 5e4 + 4.5e5 * (0.5 + 0.5 * std::sin(3.0 * x));
    double thW = 1e-3 + 0.998 * s, thA = 1.0 - thW;
    const bool trace = a % 37 == 0;
    if (trace) thA = 1e-9, thW = 1.0 - thA;
    c.e[0][i] = water.internalEnergy(1000.0 + 10.0 * std::cos(5.0 * x), 1e5);
    c.e[1][i] = 717.5 * (250.0 + 200.0 * s);
    c.rho[0][i] = thW * water.density(pStar, c.e[0][i]);
    c.rho[1][i] = thA * air.density(pStar, c.e[1][i]);
    c.carried[0][i] = 1.0 / water.density(pStar, c.e[0][i]);
    c.carried[1][i] = 1.0 / air.density((a % 2 ? 2.0 : 0.5) * pStar, c.e[1][i]);
    if (a % 211 == 0) c.e[1][i] = -1.0;
  }
  return c;
}

struct Result {
  std::vector<double> p, rm0, rm1;
  std::vector<int> iters;
  std::vector<std::pair<int, std::int64_t>> held;
  std::vector<std::int64_t> failed;
};

Result solve(ice::EquilibriumPressure& eq, const Cells& c, bool oneByOne) {
  Result out;
  const std::size_t size = c.rho[0].size();
  out.p.assign(size, 1e5);
  out.rm0.assign(size, 0.0);
  out.rm1.assign(size, 0.0);
  out.iters.assign(size, -1);
  const std::vector<const double*> rho = {c.rho[0].data(), c.rho[1].data()}, e = {c.e[0].data(), c.e[1].data()},
                                   carried = {c.carried[0].data(), c.carried[1].data()};
  const std::vector<double*> rm = {out.rm0.data(), out.rm1.data()};
  auto run = [&](const std::vector<std::int64_t>& cells) {
    for (const auto& f : eq.solve(cells, rho, e, out.p.data(), rm, out.iters.data(), &carried))
      out.failed.push_back(f.cell);
    const auto& h = eq.heldTraces();
    out.held.insert(out.held.end(), h.begin(), h.end());
  };
  if (oneByOne) {
    for (const std::int64_t cell : c.list) run({cell});
  } else {
    run(c.list);
  }
  std::sort(out.held.begin(), out.held.end());
  std::sort(out.failed.begin(), out.failed.end());
  return out;
}

TEST(IceEquilibriumBlocks, BlocksGiveTheCellByCellResultBitForBit) {
  const auto water = ice::makeEos(test::modelSpec("stiffened_gas", {{"gamma", 4.4}, {"p_inf", 6e8}}), 4186);
  const auto air = ice::makeEos(test::modelSpec("ideal_gas", {{"gamma", 1.4}}), 717.5);
  ice::EquilibriumPressure eq({water.get(), air.get()}, 1e-11, 100, {true, true}, 1e-4);
  const Cells cells = makeCells(2600, *water, *air);  // three blocks of 1024, the last one partial
  const Result all = solve(eq, cells, false), one = solve(eq, cells, true);
  ASSERT_FALSE(all.failed.empty());
  ASSERT_FALSE(all.held.empty());
  EXPECT_EQ(all.failed, one.failed);
  EXPECT_EQ(all.held, one.held);
  for (const std::int64_t c : cells.list) {
    const auto i = static_cast<std::size_t>(c);
    SCOPED_TRACE(c);
    if (std::binary_search(one.failed.begin(), one.failed.end(), c)) continue;
    ASSERT_TRUE(std::isfinite(one.p[i]));
    EXPECT_EQ(all.p[i], one.p[i]);
    EXPECT_EQ(all.rm0[i], one.rm0[i]);
    EXPECT_EQ(all.rm1[i], one.rm1[i]);
    EXPECT_EQ(all.iters[i], one.iters[i]);
  }
}

// Without per-cell counts (iters nullptr: the solver keeps them only for the output) the solve
// gives the same pressures, and its most iterations are the largest per-cell count.
TEST(IceEquilibriumBlocks, WithoutPerCellCountsTheSolveIsTheSameAndKeepsTheMost) {
  const auto water = ice::makeEos(test::modelSpec("stiffened_gas", {{"gamma", 4.4}, {"p_inf", 6e8}}), 4186);
  const auto air = ice::makeEos(test::modelSpec("ideal_gas", {{"gamma", 1.4}}), 717.5);
  ice::EquilibriumPressure eq({water.get(), air.get()}, 1e-11, 100, {true, true}, 1e-4);
  const Cells cells = makeCells(2600, *water, *air);
  const Result counted = solve(eq, cells, false);
  int most = 0;
  for (const std::int64_t c : cells.list) most = std::max(most, counted.iters[static_cast<std::size_t>(c)]);
  ASSERT_GT(most, 1);
  EXPECT_EQ(eq.lastMostIterations(), most);
  const std::size_t size = cells.rho[0].size();
  std::vector<double> p(size, 1e5), rm0(size, 0.0), rm1(size, 0.0);
  const std::vector<const double*> rho = {cells.rho[0].data(), cells.rho[1].data()},
                                   e = {cells.e[0].data(), cells.e[1].data()},
                                   carried = {cells.carried[0].data(), cells.carried[1].data()};
  eq.solve(cells.list, rho, e, p.data(), {rm0.data(), rm1.data()}, nullptr, &carried);
  EXPECT_EQ(eq.lastMostIterations(), most);
  for (const std::int64_t c : cells.list) {
    const auto i = static_cast<std::size_t>(c);
    if (!std::isfinite(counted.p[i])) continue;
    EXPECT_EQ(p[i], counted.p[i]) << c;
  }
}

}  // namespace
