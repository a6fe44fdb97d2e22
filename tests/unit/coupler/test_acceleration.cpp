// Coupling accelerations and convergence measures on fixed-point problems with known answers.
// Runs with 1 and 2 ranks: the coupling data are split over the ranks, results must not change.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <vector>

#include "coupler/acceleration/acceleration.h"
#include "coupler/acceleration/iqn_ils.h"
#include "coupler/acceleration/qr_factorization.h"
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

// QrFactorization: the factors stay a QR of the columns as they come and go (rows split over
// the ranks), without a rebuild.
namespace {

/// Inserts, erases in the middle, at the end and at the front, with columns of n rows; after each
/// change Q R reproduces the columns, Q is orthonormal and R upper triangular.
void checkQrUpdates(int n) {
  const core::Comm& comm = mpmice::test::comm();
  struct {
    int lo, len;
  } p{(n * comm.rank()) / comm.size(), (n * (comm.rank() + 1)) / comm.size() - (n * comm.rank()) / comm.size()};
  std::srand(5);
  const Eigen::MatrixXd all = Eigen::MatrixXd::Random(n, 6);
  QrFactorization qr(comm);
  std::vector<int> order;  // global column index of each factor column, newest first
  auto check = [&] {
    const int m = qr.cols();
    ASSERT_EQ(m, static_cast<int>(order.size()));
    for (int j = 0; j < m; ++j) {
      Eigen::VectorXd a = Eigen::VectorXd::Zero(p.len);
      for (int i = 0; i <= j; ++i) a += qr.q()[static_cast<std::size_t>(i)] * qr.r()(i, j);
      const Eigen::VectorXd want = all.col(order[static_cast<std::size_t>(j)]).segment(p.lo, p.len);
      EXPECT_LT(std::sqrt(comm.sum((a - want).squaredNorm())), 1e-12) << "column " << j;
      for (int i = j + 1; i < m; ++i) EXPECT_EQ(qr.r()(i, j), 0.0);
      for (int i = 0; i < m; ++i) {
        const double d = comm.sum(qr.q()[static_cast<std::size_t>(i)].dot(qr.q()[static_cast<std::size_t>(j)]));
        EXPECT_NEAR(d, i == j ? 1.0 : 0.0, 1e-12);
      }
    }
  };
  for (int c = 0; c < 5; ++c) {
    qr.pushFront(all.col(c).segment(p.lo, p.len));
    order.insert(order.begin(), c);
    check();
  }
  qr.erase(2);  // a middle column
  order.erase(order.begin() + 2);
  check();
  qr.erase(qr.cols() - 1);  // the oldest
  order.pop_back();
  check();
  qr.erase(0);  // the newest
  order.erase(order.begin());
  check();
  qr.pushFront(all.col(5).segment(p.lo, p.len));
  order.insert(order.begin(), 5);
  check();
  // The least-squares solution equals the normal equations'.
  const Eigen::VectorXd rhs = Eigen::VectorXd::Ones(n).segment(p.lo, p.len);
  const Eigen::VectorXd a = qr.solve(rhs);
  Eigen::MatrixXd A(n, qr.cols());
  for (int j = 0; j < qr.cols(); ++j) A.col(j) = all.col(order[static_cast<std::size_t>(j)]);
  const Eigen::VectorXd ref = A.colPivHouseholderQr().solve(Eigen::VectorXd::Ones(n));
  EXPECT_LT((a - ref).cwiseAbs().maxCoeff(), 1e-10);
}

}  // namespace

// n = 700: columns longer than the 256-row blocks the insertion's rotations work in (a partial
// last block too).
TEST(QrFactorization, InsertAtTheFrontAndEraseAnywhereKeepAValidQr) {
  for (const int n : {9, 700}) {
    SCOPED_TRACE("n = " + std::to_string(n));
    checkQrUpdates(n);
  }
}

// The residual-sum preconditioner: an iterate of two fields whose scales differ by 1e8 (a
// pressure in Pa beside a velocity in m/s). The weights it learns from the residuals make both
// fields weigh alike (their ratio is the scale ratio), and the iteration reaches the same fixed
// point with and without it.
TEST(IqnIls, ResidualSumPreconditionerEqualisesBadlyScaledFields) {
  const core::Comm& comm = mpmice::test::comm();
  const int n = 12;
  LinearProblem p(n, 0.95, 21, comm);
  Eigen::VectorXd scale = Eigen::VectorXd::Ones(n);
  scale.tail(n / 2).setConstant(1e8);
  const Eigen::MatrixXd S = scale.asDiagonal(), Sinv = scale.cwiseInverse().asDiagonal();
  const Eigen::MatrixXd A = S * p.A * Sinv;  // H in scaled units: y = S x, H_s(y) = S H(S^-1 y)
  p.A = A;
  auto run = [&](bool precondition, std::vector<double>* weights) {
    IqnIls q(0.1, 4, 1e-12, comm, precondition);
    std::vector<Segment> segs;  // this rank's rows: the first half of the vector is group 0
    for (int i = 0; i < p.len; ++i) segs.push_back({i, 1, (p.lo + i) < n / 2 ? 0 : 1});
    q.setSegments(segs);
    Eigen::VectorXd x = Eigen::VectorXd::Zero(p.len);
    for (int step = 0; step < 3; ++step) {
      p.b = S * Eigen::VectorXd::Constant(n, 1.0 + step);
      for (int k = 1; k <= 100; ++k) {
        const Eigen::VectorXd xt = p.H(x);
        const Eigen::VectorXd d = (xt - x).cwiseQuotient(scale.segment(p.lo, p.len));
        if (std::sqrt(comm.sum(d.squaredNorm())) < 1e-9) {
          q.iterationsConverged();
          x = xt;
          break;
        }
        x = q.performAcceleration(x, xt);
      }
    }
    if (weights) *weights = q.weights();
    return x;
  };
  std::vector<double> w;
  const Eigen::VectorXd plain = run(false, nullptr), preconditioned = run(true, &w);
  ASSERT_EQ(w.size(), 2u);
  EXPECT_GT(w[0] / w[1], 1e6);  // the small field's weight is ~1e8 times the large one's
  EXPECT_LT(w[0] / w[1], 1e10);
  EXPECT_LT((plain - preconditioned).cwiseQuotient(scale.segment(p.lo, p.len)).cwiseAbs().maxCoeff(), 1e-6);
}
