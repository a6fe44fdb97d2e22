// Interface mappings (nearest neighbour, RBF): identity on coincident clouds, nearest points
// against brute force, exact reproduction of constant and linear fields, conservation of the
// total force and moment, convergence under refinement, degenerate source clouds, 2D clouds
// whose z differs, and the factory's errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <iostream>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "coupler/mapping/mapping.h"
#include "coupler/mapping/nearest_neighbor.h"
#include "coupler/mapping/point_cloud.h"
#include "coupler/mapping/rbf.h"

using namespace mpmice::coupler;

namespace {

constexpr double kPi = 3.14159265358979323846;

/// Points along the outline of the rectangle [0, w] x [0, h] (counter-clockwise from the origin)
/// at arc lengths offset + k * spacing; z is the same for all of them. This is the shape of a
/// 2D flap: the MPM surface particles on one side, the OpenFOAM patch on the other.
PointCloud outline(double spacing, double offset, double z, double w = 0.1, double h = 1.0) {
  PointCloud c;
  const double perimeter = 2.0 * (w + h);
  for (int k = 0;; ++k) {
    const double s = offset + k * spacing;
    if (s > perimeter - 0.25 * spacing) break;  // no point next to the first one
    if (s < w) c.add(s, 0.0, z);
    else if (s < w + h) c.add(w, s - w, z);
    else if (s < 2.0 * w + h) c.add(w - (s - w - h), h, z);
    else c.add(0.0, h - (s - 2.0 * w - h), z);
  }
  return c;
}

PointCloud randomCloud(std::size_t n, int dim, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(-1.0, 2.0);
  PointCloud c;
  for (std::size_t i = 0; i < n; ++i) c.add(u(gen), u(gen), dim == 3 ? u(gen) : 0.0);
  return c;
}

std::vector<double> randomValues(std::size_t n, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> v(n);
  for (auto& x : v) x = u(gen);
  return v;
}

/// Values of f at the points of c, ncomp = 1.
template <class F>
std::vector<double> sample(const PointCloud& c, F f) {
  std::vector<double> v(c.size());
  for (std::size_t i = 0; i < c.size(); ++i) v[i] = f(c.x[0][i], c.x[1][i], c.x[2][i]);
  return v;
}

double maxAbs(const std::vector<double>& v) {
  double m = 0.0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

double maxDiff(const std::vector<double>& a, const std::vector<double>& b) {
  double m = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) m = std::max(m, std::abs(a[i] - b[i]));
  return m;
}

std::size_t bruteNearest(const PointCloud& s, const PointCloud& t, std::size_t j, int dim) {
  std::size_t best = 0;
  double bestD2 = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < s.size(); ++i) {
    double d2 = 0.0;
    for (int d = 0; d < dim; ++d) {
      const auto dd = static_cast<std::size_t>(d);
      d2 += (t.x[dd][j] - s.x[dd][i]) * (t.x[dd][j] - s.x[dd][i]);
    }
    if (d2 < bestD2) {
      bestD2 = d2;
      best = i;
    }
  }
  return best;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Nearest neighbour

TEST(NearestNeighbor, CoincidentCloudsGiveExactIdentityBothWays) {
  const PointCloud c = outline(0.0125, 0.0, 0.0);
  NearestNeighbor nn;
  nn.compute(c, c, 2);
  ASSERT_EQ(nn.sourceSize(), c.size());
  ASSERT_EQ(nn.targetSize(), c.size());
  const auto in = randomValues(3 * c.size(), 1);
  std::vector<double> out(in.size(), -7.0), back(in.size(), -7.0);
  nn.mapConsistent(in.data(), out.data(), 3);
  nn.mapConservative(in.data(), back.data(), 3);
  EXPECT_EQ(out, in);
  EXPECT_EQ(back, in);
}

TEST(NearestNeighbor, ShiftedCloudTakesItsNearestPoint) {
  // Every target is its source point moved by 0.3 spacing outward: its nearest is that point.
  const PointCloud s = outline(0.0125, 0.002, 0.0);
  PointCloud t;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const double x = s.x[0][i], y = s.x[1][i];
    const double dx = x < 0.05 ? -0.00375 : 0.00375, dy = y < 0.5 ? -0.00375 : 0.00375;
    t.add(x + dx, y + dy, 0.5);
  }
  NearestNeighbor nn;
  nn.compute(s, t, 2);
  const auto in = randomValues(s.size(), 2);
  std::vector<double> out(t.size());
  nn.mapConsistent(in.data(), out.data(), 1);
  for (std::size_t i = 0; i < t.size(); ++i) {
    EXPECT_EQ(nn.nearest()[i], i);
    EXPECT_EQ(out[i], in[i]);
  }
}

