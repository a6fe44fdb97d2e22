// IceSolver phase 5, semi-implicit: the pressure increment solves
//   kbar dp - dt^2 div( beta_f grad dp ) = -dt div U*,    beta_f = sum_r theta_r,f v_r,f
// (theta upwinded by the face velocity u*, v the harmonic face mean used in the face velocity),
// a symmetric positive definite system: matrix-free preconditioned CG over all ranks (`cg`, with
// ghost exchange per product) or Eigen's BiCGSTAB on the assembled matrix (`bicgstab`, one rank).
// Then u_f,r = u*_f,r - dt v_r,f grad dp and p = p_eq + dp.
#include <Eigen/Sparse>
#include <cmath>
#include <stdexcept>

#include "ice/exchange/pointwise_exchange.h"
#include "ice/solver/ice_solver.h"

namespace mpmice::ice {

using core::Field;
using core::forEach;

void IceSolver::solveSemiImplicit() {
  const int dim = mesh_.dim();
  const int nm = numMaterials();
  const double dt = dt_;
  divergence();
  // Face mobilities phi_r (the face velocity's response to a pressure gradient, -dt phi_r grad dp),
  // including the pointwise exchange at the face: (diag(s) + L(w)) phi = theta (s = theta / v), so
  // phi_r = v_r without exchange and 1 / rho_mixture for K -> infinity. Coefficients
  // dt^2 beta_f / dx^2 with beta_f = sum_r theta_r,f phi_r.
  std::vector<std::array<Field, 3>> phi(static_cast<std::size_t>(nm));
  std::array<Field, 3> coef;
  const bool exch = anyK_ && nm > 1;
  for (int d = 0; d < dim; ++d) {
    coef[d] = Field("beta", core::Centering::Cell, owned_.faces(d), 1, 0);
    for (auto& ph : phi) ph[d] = Field("phi", core::Centering::Cell, owned_.faces(d), 1, 0);
    const double dx2 = mesh_.dx(d) * mesh_.dx(d);
    forEach(owned_.faces(d), [&](int i, int j, int k) {
      int l[3] = {i, j, k};
      l[d] -= 1;
      double sv[kMaxMaterials], w[kMaxMaterials * kMaxMaterials], x[kMaxMaterials], th[kMaxMaterials];
      for (int r = 0; r < nm; ++r) {
        const MaterialState& m = st_.mat[r];
        x[r] = faceSpecificVolume(m.mass(l[0], l[1], l[2]), m.spvol(l[0], l[1], l[2]), m.mass(i, j, k),
                                  m.spvol(i, j, k));
        th[r] = 0.5 * (m.theta(l[0], l[1], l[2]) + m.theta(i, j, k));
        sv[r] = th[r] / x[r];
      }
      if (exch) {
        for (int r = 0; r < nm; ++r)
          for (int q = 0; q < nm; ++q) w[r * nm + q] = dt * K_[r * nm + q] * th[r] * th[q];
        pointwiseExchange(nm, sv, w, x, 1);
      }
      double b = 0;
      for (int r = 0; r < nm; ++r) {
        const MaterialState& m = st_.mat[r];
        const double uf = m.velFace[d](i, j, k);
        b += (uf > 0 ? m.theta(l[0], l[1], l[2]) : m.theta(i, j, k)) * x[r];
        phi[r][d](i, j, k) = x[r];
      }
      coef[d](i, j, k) = dt * dt * b / dx2;
    });
  }
  Field kb("kbar", core::Centering::Cell, owned_, 1, 0), rhs("rhs", core::Centering::Cell, owned_, 1, 0);
  forEach(owned_, [&](int i, int j, int k) {
    double s = 0;
    for (const MaterialState& m : st_.mat) s += m.theta(i, j, k) * m.kappa(i, j, k);
    kb(i, j, k) = s;
    rhs(i, j, k) = -dt * st_.divU(i, j, k);
  });
  Field& x = st_.dp;
  auto neighbour = [&](const Field& f, int i, int j, int k, int d, int s) {
    int n[3] = {i, j, k};
    n[d] += s;
    return f(n[0], n[1], n[2]);
  };
  // y = A x over owned cells (x's ghosts must be filled).
  auto apply = [&](const Field& xx, Field& y) {
    forEach(owned_, [&](int i, int j, int k) {
      const double xc = xx(i, j, k);
      double acc = kb(i, j, k) * xc;
      for (int d = 0; d < dim; ++d) {
        int u[3] = {i, j, k};
        u[d] += 1;
        acc += coef[d](i, j, k) * (xc - neighbour(xx, i, j, k, d, -1));
        acc += coef[d](u[0], u[1], u[2]) * (xc - neighbour(xx, i, j, k, d, +1));
      }
      y(i, j, k) = acc;
    });
  };

  if (bicgstab_) {
    // Assemble over owned cells (one rank): ghosts map to periodic images, mirrors or zeros.
    const core::Box dom = mesh_.cellBox();
    const auto per = decomp_.periodic();
    const int n = static_cast<int>(owned_.numPts());
    std::vector<Eigen::Triplet<double>> trip;
    Eigen::VectorXd b(n), sol(n);
    forEach(owned_, [&](int i, int j, int k) {
      const int row = static_cast<int>(owned_.index(i, j, k));
      double diag = kb(i, j, k);
      for (int d = 0; d < dim; ++d)
        for (int s = -1; s <= 1; s += 2) {
          int nb[3] = {i, j, k};
          nb[d] += s;
          int f[3] = {i, j, k};
          if (s > 0) f[d] += 1;
          const double c = coef[d](f[0], f[1], f[2]);
          if (nb[d] < dom.lo[d] || nb[d] > dom.hi[d]) {
            if (per[d]) {
              nb[d] = nb[d] < dom.lo[d] ? dom.hi[d] : dom.lo[d];
            } else {
              if (bc_.fixedPressure(2 * d + (s > 0 ? 1 : 0))) diag += c;
              continue;  // mirror: no coupling
            }
          }
          diag += c;
          trip.emplace_back(row, static_cast<int>(owned_.index(nb[0], nb[1], nb[2])), -c);
        }
      trip.emplace_back(row, row, diag);
      b[row] = rhs(i, j, k);
    });
    Eigen::SparseMatrix<double> Am(n, n);
    Am.setFromTriplets(trip.begin(), trip.end());
    Eigen::BiCGSTAB<Eigen::SparseMatrix<double>, Eigen::DiagonalPreconditioner<double>> solver;
    solver.setTolerance(solverTol_);
    solver.setMaxIterations(solverMaxIt_);
    solver.compute(Am);
    sol = solver.solve(b);
    if (solver.info() != Eigen::Success)
      throw std::runtime_error("ice: semi-implicit pressure (bicgstab) did not converge: error " +
                               std::to_string(solver.error()) + " after " + std::to_string(solver.iterations()) +
                               " iterations");
    forEach(owned_, [&](int i, int j, int k) { x(i, j, k) = sol[owned_.index(i, j, k)]; });
  } else {
    Field r("r", core::Centering::Cell, owned_, 1, 0), z = r, q = r;
    Field pdir("p", core::Centering::Cell, x.box(), 1, kGhost);
    Field diag("diag", core::Centering::Cell, owned_, 1, 0);
    forEach(owned_, [&](int i, int j, int k) {
      double dg = kb(i, j, k);
      for (int d = 0; d < dim; ++d) {
        int u[3] = {i, j, k};
        u[d] += 1;
        dg += coef[d](i, j, k) + coef[d](u[0], u[1], u[2]);
      }
      diag(i, j, k) = dg;
    });
    auto dot = [&](const Field& a, const Field& b) {
      double s = 0;
      forEach(owned_, [&](int i, int j, int k) { s += a(i, j, k) * b(i, j, k); });
      return comm_.sum(s);
    };
    x.fill(0.0);
    r.copyRegion(rhs, owned_, owned_);
    const double bnorm = std::sqrt(dot(rhs, rhs));
    if (bnorm > 0) {
      forEach(owned_, [&](int i, int j, int k) { z(i, j, k) = r(i, j, k) / diag(i, j, k); });
      forEach(owned_, [&](int i, int j, int k) { pdir(i, j, k) = z(i, j, k); });
      double rz = dot(r, z);
      bool ok = false;
      int it = 0;
      for (; it < solverMaxIt_; ++it) {
        fillGhosts({{&pdir, FieldKind::Increment}}, {-1});
        apply(pdir, q);
        const double alpha = rz / dot(pdir, q);
        forEach(owned_, [&](int i, int j, int k) {
          x(i, j, k) += alpha * pdir(i, j, k);
          r(i, j, k) -= alpha * q(i, j, k);
        });
        if (std::sqrt(dot(r, r)) <= solverTol_ * bnorm) {
          ok = true;
          break;
        }
        forEach(owned_, [&](int i, int j, int k) { z(i, j, k) = r(i, j, k) / diag(i, j, k); });
        const double rz2 = dot(r, z);
        const double beta = rz2 / rz;
        rz = rz2;
        forEach(owned_, [&](int i, int j, int k) { pdir(i, j, k) = z(i, j, k) + beta * pdir(i, j, k); });
      }
      if (!ok)
        throw std::runtime_error("ice: semi-implicit pressure (cg) did not reach the tolerance " +
                                 std::to_string(solverTol_) + " in " + std::to_string(solverMaxIt_) +
                                 " iterations (ice.solver_max_iterations)");
    }
  }
  fillGhosts({{&x, FieldKind::Increment}}, {-1});
  // Correct the face velocities and the divergence.
  for (int d = 0; d < dim; ++d) {
    const double dx = mesh_.dx(d);
    forEach(owned_.faces(d), [&](int i, int j, int k) {
      int l[3] = {i, j, k};
      l[d] -= 1;
      const double g = (x(i, j, k) - x(l[0], l[1], l[2])) / dx;
      for (int r = 0; r < nm; ++r) st_.mat[r].velFace[d](i, j, k) -= dt * phi[r][d](i, j, k) * g;
    });
  }
  divergence();
  forEach(owned_, [&](int i, int j, int k) { st_.press(i, j, k) = st_.pressEq(i, j, k) + x(i, j, k); });
}

}  // namespace mpmice::ice
