#include "coupler/acceleration/qr_factorization.h"

#include <algorithm>
#include <cmath>

namespace mpmice::coupler {

void QrFactorization::rotateR(int i, int k, double c, double s, int from) {
  for (int j = from; j < r_.cols(); ++j) {
    const double a = r_(i, j), b = r_(k, j);
    r_(i, j) = c * a + s * b;
    r_(k, j) = -s * a + c * b;
  }
}

void QrFactorization::rotate(int i, int k, double c, double s, int from) {
  rotateR(i, k, c, s, from);
  // In place, element by element: no temporary column (for a long iterate a fresh page-mapped
  // allocation per rotation), the same arithmetic.
  double* qi = q_[static_cast<std::size_t>(i)].data();
  double* qk = q_[static_cast<std::size_t>(k)].data();
  const Eigen::Index n = q_[static_cast<std::size_t>(i)].size();
  for (Eigen::Index e = 0; e < n; ++e) {
    const double a = qi[e], b = qk[e];
    qi[e] = c * a + s * b;
    qk[e] = -s * a + c * b;
  }
}

void QrFactorization::pushFront(const Eigen::VectorXd& column) {
  const int m = cols();
  Eigen::VectorXd v = column;
  Eigen::VectorXd coeff = Eigen::VectorXd::Zero(m);
  for (int pass = 0; pass < 2; ++pass)
    for (int i = 0; i < m; ++i) {
      const double h = comm_.sum(q_[static_cast<std::size_t>(i)].dot(v));
      coeff[i] += h;
      v -= h * q_[static_cast<std::size_t>(i)];
    }
  const double rho = std::sqrt(comm_.sum(v.squaredNorm()));
  // [column, A] = [Q, q] H with H's first column (coeff; rho) and then (R; 0): rotations from
  // the bottom zero the first column below its top, leaving H upper triangular.
  Eigen::MatrixXd h = Eigen::MatrixXd::Zero(m + 1, m + 1);
  h.block(0, 0, m, 1) = coeff;
  h(m, 0) = rho;
  if (m > 0) h.block(0, 1, m, m) = r_;
  r_ = std::move(h);
  q_.push_back(rho > 0 ? Eigen::VectorXd(v / rho) : Eigen::VectorXd::Zero(v.size()));
  std::vector<Rotation> chain;
  for (int i = m; i >= 1; --i) {
    const double a = r_(i - 1, 0), b = r_(i, 0);
    if (b == 0.0) continue;
    const double n = std::hypot(a, b);
    rotateR(i - 1, i, a / n, b / n, 0);
    chain.push_back({i - 1, a / n, b / n});
    r_(i, 0) = 0.0;
  }
  rotateQ(chain);
}

void QrFactorization::rotateQ(const std::vector<Rotation>& chain) {
  // The rotations (k, k + 1) of one insertion, in their order, applied block by block of rows:
  // each long column is read and written once instead of once per rotation touching it. Every
  // element sees the same operations in the same order as rotation by rotation (bit-identical).
  if (chain.empty()) return;
  constexpr Eigen::Index kBlock = 256;
  const Eigen::Index n = q_.front().size();
  double carry[kBlock];
  for (Eigen::Index e0 = 0; e0 < n; e0 += kBlock) {
    const Eigen::Index len = std::min(kBlock, n - e0);
    int held = -1;  // the column whose new values `carry` holds
    for (const Rotation& g : chain) {
      double* qk = q_[static_cast<std::size_t>(g.k)].data() + e0;
      double* ql = q_[static_cast<std::size_t>(g.k + 1)].data() + e0;
      if (held != g.k + 1) {
        if (held >= 0) std::copy(carry, carry + len, q_[static_cast<std::size_t>(held)].data() + e0);
        std::copy(ql, ql + len, carry);
      }
      const double c = g.c, s = g.s;
      for (Eigen::Index t = 0; t < len; ++t) {
        const double a = qk[t], b = carry[t];
        carry[t] = c * a + s * b;
        ql[t] = -s * a + c * b;
      }
      held = g.k;
    }
    std::copy(carry, carry + len, q_[static_cast<std::size_t>(held)].data() + e0);
  }
}

void QrFactorization::erase(int j) {
  const int m = cols();
  // Drop column j of R; rotations then zero the subdiagonal it leaves in columns j..m-2.
  Eigen::MatrixXd r(m, m - 1);
  for (int c = 0, k = 0; c < m; ++c)
    if (c != j) r.col(k++) = r_.col(c);
  r_ = std::move(r);
  for (int k = j; k < m - 1; ++k) {
    const double a = r_(k, k), b = r_(k + 1, k);
    if (b == 0.0) continue;
    const double n = std::hypot(a, b);
    rotate(k, k + 1, a / n, b / n, k);
    r_(k + 1, k) = 0.0;
  }
  r_.conservativeResize(m - 1, m - 1);
  q_.pop_back();
}

void QrFactorization::clear() {
  q_.clear();
  r_.resize(0, 0);
}

Eigen::VectorXd QrFactorization::solve(const Eigen::VectorXd& rhs) const {
  const int m = cols();
  Eigen::VectorXd b(m);
  for (int i = 0; i < m; ++i) b[i] = comm_.sum(q_[static_cast<std::size_t>(i)].dot(rhs));
  return r_.triangularView<Eigen::Upper>().solve(b);
}

}  // namespace mpmice::coupler
