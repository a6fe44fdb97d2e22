// IceSolver phases 8-9 and 11: momentum and energy sources at cell centres, the Lagrangian values
// and the specific volume evolution.
//   u_L = u - dt v_r grad(p_f) + dt g (+ viscous),      e_L = e - dt p v_r (kappa_r / kbar) div U (+ viscous heat)
//   v_L = v (1 + dt (kappa_r / kbar) div U),            U = sum_s theta_s u_f,s
// The total energy is made conservative: the mismatch between the flux form -dt sum_faces A p_f U_f
// (the p dV work of every material in the cell, U summed over all of them) and what the materials
// take (the fluids' kinetic plus internal changes above, and for an external material (a solid)
// the work its own solver says the pressure forces did on it: setExternalCouplingWork) is a
// truncation error; it is given to the materials in proportion to theta_r kappa_r (fluids alone)
// or to their heat capacities m_r cv_r (a cell with a solid), an external material's share as
// energy to its solver (dEnergy, with the exchange heat); where the solid's own volume change is
// given (setExternalVolumeChange), the p dV work of its difference from the solid's theta-kappa
// share goes to the fluids first (below). So closed boxes keep
// their total energy to round-off, with solids or without. Energy sources add
// power * theta * V * dt to their material.
#include <algorithm>
#include <cmath>
#include <utility>

#include "ice/exchange/pointwise_exchange.h"  // kMaxMaterials
#include "ice/ice_constants.h"
#include "ice/solver/ice_solver.h"
#include "ice/sources/energy_shares.h"
#include "ice/state/phase_units.h"

