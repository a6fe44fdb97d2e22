// Shape functions: partition of unity, zero gradient sum, linear reproduction, registry errors.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "mpm/shape/shape_function.h"

using namespace mpmice::mpm;

namespace {
template <class S>
void checkShape(double lp) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(2.0, 9.0);
  for (int t = 0; t < 1000; ++t) {
    const double xi = u(rng);
    int base = 0;
    double w[S::kNodes], dw[S::kNodes];
    S::eval(xi, lp, base, w, dw);
    double sw = 0, sdw = 0, sx = 0, sxdw = 0;
    for (int a = 0; a < S::kNodes; ++a) {
      EXPECT_GE(w[a], -1e-14) << S::kName << " at " << xi;
      sw += w[a];
      sdw += dw[a];
      sx += w[a] * (base + a);
      sxdw += dw[a] * (base + a);
    }
    EXPECT_NEAR(sw, 1.0, 1e-13) << S::kName << " partition of unity at " << xi;
    EXPECT_NEAR(sdw, 0.0, 1e-13) << S::kName << " gradient sum at " << xi;
    EXPECT_NEAR(sx, xi, 1e-12) << S::kName << " reproduces x at " << xi;
    EXPECT_NEAR(sxdw, 1.0, 1e-12) << S::kName << " gradient of x at " << xi;
    // Gradient against a central difference of the weights.
    const double h = 1e-6;
    int bp, bm;
    double wp[S::kNodes], wm[S::kNodes], d[S::kNodes];
    S::eval(xi + h, lp, bp, wp, d);
    S::eval(xi - h, lp, bm, wm, d);
    if (bp == base && bm == base) {
      for (int a = 0; a < S::kNodes; ++a) {
        EXPECT_NEAR((wp[a] - wm[a]) / (2 * h), dw[a], 1e-6) << S::kName;
      }
    }
  }
}
}  // namespace

TEST(ShapeFunction, LinearPartitionOfUnity) { checkShape<LinearShape>(0); }
TEST(ShapeFunction, GimpPartitionOfUnity) {
  checkShape<GimpShape>(0.25);
  checkShape<GimpShape>(0.5);
  checkShape<GimpShape>(1.0 / 6.0);
}
TEST(ShapeFunction, BSpline2PartitionOfUnity) { checkShape<BSpline2Shape>(0); }
TEST(ShapeFunction, BSpline3PartitionOfUnity) { checkShape<BSpline3Shape>(0); }

TEST(ShapeFunction, FloorIndexIsFloorForGridCoordinates) {
  // Integers, values just below and above them, negatives (B-spline stencils start half a cell
  // below the first node), and random coordinates: the same integer as std::floor.
  std::vector<double> xs = {0.0, -0.0, 1.0, -1.0, 0.5, -0.5, 2.999999999999999, 3.0, -2.000000000000001, 1e9, -1e9};
  for (int i = -5; i <= 5; ++i) {
    xs.push_back(std::nextafter(static_cast<double>(i), -1e300));
    xs.push_back(std::nextafter(static_cast<double>(i), 1e300));
  }
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-600.0, 600.0);
  for (int k = 0; k < 10000; ++k) xs.push_back(u(rng));
  for (double x : xs) EXPECT_EQ(floorIndex(x), static_cast<int>(std::floor(x))) << x;
}

TEST(ShapeFunction, RegistryByName) {
  for (const auto& n : shapeFunctionNames()) EXPECT_EQ(toString(parseShapeFunction(n)), n);
  EXPECT_EQ(stencilWidth(ShapeKind::BSpline3), 4);
  try {
    (void)parseShapeFunction("quintic");
    FAIL() << "unknown name accepted";
  } catch (const std::invalid_argument& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("quintic"), std::string::npos);
    EXPECT_NE(m.find("linear, gimp, bspline2, bspline3"), std::string::npos) << m;
  }
}
