// Coupling accelerations and convergence measures on fixed-point problems with known answers.
// Runs with 1 and 2 ranks: the coupling data are split over the ranks, results must not change.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <vector>

#include "coupler/acceleration/acceleration.h"
#include "coupler/acceleration/iqn_ils.h"
#include "coupler/acceleration/relaxation.h"
#include "coupler/convergence/convergence_measure.h"
#include "test_comm.h"

using namespace mpmice;
using namespace mpmice::coupler;

namespace {

/// A linear "coupled solver" H(x) = A x + b over a global vector of size n split across ranks.
struct LinearProblem {
  Eigen::MatrixXd A;
  Eigen::VectorXd b;
  int n;
  const core::Comm& comm;
  int lo, len;

  LinearProblem(int size, double spectralScale, unsigned seed, const core::Comm& c)
      : n(size), comm(c) {
    std::srand(seed);
    A = Eigen::MatrixXd::Random(n, n);
    const double rho = A.eigenvalues().cwiseAbs().maxCoeff();
    A *= spectralScale / rho;  // spectral radius = spectralScale
    b = Eigen::VectorXd::Random(n);
    lo = (n * c.rank()) / c.size();
    len = (n * (c.rank() + 1)) / c.size() - lo;
  }
  Eigen::VectorXd gather(const Eigen::VectorXd& local) const {
    std::vector<double> g(n, 0.0);
    for (int i = 0; i < len; ++i) g[lo + i] = local[i];
    comm.sumInPlace(g);
    return Eigen::Map<Eigen::VectorXd>(g.data(), n);
  }
  Eigen::VectorXd H(const Eigen::VectorXd& local) const {
    return (A * gather(local) + b).segment(lo, len);
  }
  Eigen::VectorXd exact() const {
    return (Eigen::MatrixXd::Identity(n, n) - A).fullPivLu().solve(b).segment(lo, len);
  }
};

/// Iterates until ||x~ - x|| <= 1e-10 ||x~||; returns the iteration count (or -1 beyond max).
int solve(Acceleration& acc, const LinearProblem& p, Eigen::VectorXd& x, int maxIt) {
  auto conv = makeConvergenceMeasure("relative", 1e-10);
  conv->newStep();
  for (int k = 1; k <= maxIt; ++k) {
    const Eigen::VectorXd xt = p.H(x);
    if (conv->measure(x, xt, p.comm)) {
      acc.iterationsConverged();
      x = xt;
      return k;
    }
    x = acc.performAcceleration(x, xt);
  }
  return -1;
}

}  // namespace

TEST(ConstantRelaxation, IsXPlusOmegaR) {
  ConstantRelaxation c(0.25);
  Eigen::VectorXd x(3), xt(3);
  x << 1, 2, 3;
  xt << 5, 2, -1;
  const Eigen::VectorXd next = c.performAcceleration(x, xt);
  EXPECT_DOUBLE_EQ(next[0], 2.0);
  EXPECT_DOUBLE_EQ(next[1], 2.0);
  EXPECT_DOUBLE_EQ(next[2], 2.0);
}

TEST(Aitken, FirstStepUsesInitialRelaxation) {
  AitkenRelaxation a(0.1, mpmice::test::comm());
  Eigen::VectorXd x = Eigen::VectorXd::Constant(4, 1.0), xt = Eigen::VectorXd::Constant(4, 3.0);
  const Eigen::VectorXd next = a.performAcceleration(x, xt);
  EXPECT_DOUBLE_EQ(next[0], 1.2);  // 1 + 0.1 (3 - 1), due to the initial relaxation 0.1
  EXPECT_DOUBLE_EQ(a.relaxation(), 0.1);
}

TEST(Aitken, SolvesScalarLinearProblemBySecant) {
  // For a scalar linear map Aitken's rule is the secant method: exact after two relaxations.
  const core::Comm& comm = mpmice::test::comm();
  LinearProblem p(1 * comm.size(), 0.0, 1, comm);
  p.A = Eigen::MatrixXd::Identity(p.n, p.n) * 1.8;  // divergent plain iteration (|a| > 1)
  AitkenRelaxation a(0.5, comm);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(p.len);
  const int its = solve(a, p, x, 10);
  ASSERT_GT(its, 0);
  EXPECT_LE(its, 4);
  EXPECT_NEAR((x - p.exact()).cwiseAbs().maxCoeff(), 0.0, 1e-8);
}