TEST(NearestNeighbor, MatchesBruteForceOnRandomClouds) {
  for (int dim : {2, 3}) {
    const PointCloud s = randomCloud(3000, dim, 10u + static_cast<unsigned>(dim));
    const PointCloud t = randomCloud(2000, dim, 20u + static_cast<unsigned>(dim));
    NearestNeighbor nn;
    nn.compute(s, t, dim);
    for (std::size_t j = 0; j < t.size(); ++j)
      ASSERT_EQ(nn.nearest()[j], bruteNearest(s, t, j, dim)) << "dim " << dim << " target " << j;
  }
}

TEST(NearestNeighbor, TiesGoToTheLowerSourceIndex) {
  // Integer lattice sources (repeated twice: duplicates too); targets at cell centres and edge
  // midpoints are equally far from 4 or 2 sources.
  PointCloud s;
  for (int rep = 0; rep < 2; ++rep)
    for (int j = 10; j >= 0; --j)
      for (int i = 0; i <= 10; ++i) s.add(i, j, 0.0);
  PointCloud t;
  for (int j = 0; j < 20; ++j)
    for (int i = 0; i < 20; ++i) t.add(0.5 * i, 0.5 * j, 0.0);
  NearestNeighbor nn;
  nn.compute(s, t, 2);
  for (std::size_t j = 0; j < t.size(); ++j) ASSERT_EQ(nn.nearest()[j], bruteNearest(s, t, j, 2));

  PointCloud two;
  two.add(1.0, 0.0, 0.0);
  two.add(0.0, 0.0, 0.0);
  PointCloud mid;
  mid.add(0.5, 0.0, 0.0);
  nn.compute(two, mid, 2);
  EXPECT_EQ(nn.nearest()[0], 0u);
}

TEST(NearestNeighbor, ConservativeKeepsTheTotalForce) {
  const PointCloud s = outline(0.0125, 0.0, 0.0);
  const PointCloud t = outline(0.0173, 0.004, 0.5);
  NearestNeighbor nn;
  nn.compute(s, t, 2);
  const auto f = randomValues(2 * t.size(), 3);
  std::vector<double> fs(2 * s.size());
  nn.mapConservative(f.data(), fs.data(), 2);
  for (std::size_t c = 0; c < 2; ++c) {
    double sumT = 0.0, sumS = 0.0, absT = 0.0;
    for (std::size_t j = 0; j < t.size(); ++j) {
      sumT += f[2 * j + c];
      absT += std::abs(f[2 * j + c]);
    }
    for (std::size_t i = 0; i < s.size(); ++i) sumS += fs[2 * i + c];
    EXPECT_NEAR(sumS, sumT, 1e-14 * absT);
  }
}

// ---------------------------------------------------------------------------------------------
// RBF, for the thin-plate spline (support 0) and Wendland C2 (support 0.5)

class RbfTest : public ::testing::TestWithParam<double> {};

