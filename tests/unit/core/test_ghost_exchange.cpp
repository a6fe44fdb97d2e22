// Ghost exchange and node sums across ranks match a serial computation (run with 1 and 4 ranks).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/parallel/ghost_exchange.h"
#include "test_comm.h"

using namespace mpmice::core;

namespace {
double valueAt(int i, int j, int k, int c) { return 1000.0 * c + i + 37.0 * j + 1371.0 * k + 0.5; }
int wrap(int i, int n) { return ((i % n) + n) % n; }
}  // namespace

class GhostExchangeTest : public ::testing::TestWithParam<int> {};

TEST_P(GhostExchangeTest, CellFillMatchesGlobalValues) {
  const int dim = GetParam();
  const Comm& comm = mpmice::test::comm();
  Mesh m(dim, {0, 0, 0}, {1, 1, 1}, {9, 7, 5});
  for (bool periodic : {false, true}) {
    std::array<bool, 3> per{periodic, false, periodic};
    Decomposition d(m, comm.size(), per);
    const int ng = 2;
    GhostExchange ex(d, comm, Centering::Cell, ng);
    Field f("f", Centering::Cell, ex.storedBox(), 2, ng, -1.0);
    for (int c = 0; c < 2; ++c)
      forEach(ex.ownedBox(), [&](int i, int j, int k) { f(i, j, k, c) = valueAt(i, j, k, c); });
    ex.fill(f);
    const IntVect n = m.cells();
    for (int c = 0; c < 2; ++c)
      forEach(ex.storedBox(), [&](int i, int j, int k) {
        int gi = i, gk = k;
        if (per[0]) gi = wrap(i, n[0]);
        if (dim == 3 && per[2]) gk = wrap(k, n[2]);
        const bool inside = m.cellBox().contains(gi, j, gk);
        const double expect = inside ? valueAt(gi, j, gk, c) : -1.0;  // outside: untouched
        EXPECT_EQ(f(i, j, k, c), expect) << "dim " << dim << " cell " << i << "," << j << "," << k;
      });
  }
}

TEST_P(GhostExchangeTest, NodeSumMatchesSerialDeposit) {
  // Each rank deposits, for every cell it owns, a value into the cell's corner nodes (as MPM's
  // particle-to-grid does). After sumAndFill every stored node holds the serial total.
  const int dim = GetParam();
  const Comm& comm = mpmice::test::comm();
  Mesh m(dim, {0, 0, 0}, {1, 1, 1}, {8, 6, 4});
  for (bool periodic : {false, true}) {
    std::array<bool, 3> per{periodic, periodic, false};
    Decomposition d(m, comm.size(), per);
    const int ng = 1;
    GhostExchange ex(d, comm, Centering::Node, ng);
    Field f("mass", Centering::Node, ex.storedBox(), 1, ng, 0.0);
    const Box serialNodes = m.nodeBox();
    Field serial("serial", Centering::Node, serialNodes, 1, 0, 0.0);
    const IntVect period = d.period(Centering::Node);
    auto deposit = [&](Field& into, const Box& cells, bool wrapIdx) {
      forEach(cells, [&](int i, int j, int k) {
        const int ni = dim >= 1 ? 2 : 1, nj = dim >= 2 ? 2 : 1, nk = dim >= 3 ? 2 : 1;
        for (int c = 0; c < nk; ++c)
          for (int b = 0; b < nj; ++b)
            for (int a = 0; a < ni; ++a) {
              int x = i + a, y = j + b, z = k + c;
              if (wrapIdx) {
                if (per[0]) x = wrap(x, period[0]);
                if (per[1] && dim >= 2) y = wrap(y, period[1]);
              }
              into(x, y, z) += valueAt(i, j, k, 0) * (1 + a + 2 * b + 4 * c);
            }
      });
    };
    deposit(f, d.cellBox(comm.rank()), false);
    deposit(serial, m.cellBox(), true);
    ex.sumAndFill(f);
    forEach(ex.storedBox(), [&](int i, int j, int k) {
      int x = i, y = j;
      if (per[0]) x = wrap(i, period[0]);
      if (per[1] && dim >= 2) y = wrap(j, period[1]);
      if (!serialNodes.contains(x, y, k)) return;  // off the domain: not defined
      EXPECT_NEAR(f(i, j, k), serial(x, y, k), 1e-9 * std::abs(serial(x, y, k)))
          << "dim " << dim << " periodic " << periodic << " node " << i << "," << j << "," << k;
    });
  }
}

INSTANTIATE_TEST_SUITE_P(Dims, GhostExchangeTest, ::testing::Values(1, 2, 3));

TEST_P(GhostExchangeTest, WideStencilSumIncludesNodesOutsideTheMesh) {
  // A quadratic B-spline stencil reaches one node beyond each mesh face: with ownExterior those
  // nodes are summed across ranks like interior ones and match a serial deposit.
  const int dim = GetParam();
  const Comm& comm = mpmice::test::comm();
  Mesh m(dim, {0, 0, 0}, {1, 1, 1}, {8, 6, 4});
  Decomposition d(m, comm.size());
  const int ng = 1;
  GhostExchange ex(d, comm, Centering::Node, ng, true);
  Field f("mass", Centering::Node, ex.storedBox(), 1, ng, 0.0);
  const Box serialNodes = m.nodeBox().grow(ng, dim);
  Field serial("serial", Centering::Node, serialNodes, 1, ng, 0.0);
  auto deposit = [&](Field& into, const Box& cells) {
    forEach(cells, [&](int i, int j, int k) {
      const int lo = -1, hi = 2;  // nodes i-1 .. i+2
      for (int c = (dim >= 3 ? lo : 0); c <= (dim >= 3 ? hi : 0); ++c)
        for (int b = (dim >= 2 ? lo : 0); b <= (dim >= 2 ? hi : 0); ++b)
          for (int a = lo; a <= hi; ++a) {
            const int x = std::clamp(i + a, -1, m.cells()[0] + 1);
            const int y = dim >= 2 ? std::clamp(j + b, -1, m.cells()[1] + 1) : 0;
            const int z = dim >= 3 ? std::clamp(k + c, -1, m.cells()[2] + 1) : 0;
            into(x, y, z) += valueAt(i, j, k, 0) * (1 + (a + 1) + 4 * (b + 1) + 16 * (c + 1));
          }
    });
  };
  deposit(f, d.cellBox(comm.rank()));
  deposit(serial, m.cellBox());
  ex.sumAndFill(f);
  forEach(ex.storedBox(), [&](int i, int j, int k) {
    EXPECT_NEAR(f(i, j, k), serial(i, j, k), 1e-9 * std::abs(serial(i, j, k)))
        << "dim " << dim << " node " << i << "," << j << "," << k;
  });
}
