// The advection's slab windows (advection_phase.cpp: the state's velocity and energy hold a
// fluid's conserved amounts slab by slab while the Lagrangian values they held are kept for a few
// slabs, and saved where read later): the positivity blend and a dropped trace give the same
// values whether the window holds the whole box (5 columns, one rank) or moves (4100 columns: a
// few rows at a time). On two ranks (split in x) a blended donor lies beside the rank boundary:
// the other rank's face with it as a ghost donor reads its blend after pass 2.
#include <gtest/gtest.h>

#include <memory>

#include "../../verification/ice/ice_test_scenes.h"
#include "core/parallel/decomposition.h"
#include "test_comm.h"

using namespace mpmice;

namespace {
// Blocks of five columns, each the 1D positivity test's cells (IceAdvection.DonorInternalEnergy-
// StaysPositiveWhenFaceValuesExceedItsOwn: a donor, its column 2, flowing out through both faces
// between light, cold and dense, hot columns), column i the block's column (i + off) % 5; in row
// 1 column 4 holds a trace (dropped: below kTraceMass). One step of advection.
std::unique_ptr<ice::IceSolver> advectBlocks(int nx, int off, const core::Comm& comm) {
  core::Scene s;
  s.name = "donor_blocks";
  s.mesh = core::Mesh(2, {0, 0, 0}, {0.1, 0.1, 1}, {nx, 8, 1});  // spacing 0.1
  s.materials = {test::idealGas("gas")};
  s.geometry = {test::region("all", test::box({-1, -1, -1}, {1e4, 2, 2}), {{"gas", 1.0}}, 1e5, 1.0)};
  s.ice.advection = "second_order";
  s.ice.limiter = "superbee";
  auto sol = std::make_unique<ice::IceSolver>(s, comm);
  const double dt = 1e-4, dx = 0.1, V = sol->mesh().cellVolume();
  const double v[5] = {10, 10, 1, 0.1, 0.1}, e[5] = {2e4, 2e4, 2e5, 2e6, 2e6};
  auto& m = sol->state().mat[0];
  for (int d = 0; d < 2; ++d) m.velFace[d].fill(0.0);
  const core::Box faces = sol->ownedBox().faces(0);
  core::forEach(faces, [&](int i, int j, int k) {
    const int q = (i + off) % 5;  // face i: the low face of column i
    if (q == 2) m.velFace[0](i, j, k) = -0.3 * dx / dt;  // out of column 2 to the left
    if (q == 3) m.velFace[0](i, j, k) = 0.5 * dx / dt;   // and to the right
  });
  // Over the stored cells: the ghosts' mass, volume fraction and specific volume are the
  // equilibrium's to fill, which this test leaves out (the advection fills the Lagrangian values').
  core::forEach(sol->state().press.box(), [&](int i, int j, int k) {
    const int q = ((i + off) % 5 + 5) % 5;
    const bool trace = j == 1 && q == 4;
    m.theta(i, j, k) = 1.0;
    m.spvol(i, j, k) = m.lagSpvol()(i, j, k) = v[q];
    m.mass(i, j, k) = trace ? 1e-210 : V / v[q];
    m.lagEint()(i, j, k) = e[q] + j;
    m.lagVel()(i, j, k, 0) = 0.0;
    m.lagVel()(i, j, k, 1) = trace ? 3.0 : 0.0;
  });
  sol->beginStep(dt);
  sol->advectFluids();
  return sol;
}
}  // namespace

TEST(IceAdvectionWindow, BlendAndDroppedTraceAreTheSameWhenTheWindowMoves) {
  const int nx = 4100;
  // The offset that puts a donor (block column 2) just below rank 1's first column on two ranks.
  const core::Decomposition two(core::Mesh(2, {0, 0, 0}, {0.1, 0.1, 1}, {nx, 8, 1}), 2);
  const int first = two.cellBox(1).lo[0];
  const int off = ((2 - (first - 1)) % 5 + 5) % 5;
  const auto whole = advectBlocks(5, 0, core::Comm(MPI_COMM_SELF));
  const auto moving = advectBlocks(nx, off, test::comm());
  EXPECT_GT(whole->positivityBlends(), 0);
  EXPECT_GT(moving->positivityBlends(), 0);
  const auto& a = whole->state().mat[0];
  const auto& b = moving->state().mat[0];
  long compared = 0;
  core::forEach(moving->ownedBox(), [&](int i, int j, int k) {
    const int q = (i + off) % 5;
    if (i - q < 0 || i - q + 4 >= nx) return;  // whole blocks only (the mesh's ends are walls)
    EXPECT_EQ(b.mass(i, j, k), a.mass(q, j, k)) << i << " " << j;
    EXPECT_EQ(b.vel(i, j, k, 0), a.vel(q, j, k, 0)) << i << " " << j;
    EXPECT_EQ(b.vel(i, j, k, 1), a.vel(q, j, k, 1)) << i << " " << j;
    EXPECT_EQ(b.eint(i, j, k), a.eint(q, j, k)) << i << " " << j;
    EXPECT_EQ(b.spvol(i, j, k), a.spvol(q, j, k)) << i << " " << j;
    ++compared;
  });
  EXPECT_GT(compared, moving->ownedBox().numPts() / 2);
  EXPECT_EQ(a.mass(4, 1, 0), 0.0) << "the trace is dropped";
  EXPECT_EQ(a.vel(4, 1, 0, 1), 3.0) << "and keeps its velocity";
}