INSTANTIATE_TEST_SUITE_P(Kernels, RbfTest, ::testing::Values(0.0, 0.5),
                         [](const ::testing::TestParamInfo<double>& i) {
                           return i.param == 0.0 ? std::string("ThinPlate") : std::string("Wendland");
                         });

TEST_P(RbfTest, ReproducesConstantAndLinearFieldsBetweenFlapOutlines) {
  const PointCloud s = outline(0.0125, 0.0, 0.0);   // MPM surface particles
  const PointCloud t = outline(0.0173, 0.004, 0.5);  // OpenFOAM face centres
  Rbf rbf(GetParam());
  rbf.compute(s, t, 2);
  EXPECT_EQ(rbf.linearTerms(), 2);
  ASSERT_EQ(rbf.matrix().rows(), static_cast<Eigen::Index>(t.size()));
  ASSERT_EQ(rbf.matrix().cols(), static_cast<Eigen::Index>(s.size()));
  // Three components at once: a constant and two linear fields.
  const auto f0 = [](double, double, double) { return 2.5; };
  const auto f1 = [](double x, double y, double) { return 3.0 + 20.0 * x - 5.0 * y; };
  const auto f2 = [](double x, double y, double) { return -1.0 + 0.1 * x + 7.0 * y; };
  std::vector<double> in(3 * s.size()), out(3 * t.size());
  for (std::size_t i = 0; i < s.size(); ++i) {
    in[3 * i] = f0(s.x[0][i], s.x[1][i], 0.0);
    in[3 * i + 1] = f1(s.x[0][i], s.x[1][i], 0.0);
    in[3 * i + 2] = f2(s.x[0][i], s.x[1][i], 0.0);
  }
  rbf.mapConsistent(in.data(), out.data(), 3);
  const double scale = maxAbs(in);
  for (std::size_t j = 0; j < t.size(); ++j) {
    EXPECT_NEAR(out[3 * j], f0(t.x[0][j], t.x[1][j], 0.0), 1e-10 * scale);
    EXPECT_NEAR(out[3 * j + 1], f1(t.x[0][j], t.x[1][j], 0.0), 1e-10 * scale);
    EXPECT_NEAR(out[3 * j + 2], f2(t.x[0][j], t.x[1][j], 0.0), 1e-10 * scale);
  }
}