TEST(IqnIls, ConvergesOnDivergentLinearProblemWithinNPlusTwo) {
  const core::Comm& comm = mpmice::test::comm();
  const int n = 12;
  LinearProblem p(n, 1.6, 7, comm);  // plain fixed-point iteration diverges
  IqnIls q(0.1, 0, 1e-10, comm);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(p.len);
  const int its = solve(q, p, x, 50);
  ASSERT_GT(its, 0) << "did not converge";
  EXPECT_LE(its, n + 3);
  EXPECT_LT((x - p.exact()).cwiseAbs().maxCoeff(), 1e-8);
}

TEST(IqnIls, ReuseOfPastStepsSavesIterations) {
  const core::Comm& comm = mpmice::test::comm();
  const int n = 12;
  LinearProblem p(n, 0.9, 11, comm);
  auto run = [&](int reuse) {
    IqnIls q(0.1, reuse, 1e-10, comm);
    Eigen::VectorXd x = Eigen::VectorXd::Zero(p.len);
    int total = 0;
    for (int step = 0; step < 4; ++step) {  // same operator, new right-hand side every step
      p.b = Eigen::VectorXd::Constant(n, 1.0 + step);
      const int its = solve(q, p, x, 60);
      EXPECT_GT(its, 0);
      total += its;
    }
    return total;
  };
  const int without = run(0), with = run(3);
  EXPECT_LT(with, without) << "reuse 3: " << with << " iterations, no reuse: " << without;
}

TEST(IqnIls, FilterDropsDependentColumns) {
  const core::Comm& comm = mpmice::test::comm();
  IqnIls q(0.5, 0, 1e-6, comm);
  Eigen::VectorXd x = Eigen::VectorXd::Constant(3, 0.0);
  // Outputs along one direction only: every new residual difference is parallel to the first.
  for (int k = 1; k <= 4; ++k) {
    Eigen::VectorXd xt = Eigen::VectorXd::Constant(3, 1.0 / k);
    x = q.performAcceleration(x, xt);
  }
  EXPECT_EQ(q.columnsUsed(), 1);
}

TEST(Factories, UnknownNamesListValidChoices) {
  AccelerationParams p;
  p.type = "broyden";
  try {
    makeAcceleration(p, mpmice::test::comm());
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'broyden'; valid: none, constant, aitken, iqn_ils"), std::string::npos);
  }
  p.type = "constant";
  p.relaxation = 1.5;
  EXPECT_THROW(makeAcceleration(p, mpmice::test::comm()), std::invalid_argument);
  EXPECT_THROW(makeConvergenceMeasure("relativ", 1e-3), std::invalid_argument);
}

TEST(ConvergenceMeasures, HandComputedResiduals) {
  const core::Comm& comm = mpmice::test::comm();
  // Every rank holds (3, 4) - (0, 0): global residual norm 5 sqrt(size).
  Eigen::VectorXd o = Eigen::VectorXd::Zero(2), n(2);
  n << 3, 4;
  const double s = std::sqrt(double(comm.size()));
  auto abs = makeConvergenceMeasure("absolute", 5.0 * s + 1e-12);
  EXPECT_TRUE(abs->measure(o, n, comm));
  EXPECT_NEAR(abs->residual(), 5.0 * s, 1e-12);
  auto rel = makeConvergenceMeasure("relative", 0.5);
  EXPECT_FALSE(rel->measure(o, n, comm));  // ||n - o|| = ||n||
  auto rr = makeConvergenceMeasure("residual_relative", 0.1);
  rr->newStep();
  EXPECT_FALSE(rr->measure(o, n, comm));   // first residual defines the scale
  Eigen::VectorXd n2 = n * 1.05;
  EXPECT_TRUE(rr->measure(n, n2, comm));   // residual 0.05 * first <= 0.1 * first
  EXPECT_NEAR(rr->threshold(), 0.5 * s, 1e-12);
}
