// Box algebra and mesh index spaces.
#include <gtest/gtest.h>

#include "core/mesh/box.h"
#include "core/mesh/mesh.h"

using namespace mpmice::core;

TEST(Box, DefaultIsInvalid) {
  Box b;
  EXPECT_FALSE(b.ok());
  EXPECT_EQ(b.numPts(), 0);
}

TEST(Box, IntersectOverlapping) {
  Box a({0, 0, 0}, {9, 9, 0}), b({5, -3, 0}, {12, 4, 0});
  Box c = a & b;
  EXPECT_EQ(c, Box({5, 0, 0}, {9, 4, 0}));
  EXPECT_EQ(c.numPts(), 25);
}

TEST(Box, IntersectDisjointIsInvalid) {
  Box a({0, 0, 0}, {3, 3, 0}), b({4, 0, 0}, {8, 3, 0});
  EXPECT_FALSE((a & b).ok());
}

TEST(Box, GrowShrinkRespectDimension) {
  Box a({2, 2, 0}, {5, 6, 0});
  Box g = a.grow(2, 2);
  EXPECT_EQ(g, Box({0, 0, 0}, {7, 8, 0}));
  EXPECT_EQ(g.shrink(2, 2), a);
  EXPECT_EQ(a.growDir(1, 1), Box({2, 1, 0}, {5, 7, 0}));
  EXPECT_FALSE(a.shrink(3, 2).ok());  // 4 cells wide: shrinking by 3 on both sides empties it
}

TEST(Box, IndexIsXFastestAndDense) {
  Box b({-1, 2, 3}, {2, 4, 4});
  std::int64_t expect = 0;
  forEach(b, [&](int i, int j, int k) { EXPECT_EQ(b.index(i, j, k), expect++); });
  EXPECT_EQ(expect, b.numPts());
}

TEST(Box, ContainsBox) {
  Box a({0, 0, 0}, {9, 9, 9});
  EXPECT_TRUE(a.contains(Box({1, 1, 1}, {9, 9, 9})));
  EXPECT_FALSE(a.contains(Box({1, 1, 1}, {10, 9, 9})));
  EXPECT_TRUE(a.contains(Box{}));
}

TEST(Mesh, IndexSpacesIn1D2D3D) {
  Mesh m1(1, {0, 0, 0}, {0.1, 0, 0}, {10, 0, 0});
  EXPECT_EQ(m1.cellBox(), Box({0, 0, 0}, {9, 0, 0}));
  EXPECT_EQ(m1.nodeBox(), Box({0, 0, 0}, {10, 0, 0}));
  EXPECT_EQ(m1.faceBox(0).numPts(), 11);
  Mesh m2(2, {0, 0, 0}, {0.5, 0.25, 0}, {4, 8, 0});
  EXPECT_EQ(m2.nodeBox().numPts(), 5 * 9);
  EXPECT_EQ(m2.faceBox(1).numPts(), 4 * 9);
  EXPECT_DOUBLE_EQ(m2.cellVolume(), 0.125);
  EXPECT_DOUBLE_EQ(m2.cellCenter(1, 0), 0.125);
  Mesh m3(3, {1, 1, 1}, {1, 1, 1}, {2, 3, 4});
  EXPECT_EQ(m3.nodeBox().numPts(), 3 * 4 * 5);
  EXPECT_EQ(m3.cellOf(2, 4.5), 3);
  EXPECT_DOUBLE_EQ(m3.upper(2), 5.0);
}

TEST(Mesh, RejectsBadSpacing) {
  EXPECT_THROW(Mesh(2, {0, 0, 0}, {0.1, -1, 0}, {4, 4, 0}), std::invalid_argument);
  EXPECT_THROW(Mesh(4, {0, 0, 0}, {1, 1, 1}, {4, 4, 4}), std::invalid_argument);
}