TEST_P(RbfTest, ReproducesLinearFieldsOnScattered3dClouds) {
  // Sources scattered on the surface of the unit cube, targets scattered inside and on it.
  std::mt19937 gen(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  PointCloud s;
  for (int i = 0; i < 300; ++i) {
    double p[3] = {u(gen), u(gen), u(gen)};
    p[i % 3] = (i / 3) % 2 == 0 ? 0.0 : 1.0;
    s.add(p[0], p[1], p[2]);
  }
  const PointCloud t = [&] {
    PointCloud c;
    for (int i = 0; i < 200; ++i) c.add(u(gen), u(gen), u(gen));
    return c;
  }();
  Rbf rbf(GetParam());
  rbf.compute(s, t, 3);
  EXPECT_EQ(rbf.linearTerms(), 3);
  const auto f = [](double x, double y, double z) { return 1.0 + 2.0 * x - 3.0 * y + 4.0 * z; };
  const auto in = sample(s, f);
  std::vector<double> out(t.size());
  rbf.mapConsistent(in.data(), out.data(), 1);
  EXPECT_LT(maxDiff(out, sample(t, f)), 1e-10 * maxAbs(in));
}

TEST_P(RbfTest, ConservativeKeepsTotalForceAndMoment) {
  const PointCloud s = outline(0.0125, 0.0, 0.0);
  const PointCloud t = outline(0.0173, 0.004, 0.5);
  Rbf rbf(GetParam());
  rbf.compute(s, t, 2);
  const auto fT = randomValues(2 * t.size(), 4);
  std::vector<double> fS(2 * s.size());
  rbf.mapConservative(fT.data(), fS.data(), 2);
  // Total force and moment (about an arbitrary point) of a cloud; `mag` sums |terms| for the
  // round-off bound.
  const double px = 0.3, py = -0.2;
  struct Totals {
    double fx = 0, fy = 0, mz = 0, mag = 0;
  };
  const auto totals = [&](const PointCloud& c, const std::vector<double>& f) {
    Totals r;
    for (std::size_t i = 0; i < c.size(); ++i) {
      const double m = (c.x[0][i] - px) * f[2 * i + 1] - (c.x[1][i] - py) * f[2 * i];
      r.fx += f[2 * i];
      r.fy += f[2 * i + 1];
      r.mz += m;
      r.mag += std::abs(f[2 * i]) + std::abs(f[2 * i + 1]) + std::abs(m);
    }
    return r;
  };
  const Totals a = totals(t, fT), b = totals(s, fS);
  EXPECT_NEAR(b.fx, a.fx, 1e-11 * a.mag);
  EXPECT_NEAR(b.fy, a.fy, 1e-11 * a.mag);
  EXPECT_NEAR(b.mz, a.mz, 1e-11 * a.mag);
}

TEST_P(RbfTest, ErrorOfASmoothFieldDecreasesUnderRefinement) {
  // Source spacing 0.025 / 2^k, k = 0..3; a dense target outline samples the max error, which sits
  // at the corners. Measured orders (max, rms): thin-plate 1.49 1.49 1.46, 1.97 1.95 1.95;
  // Wendland R = 0.5: 1.98 2.00 1.98, 2.48 2.49 2.50. Bounds below leave a margin of about 0.15.
  const auto f = [](double x, double y, double) { return std::sin(2.0 * kPi * y) * std::cos(5.0 * x); };
  const PointCloud t = outline(0.00093, 0.0003, 0.5);
  std::vector<double> maxErr, rmsErr;
  for (int k = 0; k < 4; ++k) {
    const PointCloud s = outline(0.025 / (1 << k), 0.0, 0.0);
    Rbf rbf(GetParam());
    rbf.compute(s, t, 2);
    const auto in = sample(s, f);
    std::vector<double> out(t.size());
    rbf.mapConsistent(in.data(), out.data(), 1);
    const auto exact = sample(t, f);
    double sum2 = 0.0;
    for (std::size_t j = 0; j < t.size(); ++j) sum2 += (out[j] - exact[j]) * (out[j] - exact[j]);
    maxErr.push_back(maxDiff(out, exact));
    rmsErr.push_back(std::sqrt(sum2 / static_cast<double>(t.size())));
  }
  const bool thinPlate = GetParam() == 0.0;
  const double minMaxOrder = thinPlate ? 1.3 : 1.8, minRmsOrder = thinPlate ? 1.8 : 2.3;
  std::cout << (thinPlate ? "thin-plate" : "Wendland") << " orders (max, rms):";
  for (std::size_t k = 1; k < maxErr.size(); ++k) {
    const double pMax = std::log2(maxErr[k - 1] / maxErr[k]);
    const double pRms = std::log2(rmsErr[k - 1] / rmsErr[k]);
    std::cout << " (" << pMax << ", " << pRms << ")";
    EXPECT_GT(pMax, minMaxOrder) << "refinement " << k << ", max errors " << maxErr[k - 1]
                                 << " -> " << maxErr[k];
    EXPECT_GT(pRms, minRmsOrder) << "refinement " << k << ", rms errors " << rmsErr[k - 1]
                                 << " -> " << rmsErr[k];
  }
  std::cout << '\n';
}

TEST_P(RbfTest, SourcesOnALineStillReproduceConstantsAndTheVariationAlongIt) {
  // 2D: every source on x = 0.05 (x is undetermined); targets on the line and beside it.
  PointCloud s, t;
  for (int i = 0; i <= 40; ++i) s.add(0.05, 0.025 * i, 0.0);
  for (int i = 0; i <= 30; ++i) t.add(0.05, 0.0331 * i, 0.5);
  for (int i = 0; i <= 30; ++i) t.add(0.07, 0.0331 * i, 0.5);
  Rbf rbf(GetParam());
  rbf.compute(s, t, 2);
  EXPECT_EQ(rbf.linearTerms(), 1);
  const auto c = [](double, double, double) { return -4.0; };
  const auto lin = [](double, double y, double) { return 2.0 + 3.0 * y; };
  for (const auto& g : {std::function<double(double, double, double)>(c),
                        std::function<double(double, double, double)>(lin)}) {
    const auto in = sample(s, g);
    std::vector<double> out(t.size());
    rbf.mapConsistent(in.data(), out.data(), 1);
    EXPECT_LT(maxDiff(out, sample(t, g)), 1e-10 * maxAbs(in));
  }
  // A diagonal line: the kept direction is the line's, whatever the axes.
  PointCloud d, dt;
  for (int i = 0; i <= 40; ++i) d.add(0.025 * i, 1.0 - 0.025 * i, 0.0);
  for (int i = 0; i <= 30; ++i) dt.add(0.0331 * i, 1.0 - 0.0331 * i, 0.0);
  rbf.compute(d, dt, 2);
  EXPECT_EQ(rbf.linearTerms(), 1);
  const auto alongD = [](double x, double y, double) { return 1.0 + x - y; };
  const auto in = sample(d, alongD);
  std::vector<double> out(dt.size());
  rbf.mapConsistent(in.data(), out.data(), 1);
  EXPECT_LT(maxDiff(out, sample(dt, alongD)), 1e-10 * maxAbs(in));
}

TEST_P(RbfTest, CoplanarAndTinySourceCloudsFallBackToWhatIsDetermined) {
  // 3D, sources on the plane z = 0.2: linear in x and y is kept, z dropped.
  PointCloud s, t;
  for (int j = 0; j <= 12; ++j)
    for (int i = 0; i <= 12; ++i) s.add(i / 12.0, j / 12.0, 0.2);
  for (int i = 0; i < 50; ++i) t.add(0.02 * i, 1.0 - 0.019 * i, 0.2 + 0.001 * i);
  Rbf rbf(GetParam());
  rbf.compute(s, t, 3);
  EXPECT_EQ(rbf.linearTerms(), 2);
  const auto f = [](double x, double y, double) { return 1.0 - x + 2.0 * y; };
  auto in = sample(s, f);
  std::vector<double> out(t.size());
  rbf.mapConsistent(in.data(), out.data(), 1);
  EXPECT_LT(maxDiff(out, sample(t, f)), 1e-10 * maxAbs(in));

  // One source point: the constant only. Two: the constant and the variation along them.
  PointCloud one;
  one.add(0.3, 0.4, 0.0);
  rbf.compute(one, t, 2);
  EXPECT_EQ(rbf.linearTerms(), 0);
  const double v = 1.75;
  out.assign(t.size(), 0.0);
  rbf.mapConsistent(&v, out.data(), 1);
  for (double o : out) EXPECT_NEAR(o, v, 1e-12);
  PointCloud two = one;
  two.add(0.3, 0.9, 0.0);
  rbf.compute(two, t, 2);
  EXPECT_EQ(rbf.linearTerms(), 1);
  const auto g = [](double, double y, double) { return 5.0 - 2.0 * y; };
  in = sample(two, g);
  rbf.mapConsistent(in.data(), out.data(), 1);
  EXPECT_LT(maxDiff(out, sample(t, g)), 1e-10 * maxAbs(in));
}

TEST_P(RbfTest, CoincidentSourcePointsAreReported) {
  PointCloud s = outline(0.05, 0.0, 0.0);
  s.add(s.x[0][3], s.x[1][3], 0.0);
  Rbf rbf(GetParam());
  EXPECT_THROW(rbf.compute(s, outline(0.03, 0.0, 0.0), 2), std::runtime_error);
  EXPECT_FALSE(rbf.computed());
  // Named from the points themselves (not from the factorisation, whose outcome on an exactly
  // singular system depends on the vector width of the build).
  try {
    rbf.compute(s, outline(0.03, 0.0, 0.0), 2);
  } catch (const std::runtime_error& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("source points 3 and " + std::to_string(s.size() - 1) + " coincide"), std::string::npos) << msg;
  }
}

