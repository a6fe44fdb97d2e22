#include "ice/linear/jacobi_cg.h"

#include <cmath>

namespace mpmice::ice::linear {

using core::Field;
using core::forEach;

double JacobiCg::dot(const Field& a, const Field& b, const core::Box& owned) const {
  double s = 0;
  forEach(owned, [&](int i, int j, int k) { s += a(i, j, k) * b(i, j, k); });
  return comm_.sum(s);
}

LinearResult JacobiCg::solve(const LinearOperator& A, const Field& b, Field& x, const core::Box& owned, double tol,
                             int maxIterations) {
  if (r_.box() != owned || p_.box() != x.box()) {
    r_ = Field("cg_residual", core::Centering::Cell, owned, 1, 0);
    z_ = Field("cg_preconditioned", core::Centering::Cell, owned, 1, 0);
    q_ = Field("cg_product", core::Centering::Cell, owned, 1, 0);
    diag_ = Field("cg_diagonal", core::Centering::Cell, owned, 1, 0);
    p_ = Field("cg_direction", core::Centering::Cell, x.box(), 1, x.nghost());
  }
  p_.fill(0.0);
  A.diagonal(diag_);
  LinearResult res;
  x.fill(0.0);
  r_.copyRegion(b, owned, owned);
  const double bnorm = std::sqrt(dot(b, b, owned));
  if (!(bnorm > 0)) {
    res.converged = true;
    return res;
  }
  forEach(owned, [&](int i, int j, int k) { z_(i, j, k) = r_(i, j, k) / diag_(i, j, k); });
  forEach(owned, [&](int i, int j, int k) { p_(i, j, k) = z_(i, j, k); });
  double rz = dot(r_, z_, owned);
  for (int it = 0; it < maxIterations; ++it) {
    A.apply(p_, q_);
    const double alpha = rz / dot(p_, q_, owned);
    forEach(owned, [&](int i, int j, int k) {
      x(i, j, k) += alpha * p_(i, j, k);
      r_(i, j, k) -= alpha * q_(i, j, k);
    });
    res.iterations = it + 1;
    res.error = std::sqrt(dot(r_, r_, owned));
    if (res.error <= tol * bnorm) {
      res.converged = true;
      res.error /= bnorm;
      return res;
    }
    forEach(owned, [&](int i, int j, int k) { z_(i, j, k) = r_(i, j, k) / diag_(i, j, k); });
    const double rz2 = dot(r_, z_, owned);
    const double beta = rz2 / rz;
    rz = rz2;
    forEach(owned, [&](int i, int j, int k) { p_(i, j, k) = z_(i, j, k) + beta * p_(i, j, k); });
  }
  res.error /= bnorm;
  return res;
}

}  // namespace mpmice::ice::linear
