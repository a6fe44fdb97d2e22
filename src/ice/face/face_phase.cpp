// IceSolver phases 3 and 6: face velocities with the pointwise implicit exchange at faces, and the
// face pressure p_f = (p_L / rho_L + p_R / rho_R) / (1 / rho_L + 1 / rho_R) (rho: mixture density).
#include <cmath>

#include "ice/exchange/face_exchange.h"
#include "ice/solver/ice_solver.h"
#include "ice/state/phase_units.h"

namespace mpmice::ice {

using core::forEach;

void IceSolver::computeFaceVelocities() {
  const int dim = mesh_.dim();
  const int nm = numMaterials();
  const double dt = dt_;
  const bool exch = anyK_ && nm > 1;
  const core::Box& sb = st_.press.box();
  const std::int64_t strides[3] = {1, sb.length(0), std::int64_t(sb.length(0)) * sb.length(1)};
  const double* p = st_.press.data();
  for (int d = 0; d < dim; ++d) {
    const double dx = mesh_.dx(d);
    const double g = gravity_[d];
    const std::int64_t sd = strides[d];
    const core::Box fb = owned_.faces(d);
    const bool inLo = bc_.touches(2 * d) && bc_.type(2 * d) == core::BoundaryType::Inflow;
    const bool inHi = bc_.touches(2 * d + 1) && bc_.type(2 * d + 1) == core::BoundaryType::Inflow;
    struct Ptr {
      const double *m, *u;
      double* uf;
    };
    std::vector<Ptr> ptr(static_cast<std::size_t>(nm));
    for (int r = 0; r < nm; ++r) {
      MaterialState& m = st_.mat[r];
      ptr[r] = {m.mass.data(), m.vel.data(d), m.velFace[d].data()};
    }
    forEach(fb, [&](int i, int j, int k) {
      const std::int64_t cR = sb.index(i, j, k), cL = cR - sd, fi = fb.index(i, j, k);
      const double dpdx = (p[cR] - p[cL]) / dx;
      double x[kMaxMaterials], th[kMaxMaterials], vf[kMaxMaterials];
      faceMaterialValues(st_.mat, cL, cR, th, vf);
      for (int r = 0; r < nm; ++r) {
        const Ptr& P = ptr[r];
        const double mL = P.m[cL], mR = P.m[cR];
        const double msum = mL + mR;
        const double t1 = msum > 0 ? (mL * P.u[cL] + mR * P.u[cR]) / msum : 0.5 * (P.u[cL] + P.u[cR]);
        x[r] = t1 - dt * vf[r] * dpdx + dt * g;
      }
      if (exch) faceExchange(nm, dt, K_.data(), th, vf, x);
      const int idx[3] = {i, j, k};
      const bool atLo = inLo && idx[d] == owned_.lo[d], atHi = inHi && idx[d] == owned_.hi[d] + 1;
      for (int r = 0; r < nm; ++r) {
        double u = x[r];
        if (atLo) u = bc_.inflow(2 * d).velocity[d];
        if (atHi) u = bc_.inflow(2 * d + 1).velocity[d];
        ptr[r].uf[fi] = u;
      }
    });
  }
}

void computeFacePressures(IceState& st, const core::Box& owned, int dim) {
  for (int d = 0; d < dim; ++d) {
    forEach(owned.faces(d), [&](int i, int j, int k) {
      int l[3] = {i, j, k};
      l[d] -= 1;
      double rL = 0, rR = 0;
      for (const MaterialState& m : st.mat) {
        rL += m.mass(l[0], l[1], l[2]);
        rR += m.mass(i, j, k);
      }
      const double pL = st.press(l[0], l[1], l[2]), pR = st.press(i, j, k);
      st.pressFace[d](i, j, k) = (rL + rR) > 0 ? (pL * rR + pR * rL) / (rL + rR) : 0.5 * (pL + pR);
    });
  }
}

void IceSolver::computeFacePressure() { computeFacePressures(st_, owned_, mesh_.dim()); }

}  // namespace mpmice::ice