// ---------------------------------------------------------------------------------------------
// Both mappings

TEST(Mapping, ZIsIgnoredIn2d) {
  // OpenFOAM's 2D patch: face centres at z = 0.5, points on the planes z = 0 and 1; MPM at z = 0.
  const PointCloud s = outline(0.0125, 0.0, 0.0);
  const PointCloud t0 = outline(0.0173, 0.004, 0.0);
  const PointCloud tHalf = outline(0.0173, 0.004, 0.5);
  PointCloud sMixed = s, tMixed = t0;
  for (std::size_t i = 0; i < sMixed.size(); ++i) sMixed.x[2][i] = i % 3 == 0 ? 1.0 : 0.0;
  for (std::size_t j = 0; j < tMixed.size(); ++j) tMixed.x[2][j] = j % 2 == 0 ? 0.0 : 1.0;
  for (const std::string type : {"nearest_neighbor", "rbf"}) {
    for (double support : {0.0, 0.5}) {
      const auto in = randomValues(2 * s.size(), 6);
      const auto mapped = [&](const PointCloud& src, const PointCloud& tgt) {
        auto m = makeMapping(type, support);
        m->compute(src, tgt, 2);
        std::vector<double> out(2 * tgt.size());
        m->mapConsistent(in.data(), out.data(), 2);
        return out;
      };
      const auto reference = mapped(s, t0);
      EXPECT_EQ(mapped(s, tHalf), reference) << type << " support " << support;
      EXPECT_EQ(mapped(s, tMixed), reference) << type << " support " << support;
      EXPECT_EQ(mapped(sMixed, tMixed), reference) << type << " support " << support;
    }
  }
}

