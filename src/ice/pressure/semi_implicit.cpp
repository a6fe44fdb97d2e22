// IceSolver phase 5, semi-implicit: the pressure increment solves
//   kbar dp - w dt^2 div( beta_f grad dp ) = -dt div U*,    beta_f = sum_r theta_r,f phi_r,f
// (theta upwinded by the face velocity u*, phi the face mobility with the exchange at faces; w the
// time weight ice.semi_implicit_theta: 1 backward Euler, 0.5 Crank-Nicolson),
// a symmetric positive definite system: ice/linear's Jacobi-preconditioned CG over all ranks
// (`cg`, with ghost exchange per product), hypre's structured PCG preconditioned by PFMG or SMG
// on the assembled stencil over all ranks (`pfmg_pcg`, `smg_pcg`) or Eigen's BiCGSTAB on it
// (`bicgstab`, one rank). Then u_f,r = u*_f,r - w dt phi_r,f grad dp and p = p_eq + w dp, the
// pressure the face pressure and the Lagrangian phase take (with w = 0.5 the step's midpoint: the
// p dV work of an expansion at the end-of-step pressure heated a strong rarefaction, docs/ice.md).
#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "ice/exchange/face_exchange.h"
#include "ice/face/solid_faces.h"
#include "ice/linear/bicgstab.h"
#include "ice/linear/hypre_struct_pcg.h"
#include "ice/solver/ice_solver.h"
#include "ice/state/phase_units.h"

