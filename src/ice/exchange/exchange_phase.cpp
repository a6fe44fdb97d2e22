// IceSolver phase 10: pointwise implicit momentum and heat exchange over all materials per cell,
//   m_r u_r + dt V sum_s theta_r theta_s K_rs (u_r - u_s) = m_r u_r^L     (same shape for m cv T, H)
// solved with pointwiseExchange(). Momentum is conserved exactly. The kinetic energy the drag
// removes, D = sum_r m_r (|u_r^L|^2 - |u_r|^2) / 2 >= 0, becomes heat shared in proportion to the
// heat capacities m_r cv_r (every material warms by D / sum_r m_r cv_r), so total energy is
// conserved. Not given to the material that lost the speed: a trace of fluid in a solid cell
// (mass ~1e-10 of the cell's) would take all of it, +|du|^2/2 per unit mass each step, and its
// specific volume, hence du = dt v grad p, grows with its temperature: a runaway (the seed
// cylinder's wall, docs/coupling.md). Uintah's exchange converts none of D to internal energy.
// The increments of external materials are kept for the coupler (their energy adds to their share
// of the Lagrangian phase's energy correction). With solids, the fluids' Lagrangian kinetic energy
// is paid in the Lagrangian phase and, in a cell with a solid, the correction is shared by heat
// capacity there (lagrangian_phase.cpp), so the gas a solid's pressure jump accelerates and the
// drag stops neither gains nor loses net energy (docs/coupling.md "Energy budget").
#include <algorithm>

#include "ice/exchange/pointwise_exchange.h"
#include "ice/ice_constants.h"
#include "ice/solver/ice_solver.h"
#include "ice/sources/energy_shares.h"
#include "ice/state/fixed_counts.h"