TEST(Mapping, FactoryNamesAndErrors) {
  EXPECT_EQ(mappingNames(), (std::vector<std::string>{"nearest_neighbor", "rbf"}));
  EXPECT_STREQ(makeMapping("nearest_neighbor", 0.0)->name(), "nearest_neighbor");
  EXPECT_STREQ(makeMapping("rbf", 0.5)->name(), "rbf");
  try {
    makeMapping("rbff", 0.0);
    FAIL() << "an unknown mapping name must throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'rbff'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("nearest_neighbor, rbf"), std::string::npos) << e.what();
  }
  EXPECT_THROW(makeMapping("rbf", -1.0), std::invalid_argument);
  EXPECT_THROW(makeMapping("rbf", std::nan("")), std::invalid_argument);
}

TEST(Mapping, RejectsEmptyCloudsBadDimAndUseBeforeCompute) {
  const PointCloud c = outline(0.1, 0.0, 0.0), empty;
  for (const std::string type : {"nearest_neighbor", "rbf"}) {
    auto m = makeMapping(type, 0.0);
    double v = 0.0, w = 0.0;
    EXPECT_THROW(m->mapConsistent(&v, &w, 1), std::logic_error) << type;
    EXPECT_THROW(m->compute(empty, c, 2), std::invalid_argument) << type;
    EXPECT_THROW(m->compute(c, empty, 2), std::invalid_argument) << type;
    EXPECT_THROW(m->compute(c, c, 1), std::invalid_argument) << type;
    EXPECT_FALSE(m->computed());
    m->compute(c, c, 2);
    EXPECT_TRUE(m->computed());
    EXPECT_THROW(m->mapConservative(&v, &w, 0), std::invalid_argument) << type;
  }
}