namespace mpmice::ice {

using core::Field;
using core::forEach;

void IceSolver::allocateSemiImplicitScratch() {
  const int dim = mesh_.dim();
  const int nm = numMaterials();
  SemiImplicitScratch& S = semi_;
  if (S.mobility.size() != static_cast<std::size_t>(nm)) {
    S.mobility.assign(static_cast<std::size_t>(nm), {});
    for (auto& ph : S.mobility)
      for (int d = 0; d < dim; ++d) ph[d] = Field("mobility", core::Centering::Cell, owned_.faces(d), 1, 0);
    S.stencil.allocate(owned_, dim);
    S.stencil.fillGhosts = [this](Field& f) { fillGhosts({{&f, FieldKind::Increment}}, {-1}); };
    S.rhs = Field("rhs", core::Centering::Cell, owned_, 1, 0);
  }
}

void IceSolver::assembleSemiImplicit() {
  const int dim = mesh_.dim();
  const int nm = numMaterials();
  const double dt = dt_;
  SemiImplicitScratch& S = semi_;
  allocateSemiImplicitScratch();
  // The mobilities come with this step's face velocities (computeFaceVelocities, the same
  // exchange solve); computed here when the state was set in between.
  const bool fresh = S.mobilityFresh;
  S.mobilityFresh = false;
  // Face mobilities phi_r (the face velocity's response to a pressure gradient, -dt phi_r grad dp),
  // including the pointwise exchange at the face: (diag(s) + L(w)) phi = theta (s = theta / v), so
  // phi_r = v_r without exchange and 1 / rho_mixture for K -> infinity. Coefficients
  // dt^2 beta_f / dx^2 with beta_f = sum_r theta_r,f phi_r.
  const bool exch = anyK_ && nm > 1;
  const core::Box& sb = st_.press.box();
  const std::int64_t strides[3] = {1, sb.length(0), std::int64_t(sb.length(0)) * sb.length(1)};
  for (int d = 0; d < dim; ++d) {
    const double dx2 = mesh_.dx(d) * mesh_.dx(d);
    const std::int64_t sd = strides[d];
    Field& coef = S.stencil.coef[d];
    const core::Box fb = owned_.faces(d);
    const SolidFaces& sf = st_.solidFaces;
    forEach(fb, [&](int i, int j, int k) {
      const std::int64_t cR = sb.index(i, j, k), cL = cR - sd, fi = fb.index(i, j, k);
      double x[kMaxMaterials];
      if (fresh) {
        for (int r = 0; r < nm; ++r) x[r] = S.mobility[r][d].data()[fi];
      } else {
        double th[kMaxMaterials];
        faceMaterialValues(st_.mat, cL, cR, th, x);
        openSolidFaceExchange(st_, d, fi, th);
        if (exch) faceExchange(nm, dt, K_.data(), th, x, x);
        for (int r = 0; r < nm; ++r) S.mobility[r][d].data()[fi] = x[r];
      }
      double b = 0, tsum = 0;
      for (int r = 0; r < nm; ++r) {
        const MaterialState& m = st_.mat[r];
        const double uf = m.velFace[d].data()[fi];
        // With the solids' face transport their volume flux does not answer to the pressure:
        // the fluids' does, through the open part of the face (computeVolumeFluxes).
        if (sf.on && m.external) continue;
        const double t = m.theta.data()[uf > 0 ? cL : cR];
        b += t * x[r];
        tsum += t;
      }
      if (sf.on) b = tsum > 0 ? (1.0 - sf.cover[d].data()[fi]) * b / tsum : 0.0;
      coef(i, j, k) = semiTheta_ * dt * dt * b / dx2;
    });
  }
  const VolumeFluxFaces faces(st_, mesh_, owned_);  // the divergence of the face volume fluxes
  forEach(owned_, [&](int i, int j, int k) {
    double s = 0;
    for (const MaterialState& m : st_.mat) s += m.theta(i, j, k) * m.kappa(i, j, k);
    S.stencil.centre(i, j, k) = s;
    const std::int64_t f[3] = {faces.box[0].index(i, j, k), dim > 1 ? faces.box[1].index(i, j, k) : 0,
                               dim > 2 ? faces.box[2].index(i, j, k) : 0};
    S.rhs(i, j, k) = -dt * faces.divergence(dim, f);
  });
}

linear::HypreStructPcg& IceSolver::structSolver() {
  // SMG's plane smoother is itself built from the set-up's matrix, so a lagged SMG preconditions
  // poorly (the jump test of test_hypre_pressure: 57 iterations in 10 steps against 22 fresh):
  // ice.preconditioner_reuse applies to PFMG only.
  const bool pfmg = linearSolver_ == LinearSolver::PfmgPcg;
  if (!semi_.hypre)
    semi_.hypre = std::make_unique<linear::HypreStructPcg>(
        comm_, pfmg ? linear::StructPreconditioner::Pfmg : linear::StructPreconditioner::Smg,
        pfmg ? preconditionerReuse_ : 1);
  return *semi_.hypre;
}

long IceSolver::preconditionerSetups() const { return semi_.hypre ? semi_.hypre->setups() : 0; }

std::string IceSolver::pressureSolveSummary(long steps) const {
  std::ostringstream o;
  o << "ice: semi-implicit pressure (" << linearSolverName_ << "), " << linItersTotal_ << " linear iterations in "
    << steps << " steps (" << double(linItersTotal_) / double(std::max(1L, steps)) << " per step)";
  if (const long setups = preconditionerSetups(); setups > 0)
    o << ", " << setups << " multigrid set-ups (ice.preconditioner_reuse "
      << (linearSolver_ == LinearSolver::PfmgPcg ? preconditionerReuse_ : 1) << ")";
  return o.str();
}

void IceSolver::solvePressureSystem() {
  SemiImplicitScratch& S = semi_;
  Field& x = st_.dp;
  linear::StencilBoundary bc{mesh_.cellBox(), decomp_.periodic(), {}};
  for (int s = 0; s < 6; ++s) bc.fixedSide[s] = bc_.fixedPressure(s);
  linear::LinearResult res;
  switch (linearSolver_) {
    case LinearSolver::Cg:
      if (!S.cg) S.cg = std::make_unique<linear::JacobiCg>(comm_);
      res = S.cg->solve(S.stencil, S.rhs, x, owned_, solverTol_, solverMaxIt_);
      break;
    case LinearSolver::Bicgstab:
      res = linear::solveBicgstab(S.stencil, bc, S.rhs, x, solverTol_, solverMaxIt_);
      break;
    case LinearSolver::PfmgPcg:
    case LinearSolver::SmgPcg:
      res = structSolver().solve(S.stencil, bc, S.rhs, x, solverTol_, solverMaxIt_);
      break;
  }
  linIters_ = res.iterations;
  linItersTotal_ += res.iterations;
  if (!res.converged)
    throw std::runtime_error("ice: semi-implicit pressure (" + linearSolverName_ + ") did not reach the tolerance " +
                             std::to_string(solverTol_) + " in " + std::to_string(solverMaxIt_) +
                             " iterations (ice.solver_max_iterations): relative residual " +
                             std::to_string(res.error) + " after " + std::to_string(res.iterations));
}

void IceSolver::solveSemiImplicit() {
  const int dim = mesh_.dim();
  const int nm = numMaterials();
  computeVolumeFluxes(st_, mesh_, owned_);
  assembleSemiImplicit();
  solvePressureSystem();
  Field& x = st_.dp;
  fillGhosts({{&x, FieldKind::Increment}}, {-1});
  // Correct the face velocities and the divergence.
  const core::Box& sb = x.box();
  const std::int64_t strides[3] = {1, sb.length(0), std::int64_t(sb.length(0)) * sb.length(1)};
  const double* xp = x.data();
  for (int d = 0; d < dim; ++d) {
    const double dx = mesh_.dx(d);
    const std::int64_t sd = strides[d];
    const core::Box fb = owned_.faces(d);
    double* uf[kMaxMaterials];
    const double* phi[kMaxMaterials];
    for (int r = 0; r < nm; ++r) uf[r] = st_.mat[r].velFace[d].data(), phi[r] = semi_.mobility[r][d].data();
    forEach(fb, [&](int i, int j, int k) {
      const std::int64_t c = sb.index(i, j, k), f = fb.index(i, j, k);
      const double g = (xp[c] - xp[c - sd]) / dx;
      for (int r = 0; r < nm; ++r) uf[r][f] -= semiTheta_ * dt_ * phi[r][f] * g;
    });
  }
  computeVolumeFluxes(st_, mesh_, owned_);
  // p = p_eq + w dp (p holds the equilibrium pressure until here).
  forEach(owned_, [&](int i, int j, int k) { st_.press(i, j, k) += semiTheta_ * x(i, j, k); });
}

}  // namespace mpmice::ice
