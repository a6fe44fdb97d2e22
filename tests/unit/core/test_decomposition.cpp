// Decomposition over 1..8 ranks owns every cell (and node) exactly once.
#include <gtest/gtest.h>

#include <vector>

#include "core/parallel/decomposition.h"

using namespace mpmice::core;

namespace {
void expectExactCover(const Mesh& m, int nranks, Centering c, std::array<bool, 3> per) {
  Decomposition d(m, nranks, per);
  const Box dom = d.domainBox(c);
  std::vector<int> count(static_cast<std::size_t>(dom.numPts()), 0);
  for (int r = 0; r < nranks; ++r) {
    Box own = d.ownedBox(r, c);
    ASSERT_TRUE(own.ok()) << "rank " << r << " owns nothing";
    ASSERT_TRUE(dom.contains(own));
    forEach(own, [&](int i, int j, int k) { count[dom.index(i, j, k)]++; });
  }
  const IntVect period = d.period(c);
  forEach(dom, [&](int i, int j, int k) {
    const bool image = (i >= period[0]) || (j >= period[1]) || (k >= period[2]);  // periodic copy
    EXPECT_EQ(count[dom.index(i, j, k)], image ? 0 : 1) << "index " << i << "," << j << "," << k;
  });
}
}  // namespace

TEST(Decomposition, EveryCellOwnedOnce1To4Ranks) {
  const Mesh meshes[] = {Mesh(1, {0, 0, 0}, {1, 1, 1}, {13, 1, 1}),
                         Mesh(2, {0, 0, 0}, {1, 1, 1}, {7, 5, 1}),
                         Mesh(3, {0, 0, 0}, {1, 1, 1}, {5, 4, 3})};
  for (const Mesh& m : meshes)
    for (int n = 1; n <= 4; ++n) {
      expectExactCover(m, n, Centering::Cell, {false, false, false});
      expectExactCover(m, n, Centering::Node, {false, false, false});
      expectExactCover(m, n, Centering::Node, {true, false, true});
    }
}

TEST(Decomposition, ProcessGridPrefersSquareBoxes) {
  EXPECT_EQ(chooseProcessGrid({64, 64, 1}, 2, 4), (IntVect{2, 2, 1}));
  EXPECT_EQ(chooseProcessGrid({256, 8, 1}, 2, 4), (IntVect{4, 1, 1}));
  EXPECT_EQ(chooseProcessGrid({100, 1, 1}, 1, 3), (IntVect{3, 1, 1}));
}

TEST(Decomposition, OwnerOfCellMatchesBoxes) {
  Mesh m(2, {0, 0, 0}, {1, 1, 1}, {9, 7, 1});
  Decomposition d(m, 4);
  for (int r = 0; r < 4; ++r)
    forEach(d.cellBox(r), [&](int i, int j, int k) { EXPECT_EQ(d.ownerOfCell(i, j, k), r); });
  EXPECT_EQ(d.ownerOfCell(-1, 0, 0), -1);
  EXPECT_EQ(d.ownerOfCell(9, 0, 0), -1);
}

TEST(Decomposition, TooManyRanksIsAnError) {
  Mesh m(1, {0, 0, 0}, {1, 1, 1}, {3, 1, 1});
  EXPECT_THROW(Decomposition(m, 4), std::invalid_argument);
}
