#include "coupler/acceleration/iqn_ils.h"

#include <cmath>
#include <vector>

namespace mpmice::coupler {

Eigen::VectorXd IqnIls::performAcceleration(const Eigen::VectorXd& x, const Eigen::VectorXd& xt) {
  const Eigen::VectorXd r = xt - x;
  if (havePrev_) current_.push_front({r - rPrev_, xt - xtPrev_});
  rPrev_ = r;
  xtPrev_ = xt;
  havePrev_ = true;

  // Gather columns: this step's, then the reused steps', newest first.
  std::vector<const Column*> cols;
  for (const auto& c : current_) cols.push_back(&c);
  for (const auto& step : past_)
    for (const auto& c : step) cols.push_back(&c);
  if (cols.empty()) {
    used_ = 0;
    return x + w0_ * r;
  }

  // Modified Gram-Schmidt (twice, for stability) with the QR filter: Q columns orthonormal,
  // R upper triangular. Columns whose orthogonal part is too small are dropped.
  std::vector<Eigen::VectorXd> q;
  std::vector<const Column*> kept;
  std::vector<std::vector<double>> rcols;  // R column j: coefficients on q_0..q_j
  for (const Column* c : cols) {
    Eigen::VectorXd v = c->v;
    const double norm0 = std::sqrt(comm_.sum(v.squaredNorm()));
    if (!(norm0 > 0)) continue;
    std::vector<double> coeff(q.size() + 1, 0.0);
    for (int pass = 0; pass < 2; ++pass)
      for (std::size_t i = 0; i < q.size(); ++i) {
        const double h = comm_.sum(q[i].dot(v));
        coeff[i] += h;
        v -= h * q[i];
      }
    const double rho = std::sqrt(comm_.sum(v.squaredNorm()));
    if (rho < filter_ * norm0) continue;  // near-dependent on newer columns: filtered out
    coeff.back() = rho;
    q.push_back(v / rho);
    kept.push_back(c);
    rcols.push_back(std::move(coeff));
  }
  used_ = static_cast<int>(kept.size());
  if (kept.empty()) return x + w0_ * r;

  // Solve R a = -Q^T r by back substitution.
  const std::size_t m = kept.size();
  std::vector<double> b(m), a(m, 0.0);
  for (std::size_t i = 0; i < m; ++i) b[i] = -comm_.sum(q[i].dot(r));
  for (std::size_t ii = m; ii-- > 0;) {
    double s = b[ii];
    for (std::size_t j = ii + 1; j < m; ++j) s -= rcols[j][ii] * a[j];
    a[ii] = s / rcols[ii][ii];
  }
  Eigen::VectorXd next = xt;
  for (std::size_t j = 0; j < m; ++j) next += a[j] * kept[j]->w;
  return next;
}

void IqnIls::iterationsConverged() {
  if (reuse_ > 0 && !current_.empty()) {
    past_.push_front(std::move(current_));
    while (static_cast<int>(past_.size()) > reuse_) past_.pop_back();
  }
  current_.clear();
  havePrev_ = false;
}

}  // namespace mpmice::coupler