namespace mpmice::ice {

using core::forEach;

void IceSolver::computeSourcesAndLagrangian() {
  const int dim = mesh_.dim();
  const int nm = numMaterials();
  const double V = mesh_.cellVolume();
  const double dt = dt_;
  for (MaterialState& m : st_.mat) m.dEnergy.fill(0.0);  // an external share is added below
  const core::Box& sb = st_.press.box();
  struct Ptr {
    const double *th, *ka, *v, *m, *u[3], *e;
    double *uL[3], *eL, *vL;
    double cv;
    bool external;
    const double* work;  // an external material's coupling work, owned cells (index oc below)
    const double* dVs;   // its own volume change, owned cells (null: not given)
    double* dEn;         // its exchange energy, owned cells
    const Eos* eos;
    bool cold;  // the EOS has a cold energy (e - e_cold is the thermal energy the fix guards)
  };
  // A fluid's velocity and energy become its Lagrangian ones in place (u and uL, e and eL below
  // are the same arrays; ice_state.h): the start values are kept where a later phase reads them.
  for (MaterialState& m : st_.mat) {
    if (m.external) continue;
    if (anyExternal_ || m.conductivity > 0) m.eintStart = m.eint;
    if (m.viscosity > 0 || q1_ > 0 || q2_ > 0) m.velStart = m.vel;  // shock viscosity: advectFluids
  }
  std::vector<Ptr> ptrs(static_cast<std::size_t>(nm));
  Ptr* const ptr = ptrs.data();
  for (int r = 0; r < nm; ++r) {
    MaterialState& m = st_.mat[r];
    const auto u = core::components(m.vel);
    const auto uL = core::components(m.lagVel());
    ptr[r] = {m.theta.data(), m.kappa.data(), m.spvol.data(), m.mass.data(), {u[0], u[1], u[2]}, m.eint.data(),
              {uL[0], uL[1], uL[2]}, m.lagEint().data(), m.lagSpvol().data(), m.eos->cv(), m.external,
              m.external ? m.couplingWork.data() : nullptr,
              m.external && m.volumeChangeGiven ? m.volumeChange.data() : nullptr,
              m.external ? m.dEnergy.data() : nullptr, m.eos.get(),
              m.eos->hasColdEnergy()};
  }
  const double* press = st_.press.data();
  // Per direction: the face volume fluxes (their face box, the stride to the face above a cell,
  // dx) and the face pressures on the same faces.
  const VolumeFluxFaces faces(st_, mesh_, owned_);
  const double* const* UF = faces.U;
  const core::Box* fbs = faces.box;
  const std::int64_t* fs = faces.stride;
  const double* dxs = faces.dx;
  const double* pF[3] = {nullptr, nullptr, nullptr};
  for (int d = 0; d < dim; ++d) pF[d] = st_.pressFace[d].data();
  // In a cell with a solid the heat-capacity share of the correction waits for the momentum
  // exchange's drag heat (below; applyDeferredCorrection).
  const bool deferCorrection = anyK_ && nm >= 2;
  const double* Kp = K_.data();  // the momentum exchange coefficients, nm x nm
  deferred_.clear();
  // One owned cell: stored index c, oc its index in the owned box (an external material's coupling
  // work and exchange energy), fls[d] the index of its low face normal to d. NM > 0:
  // the number of materials fixed at compile time (the small loops unroll; the same operations in
  // the same order).
  auto cell = [&]<int NM>(std::int64_t c, std::int64_t oc, const std::int64_t* fls) {
    const int n = NM > 0 ? NM : nm;
    // The cell's kappa, read before its Lagrangian volumes are written: without external materials
    // they are kappa's arrays (MaterialState::lagSpvol).
    double ka[kMaxMaterials];
    for (int r = 0; r < n; ++r) ka[r] = ptr[r].ka[c];
    double kbar = 0, thetaCav = 0;
    for (int r = 0; r < n; ++r) kbar += ptr[r].th[c] * ka[r];
    // A cavitated liquid (kappa = inf, docs/ice.md "Cavitation") makes kbar infinite: the
    // cavitated liquids take the cell's volume change (shared by their volume fractions), the others none.
    const bool cavity = std::isinf(kbar);
    if (cavity)
      for (int r = 0; r < n; ++r)
        if (std::isinf(ka[r])) thetaCav += ptr[r].th[c];
    auto volumeShare = [&](int r) {
      const Ptr& P = ptr[r];
      if (!cavity) return kbar > 0 ? P.th[c] * ka[r] / kbar : 0.0;
      return std::isinf(ka[r]) ? P.th[c] / thetaCav : 0.0;
    };
    const double p = press[c];
    const double div = faces.divergence(dim, fls);
    double gp[3] = {0, 0, 0};
    double dEflux = 0;
    for (int d = 0; d < dim; ++d) {
      const std::int64_t fl = fls[d], fh = fl + fs[d];
      const double pfl = pF[d][fl], pfh = pF[d][fh];
      gp[d] = (pfh - pfl) / dxs[d];
      {
        const double* U = UF[d];
        dEflux -= dt * V * (pfh * U[fh] - pfl * U[fl]) / dxs[d];
      }
    }
    double dKE = 0, dIE = 0, dWork = 0;
    double ecL[kMaxMaterials];  // a fluid's cold energy at its Lagrangian volume (0 without one)
    for (int r = 0; r < n; ++r) {
      ecL[r] = 0.0;
      const Ptr& P = ptr[r];
      const double v = P.v[c], mass = P.m[c];
      if (!P.external && !(mass > 0)) {
        // An absent fluid (no mass here) keeps its placeholder state: accelerated and worked on
        // at its absent density, an air's state in a water cell grew 4-5 times a step (specific
        // volume 1e153 m^3/kg, e 1e158 J/kg) until it overflowed and 0 x inf turned the cell's
        // energy correction, and the water with it, into NaN (the water-filled foam model run to
        // 1 ms stopped at 545 us, docs/ice.md "The Lagrangian work of a small compressible phase").
        for (int d = 0; d < dim; ++d) P.uL[d][c] = P.u[d][c];
        P.eL[c] = P.e[c];
        P.vL[c] = v;
        continue;
      }
      const double f = P.th[c] > 0 ? volumeShare(r) / P.th[c] : (kbar > 0 && !cavity ? ka[r] / kbar : 0.0);
      double ke0 = 0, ke1 = 0;
      for (int d = 0; d < dim; ++d) {
        const double u = P.u[d][c];
        const double uL = u - dt * v * gp[d];
        P.uL[d][c] = uL;
        ke0 += u * u;
        ke1 += uL * uL;
      }
      // Relative volume change of the material; a trace of a compressible material in a stiff one
      // takes most of the cell's volume change, so the linear update is capped at +-50% per step
      // (the next equilibrium pressure resets the volumes; capped cells are counted).
      double dvv = dt * f * div;
      if (std::abs(dvv) > kMaxVolumeChange) {
        dvv = dvv > 0 ? kMaxVolumeChange : -kMaxVolumeChange;
        ++fallbacks_;
      }
      // The work of the volume change at the start pressure, p dV. A compressible fluid of small
      // mass beside a stiff one takes most of its cell's volume change (up to the cap), and there
      // p dV at the start pressure alone misses the rise of the fluid's pressure over the step
      // (second order in dvv): cold JWL products in water, compressed by half their volume in a
      // step, fell below their cold energy that way (the underwater scene stopped at 737 us,
      // docs/ice.md "The Lagrangian work of a small compressible phase"). Where that work would
      // take a fluid from above its cold energy to below it, it is taken at the mean of the start
      // pressure and the fluid's own end pressure p_r(1 / v_L, e_L) = a + b e_L (trapezoidal,
      // implicit in e_L; every EOS here is linear in e at fixed density), if that keeps it above.
      // Not for a cavitated liquid (kappa = inf: its work is at the cut-off) nor for solids.
      double de = -p * v * dvv;
      const double vL = v * (1.0 + dvv);
      if (P.cold && !P.external) {
        const double rho1 = 1.0 / vL, ec1 = P.eos->coldEnergy(rho1);
        ecL[r] = ec1;
        if (dvv != 0 && !std::isinf(ka[r]) && P.e[c] + de - ec1 <= 0 && P.e[c] - P.eos->coldEnergy(1.0 / v) > 0) {
          const double dv = vL - v, a = P.eos->pressure(rho1, 0.0), b = P.eos->pressure(rho1, 1.0) - a;
          const double den = 1.0 + 0.5 * dv * b;
          if (den > 0) {
            const double e1 = (P.e[c] - 0.5 * dv * (p + a)) / den;
            if (e1 - ec1 > 0) de = e1 - P.e[c];
          }
        }
      }
      P.eL[c] = P.e[c] + de;
      P.vL[c] = vL;
      if (P.external) {  // its energy change is its own solver's: the work the forces did on it
        dWork += P.work[oc];
        continue;
      }
      dKE += 0.5 * mass * (ke1 - ke0);
      dIE += mass * de;
    }
    if (kbar > 0) {
      const double D = dEflux - dKE - dIE - dWork;
      // Fluids alone: in proportion to theta_r kappa_r (their share of the volume change). With a
      // solid in the cell: in proportion to the heat capacities m_r cv_r (one temperature rise for
      // the cell, as the drag heat), since theta_r kappa_r / kbar puts ~kappa_f / kappa_s of it
      // on a trace of fluid whose mass is ~1e-10 of the cell's: +1e9 K within steps. The gas at a
      // solid's surface that the pressure jump accelerates is paid for by the cell and stopped by
      // the drag, whose heat is shared the same way: no net energy moves into or out of it.
      double C = 0;
      bool solid = false;
      for (int r = 0; r < n; ++r) {
        const Ptr& P = ptr[r];
        C += P.m[c] * P.cv;
        solid = solid || (P.external && P.m[c] > 0);
      }
      // How far a solid holds the cell's fluids in this step: the momentum exchange (K_rs > 0)
      // removes the fraction 1 / (1 + beta_r) of fluid r's velocity relative to the solids, beta_r =
      // dt sum_s K_rs theta_s v_r, and so 1 - 1 / (1 + beta_r)^2 of the relative motion's kinetic
      // energy, which it returns as drag heat. D takes that kinetic energy back, and the two go
      // together by heat capacity: the share phi (the largest over the cell's fluids; 1 at the
      // default K = 1e15). The kinetic energy the drag leaves the fluids (1 - phi: all of it with
      // K = 0) is theirs to pay, as in a cell of fluids alone (theta kappa); by heat capacity the
      // solid paid it (a closed box with K = H = 0: the steel gave the gas 6948 J of its heat in
      // 1000 steps, docs/coupling.md "Energy budget").
      double phi = 0;
      if (solid)
        for (int r = 0; r < n; ++r) {
          if (ptr[r].external || !(ptr[r].m[c] > 0)) continue;
          double beta = 0;
          for (int q = 0; q < n; ++q)
            if (ptr[q].external && ptr[q].m[c] > 0) beta += dt * Kp[r * n + q] * ptr[q].th[c] * ptr[r].v[c];
          const double keep = 1.0 / ((1.0 + beta) * (1.0 + beta));
          phi = std::max(phi, std::isfinite(beta) ? 1.0 - keep : 1.0);
        }
      // With the solids' own volume change given (their solvers' figure, dV_s): the cell's fluids
      // fill the rest of the cell's volume change, so the p dV work of the difference between dV_s
      // and the solids' share of the cell's (theta_s kappa_s / kbar of V dt div U, what the
      // fluids' update above assumed) is theirs: Dv = p (dV_s - share). Where a solid compresses
      // faster than its share (a PVC tube crushed by detonation products), the products that
      // push it pay, not the cell's heat capacities (water at 1374 kg/m^3 beside it went below
      // 0 K that way, docs/coupling.md "The solid's own volume change"). The fluids take Dv in
      // proportion to their share of the cell's volume change, times the volume fraction they
      // fill: a trace of fluid in a solid's cell fills nothing and takes nothing (the rest goes
      // with D by heat capacity).
      double Dv = 0, thf = 0, kf = 0;
      if (solid) {
        bool given = false;
        double dVs = 0, share = 0;
        for (int r = 0; r < n; ++r) {
          const Ptr& P = ptr[r];
          if (!P.external) {
            thf += P.th[c];
            kf += volumeShare(r);
          } else if (P.dVs) {
            given = true;
            dVs += P.dVs[oc];
            share += V * dt * volumeShare(r) * div;
          }
        }
        if (given && kf > 0) Dv = p * (dVs - share);
      }
      // What the heat capacities share. In a cell with a solid, where the momentum exchange follows,
      // it is given after the exchange together with the drag heat (exchange_phase.cpp): the two are
      // the kinetic energy the explicit acceleration gives the fluids, taken back here and returned
      // as drag heat there, and both are shared by heat capacity. Apart, each can exceed the cell's
      // energy: near-vacuum air (1e-7 kg/m^3) in a strengthless foam's cells beside water at 40 MPa
      // took 1e9 m/s in a step, D -2e6 J against a cell of 0.1 J of fluid energy; the fluids refused
      // their negative shares, took the drag heat, and the audit stopped the run (docs/slides.md
      // "Runs to 1 ms"). Together they are the cell's net p dV work less its kinetic energy change.
      double Dr = D - thf * Dv, Dh = 0;  // Dh: the part by heat capacity (phi, above)
      if (solid) {
        Dh = phi * Dr;
        Dr -= Dh;
        if (deferCorrection && phi > 0) {
          deferred_.push_back({c, oc, Dh, C});  // C > 0: the solid has mass here
          Dh = 0;
        }
      }
      ShareTaker takers[kMaxMaterials];
      double shares[kMaxMaterials];
      for (int r = 0; r < n; ++r) {
        const Ptr& P = ptr[r];
        double share = P.m[c] * P.cv / C * Dh + volumeShare(r) * Dr;  // [J]
        if (Dv != 0 && !P.external) share += thf * volumeShare(r) / kf * Dv;
        shares[r] = share;
        takers[r] = {P.m[c], P.cv, &P.eL[c], ecL[r], P.external, P.external ? &P.dEn[oc] : nullptr};
      }
      // A share one fluid could not take (a compressible trace, e.g. detonation products in water,
      // holds most of theta kappa and so most of a negative D) goes to the fluids that took theirs,
      // in proportion to their heat capacities; only what none of them can take is not conserved
      // (audited). Before, the whole share was audited: 1 % of the underwater scene's energy at
      // 2.5 mm cells (docs/slides.md).
      SharesGiven g = giveShares(n, takers, shares);
      fallbacks_ += g.refused;
      // What the fluids of a cell with a solid could not take (a trace's share beyond its thermal
      // energy) goes to the solids, by heat capacity.
      if (g.lost != 0 && solid) {
        double Cs = 0;
        for (int r = 0; r < n; ++r)
          if (ptr[r].external) Cs += ptr[r].m[c] * ptr[r].cv;
        if (Cs > 0) {
          for (int r = 0; r < n; ++r) {
            const Ptr& P = ptr[r];
            if (!P.external || !(P.m[c] > 0)) continue;
            const double s2 = P.m[c] * P.cv / Cs * g.lost;
            P.eL[c] += s2 / P.m[c];
            P.dEn[oc] += s2;
          }
          g.lost = 0;
        }
      }
      if (g.lost != 0) audit_.add(g.lost, c, g.worst);  // the share of D not taken (audited)
    }
    if (anyGravity_)
      for (int r = 0; r < n; ++r)
        for (int d = 0; d < dim; ++d) ptr[r].uL[d][c] += dt * gravity_[d];
  };
  // The owned cells in forEach's order, by rows (flat indices along each row).
  auto sweep = [&]<int NM>() {
    for (int k = owned_.lo[2]; k <= owned_.hi[2]; ++k)
      for (int j = owned_.lo[1]; j <= owned_.hi[1]; ++j) {
        const int i0 = owned_.lo[0];
        std::int64_t c = sb.index(i0, j, k), oc = owned_.index(i0, j, k), fls[3] = {0, 0, 0};
        for (int d = 0; d < dim; ++d) fls[d] = fbs[d].index(i0, j, k);
        for (int i = i0; i <= owned_.hi[0]; ++i, ++c, ++oc) {
          cell.template operator()<NM>(c, oc, fls);
          for (int d = 0; d < dim; ++d) ++fls[d];
        }
      }
  };
  if (nm == 2) sweep.template operator()<2>();
  else if (nm == 3) sweep.template operator()<3>();
  else sweep.template operator()<0>();

  if (anyViscous_ || anyConduction_) {
    // Flat indices by rows (every cell field shares the state's box): a neighbour along d is
    // c -+ stride[d]. Each cell writes only itself and reads the start values: any order does.
    const std::int64_t stride[3] = {1, sb.length(0), std::int64_t(sb.length(0)) * sb.length(1)};
    double dx2[3] = {1, 1, 1};
    for (int d = 0; d < dim; ++d) dx2[d] = mesh_.dx(d) * mesh_.dx(d);
    if (anyViscous_) viscousSecond_.assign(static_cast<std::size_t>(owned_.numPts()), 0.0);
    for (MaterialState& m : st_.mat) {
      if (m.external || (m.viscosity <= 0 && m.conductivity <= 0)) continue;
      const bool visc = m.viscosity > 0, cond = m.conductivity > 0;
      const double* th = m.theta.data();
      const double* sv = m.spvol.data();
      const double* es = cond ? m.eintStart.data() : nullptr;
      const auto us = visc ? core::components(std::as_const(m.velStart)) : std::array<const double*, 3>{};
      const auto u = core::components(m.vel);
      double* e = m.eint.data();
      const double* mass = m.mass.data();
      const Eos& eos = *m.eos;
      // The Newtonian stress is mu (grad u + grad u^T) - (2/3) mu (div u) I; mu lap(u), the part
      // above, is its flux mu d_d u_q through a face normal to d. The rest, tau' / mu at the face
      // between the cells lo and hi = lo + e_d:
      //   normal:     (1/3) d_d u_d - (2/3) sum_{q != d} d_q u_q
      //   tangential: d_q u_d (q != d)
      // (summed over the faces: (mu / 3) grad(div u)). d_d u_d is the compact difference across the
      // face; a tangential derivative is the mean of the two cells' central differences (one-sided
      // beside a cell without the material, 0 with neither), so each face has one flux and
      // momentum moves between its cells. The ghost layers, corners included, hold the boundary's
      // values (a wall or symmetry plane then does no work: the face's mean velocity is 0 normal
      // to it and d_q u_d flips sign in the mirror).
      // Each cell's differences d_q u_comp (q, comp < dim) once, over the owned cells and one layer
      // around them (the faces' two cells), in viscousGrad_: dim * dim arrays of the stored box.
      const std::int64_t nStored = sb.numPts();
      auto grad = [&](int q, int comp) { return viscousGrad_.data() + (q * dim + comp) * nStored; };
      if (visc && dim > 1) {
        viscousGrad_.resize(static_cast<std::size_t>(dim * dim * nStored));
        forEach(owned_.grow(1, dim), [&](int i, int j, int k) {
          const std::int64_t x = sb.index(i, j, k);
          for (int q = 0; q < dim; ++q) {
            const std::int64_t p = x + stride[q], l = x - stride[q];
            const bool hp = th[p] > 0, hl = th[l] > 0;
            const double h = mesh_.dx(q);
            for (int comp = 0; comp < dim; ++comp)
              grad(q, comp)[x] = hp && hl ? (us[comp][p] - us[comp][l]) / (2 * h)
                                 : hp     ? (us[comp][p] - us[comp][x]) / h
                                 : hl     ? (us[comp][x] - us[comp][l]) / h
                                          : 0.0;
          }
        });
      }
      auto tangential = [&](std::int64_t x, int q, int comp) { return grad(q, comp)[x]; };
      // Adds a tau' / mu to du and returns tau' / mu . (u_lo + u_hi) (the work at the face's mean
      // velocity, doubled). Component by component, into its own sum (added to the Laplacian's after
      // the faces): a small array written element by element and read back two at a time (the
      // Laplacian's vectorized loop) stalls the store forwarding.
      auto faceStress = [&](std::int64_t lo, std::int64_t hi, int d, double a, double* du) {
        double div = 0, gu = 0;  // the tangential part of div u at the face; the work
        for (int q = 0; q < dim; ++q) {
          if (q == d) continue;
          div += 0.5 * (tangential(lo, q, q) + tangential(hi, q, q));
          const double g = 0.5 * (tangential(lo, q, d) + tangential(hi, q, d));
          du[q] += a * g;
          gu += g * (us[q][lo] + us[q][hi]);
        }
        const double g = (us[d][hi] - us[d][lo]) / (3 * mesh_.dx(d)) - 2.0 / 3.0 * div;
        du[d] += a * g;
        return gu + g * (us[d][lo] + us[d][hi]);
      };
      for (int k = owned_.lo[2]; k <= owned_.hi[2]; ++k)
        for (int j = owned_.lo[1]; j <= owned_.hi[1]; ++j) {
          std::int64_t c = sb.index(owned_.lo[0], j, k);
          for (int i = owned_.lo[0]; i <= owned_.hi[0]; ++i, ++c) {
            const double tc = th[c];
            if (!(tc > 0)) continue;
            const double v = sv[c];
            const double Tc = cond ? eos.temperature(1.0 / v, es[c]) : 0.0;
            double du[3] = {0, 0, 0}, dT = 0, dk = 0;
            double dS[3] = {0, 0, 0};  // the stress's rest (faceStress), added to du after the faces
            double kc = 0;  // |u_start|^2 / 2 here
            if (visc)
              for (int q = 0; q < dim; ++q) kc += 0.5 * us[q][c] * us[q][c];
            for (int d = 0; d < dim; ++d)
              for (int sgn = -1; sgn <= 1; sgn += 2) {
                const std::int64_t n = c + sgn * stride[d];
                // The face's share of the material is the smaller of its cells' (not their mean): a
                // trace beside a full cell then diffuses at most as a full cell does, so the explicit
                // viscous bound (ice_solver.cpp, stableTimeStep) holds in every cell (with the mean, a
                // trace of theta got nu / (2 theta): a viscous filler's trace inside a solid's cells
                // blew up at step 6).
                const double w = std::min(tc, th[n]) / tc;
                const double tb = w / dx2[d];
                if (visc && w > 0) {
                  double kn = 0;
                  for (int q = 0; q < dim; ++q) {
                    du[q] += tb * (us[q][n] - us[q][c]);
                    kn += 0.5 * us[q][n] * us[q][n];
                  }
                  dk += tb * (kn - kc);
                  // The rest of the Newtonian stress (Stokes' hypothesis, no bulk viscosity): the
                  // face's extra flux tau' / mu (faceStress below), outward from the lower cell; its
                  // work at the face's mean velocity, as above.
                  const double a = sgn * w / mesh_.dx(d);
                  dk += 0.5 * a * (sgn > 0 ? faceStress(c, n, d, a, dS) : faceStress(n, c, d, a, dS));
                }
                if (cond) dT += tb * (eos.temperature(1.0 / sv[n], es[n]) - Tc);
              }
            for (int q = 0; q < dim; ++q) du[q] += dS[q];
            if (visc) {
              // Viscous heating. The face force F = m dt nu tb (u_n - u_c) (start velocities; m v tb
              // is the same seen from both cells, so momentum moves between them), and the rest of
              // the stress's, F' = +-m dt nu (w / dx_d) tau' / mu, do the work (F + F') . (u_c + u_n) / 2
              // on the face's fluid: a total-energy flux that cancels between the two cells (a no-slip
              // wall's ghost, -u, does no work). What the cell's kinetic energy does not take of it,
              // exactly (its change u . du + du . du / 2 from its Lagrangian velocity u), is heat, in
              // two parts: the fluid takes the first-order part, half of its faces' (F + F') . (u_n -
              // u_c) / m (u = u_start; the Laplacian's is dt nu sum_faces tb |u_n - u_c|^2 / 2, the
              // rest's sums with it over the mesh to the stress's dissipation tau : grad u >= 0),
              // its dissipation; the second-order part -du . du / 2 goes to the cell's materials by
              // heat capacity below. Where the exchange holds the fluid to the cell's others and the
              // step is the mixture's (ice_solver.cpp, stableTimeStep), du overshoots the mixture's
              // change and that part is the kinetic energy the drag returns as heat, shared the same
              // way; on the fluid alone it cooled a held viscous gas by ~10 times its dissipation.
              const double f = dt_ * m.viscosity * v;
              double work = f * dk, second = 0;
              for (int q = 0; q < dim; ++q) {
                const double dq = f * du[q];
                work -= u[q][c] * dq;
                second += 0.5 * dq * dq;
                u[q][c] += dq;
              }
              e[c] += work;
              viscousSecond_[static_cast<std::size_t>(owned_.index(i, j, k))] -= mass[c] * second;
              viscousHeat_ += mass[c] * (work - second);
            }
            e[c] += dt_ * m.conductivity * v * dT;
          }
        }
    }
    if (anyViscous_) {
      // The viscous updates' second-order part [J], by heat capacity: in a cell with a solid whose
      // correction waits for the drag heat (the sweep's deferred_, in the owned cells' order), with
      // it; elsewhere now, drain-guarded as the correction's shares.
      std::size_t next = 0;
      ShareTaker takers[kMaxMaterials];
      double shares[kMaxMaterials];
      for (int k = owned_.lo[2]; k <= owned_.hi[2]; ++k)
        for (int j = owned_.lo[1]; j <= owned_.hi[1]; ++j)
          for (int i = owned_.lo[0]; i <= owned_.hi[0]; ++i) {
            const std::int64_t oc = owned_.index(i, j, k), c = sb.index(i, j, k);
            const double h = viscousSecond_[static_cast<std::size_t>(oc)];
            if (h == 0) continue;
            while (next < deferred_.size() && deferred_[next].c < c) ++next;
            if (next < deferred_.size() && deferred_[next].c == c) {
              deferred_[next].D += h;
              continue;
            }
            double C = 0;
            for (int r = 0; r < nm; ++r) C += ptr[r].m[c] * ptr[r].cv;
            for (int r = 0; r < nm; ++r) {
              const Ptr& P = ptr[r];
              const bool cold = P.cold && !P.external && P.m[c] > 0;
              shares[r] = P.m[c] * P.cv / C * h;
              takers[r] = {P.m[c], P.cv, &P.eL[c], cold ? P.eos->coldEnergy(1.0 / P.vL[c]) : 0.0, P.external,
                           P.external ? &P.dEn[oc] : nullptr};
            }
            const SharesGiven g = giveShares(nm, takers, shares);
            fallbacks_ += g.refused;
            if (g.lost != 0) audit_.add(g.lost, c, g.worst);
          }
    }
  }

  for (const Source& s : sources_) {
    const double a = std::max(t_, s.start), b = std::min(t_ + dt, s.end);
    if (!(b > a)) continue;
    MaterialState& m = st_.mat[s.material];
    const double* mass = m.mass.data();
    const double* theta = m.theta.data();
    double* e = m.lagEint().data();
    // power_density is per unit volume of the material: a cell the material shares (with a
    // solid's surface, say) receives power * theta * V (times its share inside the shape), so a
    // cell wholly inside heats at the rate of a full one.
    // A cell the shape's edge cuts takes its share of the volume inside (Source::share).
    for (std::size_t q = 0; q < s.cells.size(); ++q) {
      const std::int64_t c = s.cells[q];
      if (mass[c] > 0) e[c] += s.power * s.share[q] * theta[c] * V * (b - a) / mass[c];
    }
  }
}

}  // namespace mpmice::ice