namespace mpmice::ice {

void IceSolver::exchange() {
  const int nm = numMaterials();
  const int dim = mesh_.dim();
  const double V = mesh_.cellVolume();
  const double dtV = dt_ * V;
  for (MaterialState& m : st_.mat) {
    m.dMom.fill(0.0);  // dEnergy holds the Lagrangian phase's share already; the heat is added
  }
  if (nm < 2 || (!anyK_ && !anyH_)) {
    relaxEmbeddedFluidTemperatures();
    return;
  }
  struct Ptr {
    const double *m, *th, *vL;
    double *uL[3], *eL, *dMom[3], *dE;
    double cv;
    bool external;
  };
  std::vector<Ptr> ptr(static_cast<std::size_t>(nm));
  for (int r = 0; r < nm; ++r) {
    MaterialState& m = st_.mat[r];
    const auto uL = core::components(m.lagVel());
    ptr[r] = {m.mass.data(), m.theta.data(), m.lagSpvol().data(), {uL[0], uL[1], uL[2]}, m.lagEint().data(),
              {m.dMom.data(0), m.dMom.data(1), m.dMom.data(2)}, m.dEnergy.data(),
              m.eos->cv(), m.external};
  }
  const core::Box& sb = st_.press.box();
  dragHeat_.resize(static_cast<std::size_t>(owned_.numPts()));
  double* const drag = dragHeat_.data();  // per owned cell: the drag heat D [J] (applyDeferredCorrection)
  // The kinetic energy the drag dissipates D [J] and the heat capacity C = sum m cv [J/K] of one
  // cell after its momentum exchange (T double; D, C start at 0), or of four (T lanes::v4d).
  auto dragHeat = [&]<class T>(int n, int nd, const T* x, const T* x0, const T* mass, T& D, T& C) {
    for (int r = 0; r < n; ++r) {
      for (int d = 0; d < nd; ++d) {
        const T un = x[d * n + r], uo = x0[d * n + r];
        D += 0.5 * mass[r] * (uo - un) * (uo + un);
      }
      C += mass[r] * ptr[r].cv;
    }
  };
  // One cell (stored index c, owned index o). NM, DIM > 0: the number of materials and the mesh's
  // dimension fixed at compile time (the small loops unroll; the same operations in the same
  // order as with the run-time counts, 0).
  auto cell = [&]<int NM, int DIM>(std::int64_t c, std::int64_t o) __attribute__((always_inline)) {
    const int n = NM > 0 ? NM : nm;
    const int nd = DIM > 0 ? DIM : dim;
    double s[kMaxMaterials], w[kMaxMaterials * kMaxMaterials], x[3 * kMaxMaterials], x0[3 * kMaxMaterials];
    double mass[kMaxMaterials], th[kMaxMaterials];
    for (int r = 0; r < n; ++r) {
      mass[r] = ptr[r].m[c];
      th[r] = ptr[r].th[c];
    }
    if (anyK_) {
      for (int r = 0; r < n; ++r) {
        s[r] = mass[r];
        for (int d = 0; d < nd; ++d) x[d * n + r] = x0[d * n + r] = ptr[r].uL[d][c];
      }
      exchangeCouplings(n, dtV, K_.data(), th, w);
      pointwiseExchange(n, s, w, x, nd);
      double D = 0, C = 0;
      dragHeat(n, nd, x, x0, mass, D, C);
      drag[o] = D;
      for (int r = 0; r < n; ++r) {
        const Ptr& Q = ptr[r];
        const double de = C > 0 ? D * ptr[r].cv / C : 0.0;
        for (int d = 0; d < nd; ++d) {
          const double un = x[d * n + r], uo = x0[d * n + r];
          Q.uL[d][c] = un;
          if (Q.external) Q.dMom[d][o] = mass[r] * (un - uo);
        }
        Q.eL[c] += de;
        if (Q.external) Q.dE[o] += mass[r] * de;
      }
    }
    if (anyH_) {
      for (int r = 0; r < n; ++r) {
        const MaterialState& m = st_.mat[r];
        s[r] = mass[r] * ptr[r].cv;
        x[r] = x0[r] = m.eos->temperature(1.0 / ptr[r].vL[c], ptr[r].eL[c]);
      }
      exchangeCouplings(n, dtV, H_.data(), th, w);
      pointwiseExchange(n, s, w, x, 1);
      for (int r = 0; r < n; ++r) {
        const double de = ptr[r].cv * (x[r] - x0[r]);
        ptr[r].eL[c] += de;
        if (ptr[r].external) ptr[r].dE[o] += mass[r] * de;
      }
    }
  };
  // cell() at the four cells c .. c + 3 (the lanes, lanes.h): the same operations in the same
  // order (the temperature's, (e - e_cold(rho)) / cv, too), branches as selects.
  auto cellLanes = [&]<int NM, int DIM>(std::int64_t c, std::int64_t o) __attribute__((always_inline)) {
    using lanes::v4d, lanes::load, lanes::store, lanes::sel, lanes::splat;
    v4d s[NM], w[NM * NM], x[3 * NM], x0[3 * NM], mass[NM], th[NM];
    for (int r = 0; r < NM; ++r) {
      mass[r] = load(ptr[r].m + c);
      th[r] = load(ptr[r].th + c);
    }
    if (anyK_) {
      for (int r = 0; r < NM; ++r) {
        s[r] = mass[r];
        for (int d = 0; d < DIM; ++d) x[d * NM + r] = x0[d * NM + r] = load(ptr[r].uL[d] + c);
      }
      exchangeCouplingsLanes<NM>(dtV, K_.data(), th, w);
      pointwiseExchangeLanes<NM, DIM>(s, w, x);
      v4d D = splat(0.0), C = splat(0.0);
      dragHeat(NM, DIM, x, x0, mass, D, C);
      store(drag + o, D);
      for (int r = 0; r < NM; ++r) {
        const Ptr& Q = ptr[r];
        const v4d de = sel(C > 0, D * ptr[r].cv / C, splat(0.0));
        for (int d = 0; d < DIM; ++d) {
          const v4d un = x[d * NM + r], uo = x0[d * NM + r];
          store(Q.uL[d] + c, un);
          if (Q.external) store(Q.dMom[d] + o, mass[r] * (un - uo));
        }
        store(Q.eL + c, load(Q.eL + c) + de);
        if (Q.external) store(Q.dE + o, load(Q.dE + o) + mass[r] * de);
      }
    }
    if (anyH_) {
      for (int r = 0; r < NM; ++r) {
        const Eos& eos = *st_.mat[r].eos;
        s[r] = mass[r] * ptr[r].cv;
        const v4d rho = 1.0 / load(ptr[r].vL + c), e = load(ptr[r].eL + c);
        const v4d cold = {eos.coldEnergy(rho[0]), eos.coldEnergy(rho[1]), eos.coldEnergy(rho[2]), eos.coldEnergy(rho[3])};
        x[r] = x0[r] = (e - cold) / eos.cv();  // Eos::temperature
      }
      exchangeCouplingsLanes<NM>(dtV, H_.data(), th, w);
      pointwiseExchangeLanes<NM, 1>(s, w, x);
      for (int r = 0; r < NM; ++r) {
        const v4d de = ptr[r].cv * (x[r] - x0[r]);
        store(ptr[r].eL + c, load(ptr[r].eL + c) + de);
        if (ptr[r].external) store(ptr[r].dE + o, load(ptr[r].dE + o) + mass[r] * de);
      }
    }
  };
  // The owned cells in forEach's order, by rows (flat indices: o counts the owned cells).
  auto sweep = [&]<int NM, int DIM>() { sweepRowsByLanes<NM, DIM, std::int64_t>(owned_, sb, cellLanes, cell); };
  withFixedCounts<false>(nm, dim, sweep);
  applyDeferredCorrection();
  relaxEmbeddedFluidTemperatures();
}

// The Lagrangian phase's correction of the cells with a solid (lagrangian_phase.cpp) and the drag
// heat just given, shared together by heat capacity: the two are mostly the kinetic energy the
// explicit acceleration gave the fluids, taken back there and returned as drag heat here. The drag
// heat is taken back out of each material (it was given at one temperature rise, which the heat
// exchange since commutes with) and the sum given with the drain guard measured from there, not
// from a fluid inflated by the drag heat (water at 5e8 J/kg by it refused its -5e8 J/kg share).
void IceSolver::applyDeferredCorrection() {
  const int nm = numMaterials();
  ShareTaker takers[kMaxMaterials];
  double shares[kMaxMaterials];
  for (const DeferredCorrection& k : deferred_) {
    const double C = k.C;
    const double Dd = dragHeat_[static_cast<std::size_t>(k.oc)];
    for (int r = 0; r < nm; ++r) {
      MaterialState& m = st_.mat[r];
      const double mass = m.mass.data()[k.c], cv = m.eos->cv();
      double* e = &m.lagEint().data()[k.c];
      double* dEn = m.external ? &m.dEnergy.data()[k.oc] : nullptr;
      const double back = Dd * cv / C;  // the drag heat's share, per unit mass
      *e -= back;
      if (dEn) *dEn -= mass * back;
      const bool cold = !m.external && mass > 0 && m.eos->hasColdEnergy();
      takers[r] = {mass, cv, e, cold ? m.eos->coldEnergy(1.0 / m.lagSpvol().data()[k.c]) : 0.0, m.external, dEn};
      shares[r] = mass * cv / C * (k.D + Dd);
    }
    const SharesGiven g = giveShares(nm, takers, shares);
    fallbacks_ += g.refused;
    if (g.lost != 0) audit_.add(g.lost, k.c, g.worst);
  }
  deferred_.clear();
}

}  // namespace mpmice::ice
