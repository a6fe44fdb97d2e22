// IceSolver phases 3 and 6: face velocities with the pointwise implicit exchange at faces (with the
// Riemann face pressure, at faces in compression the response to the pressure jump is at least the
// two-shock solution's 1 / (W_L + W_R); beside a cell where the exchange holds a fluid to a solid
// that dictates its velocity, at least the fluid's acoustic 1 / (Z_L + Z_R) times that share:
// heldShare), and the face pressure p_f = (p_L / rho_L + p_R / rho_R) / (1 / rho_L + 1 / rho_R)
// (rho: mixture density),
// minus the two-shock Riemann dissipation W_L W_R / (W_L + W_R) (u_R - u_L) at faces in compression
// (ice.face_pressure: riemann, the default for fluids alone),
// plus the shock viscosity q = rho (q1 c |du| + q2 du^2) at faces in compression when asked
// (ice.shock_viscosity). p_f enters the momentum and the energy flux form, so q's work is
// returned as heat by the energy correction (fluids without external materials).
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "ice/exchange/face_exchange.h"
#include "ice/face/solid_faces.h"
#include "ice/ice_constants.h"
#include "ice/solver/ice_solver.h"
#include "ice/state/fixed_counts.h"
#include "ice/state/phase_units.h"

namespace mpmice::ice {

using core::forEach;

namespace {
// q at the face between cell l and cell (i, j, k) in direction d; rL, rR: the cells' masses.
double shockViscosity(const IceState& st, const int* l, int i, int j, int k, int d, double rL, double rR, double q1,
                      double q2) {
  double muL = 0, muR = 0, dL = 0, dR = 0, kL = 0, kR = 0;
  for (const MaterialState& m : st.mat) {
    muL += m.mass(l[0], l[1], l[2]) * m.vel(l[0], l[1], l[2], d);
    muR += m.mass(i, j, k) * m.vel(i, j, k, d);
    const double tL = m.theta(l[0], l[1], l[2]), tR = m.theta(i, j, k);
    if (tL > 0) dL += tL / m.spvol(l[0], l[1], l[2]), kL += tL * m.kappa(l[0], l[1], l[2]);
    if (tR > 0) dR += tR / m.spvol(i, j, k), kR += tR * m.kappa(i, j, k);
  }
  const double du = muR / rR - muL / rL;
  if (!(du < 0) || !(dL > 0 && dR > 0 && kL > 0 && kR > 0)) return 0.0;
  const double c = std::min(1.0 / std::sqrt(dL * kL), 1.0 / std::sqrt(dR * kR));
  const double rho = 2.0 * dL * dR / (dL + dR);
  return rho * (q1 * c * -du + q2 * du * du);
}
// The low-Mach scale of the Riemann terms at the face between cells l and r of x
// (ice.face_pressure: riemann_low_mach): min(1, max(M, s / kRiemannFullStrain)), M the larger of
// the two cells' speeds over the smaller sound speed (c = Z / rho), s the face's acoustic strain
// |p_R - p_L| / (rho c^2) (the smaller rho c^2 of the two). The dissipation W_L W_R / (W_L + W_R) du
// is a velocity-jump term in the pressure, O(1 / M) too large against the pressure variations of a
// low-Mach flow (the upwind schemes' low-Mach problem, Guillard & Viozat 1999; M is Rieper's LM-Roe
// scaling, 2011), and it damps small acoustic waves (the added-mass column's ringing) as if they
// were shocks. M alone let the noise behind a shock that reflects into gas at rest ring (the shock
// slab's reflected plateau, where M ~ 0): the strain term keeps the full dissipation wherever
// neighbouring cells differ by a nonlinear jump.
double lowMachScale(const CellMixes& x, std::size_t l, std::size_t r) {
  double ul = 0, ur = 0;
  for (const std::vector<double>& u : x.u)
    if (!u.empty()) ul += u[l] * u[l], ur += u[r] * u[r];
  const double cl = x.z[l] / x.rho[l], cr = x.z[r] / x.rho[r];
  const double mach = std::sqrt(std::max(ul, ur)) / std::min(cl, cr);
  const double strain = std::abs(x.p[r] - x.p[l]) / std::min(x.z[l] * cl, x.z[r] * cr);
  const double m = std::max(mach, strain / kRiemannFullStrain);
  return m < 1.0 ? m : 1.0;
}
// The two-shock approximate Riemann solution's dissipative part (Dukowicz 1985) at a face in
// compression (du = u_R - u_L < 0): p* = p_avg - W_L W_R / (W_L + W_R) du with the shock
// impedances W = rho (c + Gamma |du|), Gamma = (gamma + 1) / 2 of an ideal gas of gamma 1.4
// (kShockImpedanceSlope). Zero at faces in expansion and where the velocity is uniform.
// L, R: the two cells' indices in x.box.
double riemannDissipation(const CellMixes& x, std::int64_t L, std::int64_t R, int d) {
  const std::vector<double>& u = x.u[static_cast<std::size_t>(d)];
  const auto l = static_cast<std::size_t>(L), r = static_cast<std::size_t>(R);
  const double du = u[r] - u[l];
  return -riemannImpedance(x.z[l], x.rho[l], x.z[r], x.rho[r], du, x.lowMach ? lowMachScale(x, l, r) : 1.0) * du;
}
// The same two-shock solution's face velocity, u* = (W_L u_L + W_R u_R - (p_R - p_L)) / (W_L + W_R),
// responds to the pressure jump with 1 / (W_L + W_R) [m^2 s / kg], whatever the time step. At a
// face in compression (du < 0) this is returned; 0 in expansion or without impedance.
double riemannVelocityResponse(const CellMixes& x, std::int64_t L, std::int64_t R, int d) {
  const std::vector<double>& u = x.u[static_cast<std::size_t>(d)];
  const auto l = static_cast<std::size_t>(L), r = static_cast<std::size_t>(R);
  const double du = u[r] - u[l];
  if (!(du < 0) || !(x.z[l] > 0 && x.z[r] > 0)) return 0.0;
  const double wL = x.z[l] - kShockImpedanceSlope * x.rho[l] * du, wR = x.z[r] - kShockImpedanceSlope * x.rho[r] * du;
  return (x.lowMach ? lowMachScale(x, l, r) : 1.0) / (wL + wR);
}

// riemannImpedance at four faces (the lanes, lanes.h): the same operations, 0 where it returns 0.
lanes::v4d riemannImpedanceLanes(lanes::v4d zL, lanes::v4d rhoL, lanes::v4d zR, lanes::v4d rhoR, lanes::v4d du) {
  const lanes::v4m on = (du < 0) & (zL > 0) & (zR > 0);
  const lanes::v4d wL = zL - kShockImpedanceSlope * rhoL * du, wR = zR - kShockImpedanceSlope * rhoR * du;
  return lanes::sel(on, wL * wR / (wL + wR), lanes::splat(0.0));
}

// The acoustic impedance rho c = 1 / sqrt(v kappa) of material m in stored cell c; 0 where it is
// absent (theta at most kPresentFraction) or has no finite compressibility (a held trace, kappa 0;
// a cavitated liquid, kappa inf).
double impedance(const MaterialState& m, std::int64_t c) {
  const double t = m.theta.data()[c], v = m.spvol.data()[c], ka = m.kappa.data()[c];
  return t > kPresentFraction && v > 0 && ka > 0 && std::isfinite(ka) ? 1.0 / std::sqrt(v * ka) : 0.0;
}

// The share of fluid r's velocity in stored cell c that the solids (external materials) dictate
// and the pressure does not: h = a w.
//   a = beta / (1 + beta): the part of the fluid's velocity the cell's implicit momentum exchange
//       resets to the solids' in a step (the two-material solve of (theta_r / v_r) x_r + dt K
//       theta_r theta_s (x_r - x_s) = (theta_r / v_r) x_r^L divides the velocity difference by
//       1 + beta, beta = dt sum_s K_rs (theta_s v_r + theta_r v_s)); 1 for K = 1e15 wherever a
//       solid is present, 0 where none is.
//   w = Z_s / (Z_s + Z_r): the solids' weight in the velocity of a fluid-solid interface (the
//       acoustic interaction of the two, Z = rho c, Z_s the solids' volume-weighted mean): ~1 for
//       a gas against a metal (a wall to the gas: the velocity is the solid's, whatever the gas's
//       pressure), ~0.03 for water against a soft rubber (the rubber moves with the water's
//       pressure, and the held velocity carries its impulses).
double heldShare(const std::vector<MaterialState>& mat, const double* K, int r, std::int64_t c, double dt) {
  const MaterialState& f = mat[static_cast<std::size_t>(r)];
  const double tr = f.theta.data()[c], vr = f.spvol.data()[c];
  const int nm = static_cast<int>(mat.size());
  double beta = 0, thetaS = 0, zS = 0;
  for (int s = 0; s < nm; ++s) {
    const MaterialState& m = mat[static_cast<std::size_t>(s)];
    if (!m.external || !(m.mass.data()[c] > 0)) continue;
    const double ts = m.theta.data()[c];
    beta += dt * K[r * nm + s] * (ts * vr + tr * m.spvol.data()[c]);
    thetaS += ts;
    zS += ts * impedance(m, c);
  }
  if (!(beta > 0) || !(thetaS > 0)) return 0.0;
  const double a = std::isfinite(beta) ? beta / (1.0 + beta) : 1.0;
  zS /= thetaS;
  const double zr = impedance(f, c);
  const double w = zS + zr > 0 ? zS / (zS + zr) : 1.0;
  return a * w;
}
}  // namespace

void computeCellMixes(const IceState& st, const core::Box& owned, int dim, CellMixes& x) {
  computeCellMixesOver(st, owned.grow(1, dim), dim, x);
}

void computeCellMixesOver(const IceState& st, const core::Box& box, int dim, CellMixes& x) {
  x.box = box;
  const auto n = static_cast<std::size_t>(box.numPts());
  x.rho.resize(n);
  x.z.resize(n);
  if (x.lowMach) x.p.resize(n);  // the pressures only for lowMachScale's strain
  for (int d = 0; d < dim; ++d) x.u[static_cast<std::size_t>(d)].resize(n);
  const core::Box& sb = st.press.box();
  const int nm = static_cast<int>(st.mat.size());
  // Per material: mass, velocity, volume fraction, specific volume, compressibility, external.
  struct Ptr {
    const double *m, *u[3], *th, *sv, *ka;
    bool external;
  };
  std::vector<Ptr> ptrs(st.mat.size());
  for (int r = 0; r < nm; ++r) {
    const MaterialState& m = st.mat[static_cast<std::size_t>(r)];
    ptrs[static_cast<std::size_t>(r)] = {m.mass.data(), {nullptr, nullptr, nullptr}, m.theta.data(), m.spvol.data(),
                                         m.kappa.data(), m.external};
    for (int d = 0; d < dim; ++d) ptrs[static_cast<std::size_t>(r)].u[d] = m.vel.data(d);
  }
  const Ptr* const ptr = ptrs.data();
  double* const xu[3] = {x.u[0].data(), x.u[1].data(), x.u[2].data()};
  const double* const pressure = x.pressure ? x.pressure : st.press.data();
  // Stored cell c, o its index in box. NM, DIM > 0: the number of materials and the dimension
  // fixed at compile time (the small loops unroll; the same operations in the same order).
  auto cell = [&]<int NM, int DIM>(std::int64_t c, std::size_t o) {
    const int nmt = NM > 0 ? NM : nm;
    const int nd = DIM > 0 ? DIM : dim;
    double mass = 0, mu[3] = {0, 0, 0}, dn = 0, kap = 0;
    bool solid = false;
    for (int r = 0; r < nmt; ++r) {
      const Ptr& m = ptr[r];
      const double mm = m.m[c];
      mass += mm;
      solid = solid || (m.external && mm > 0);
      for (int d = 0; d < nd; ++d) mu[d] += mm * m.u[d][c];
      const double t = m.th[c];
      if (t > 0) dn += t / m.sv[c], kap += t * m.ka[c];
    }
    x.rho[o] = dn;
    if (x.lowMach) x.p[o] = pressure[c];
    x.z[o] = dn > 0 && kap > 0 && !solid ? std::sqrt(dn / kap) : 0.0;
    for (int d = 0; d < nd; ++d) xu[d][o] = mass > 0 ? mu[d] / mass : 0.0;
  };
  // cell() at the four cells c .. c + 3 (the lanes, lanes.h): the same operations, selects for
  // its branches.
  auto cellLanes = [&]<int NM, int DIM>(std::int64_t c, std::size_t o) __attribute__((always_inline)) {
    using lanes::v4d, lanes::v4m, lanes::load, lanes::sel, lanes::splat;
    const v4d zero = splat(0.0);
    v4d mass = zero, mu[DIM], dn = zero, kap = zero;
    for (int d = 0; d < DIM; ++d) mu[d] = zero;
    v4m solid = v4m{0, 0, 0, 0};
    for (int r = 0; r < NM; ++r) {
      const Ptr& m = ptr[r];
      const v4d mm = load(m.m + c);
      mass += mm;
      if (m.external) solid = solid | (mm > 0);
      for (int d = 0; d < DIM; ++d) mu[d] += mm * load(m.u[d] + c);
      const v4d t = load(m.th + c);
      const v4m on = t > 0;
      dn = sel(on, dn + t / load(m.sv + c), dn);
      kap = sel(on, kap + t * load(m.ka + c), kap);
    }
    lanes::store(x.rho.data() + o, dn);
    if (x.lowMach) lanes::store(x.p.data() + o, load(pressure + c));
    lanes::store(x.z.data() + o, sel((dn > 0) & (kap > 0) & ~solid, lanes::sqrt(dn / kap), zero));
    for (int d = 0; d < DIM; ++d) lanes::store(xu[d] + o, sel(mass > 0, mu[d] / mass, zero));
  };
  // The cells in forEach's order, by rows (flat indices along each row; o counts the box's cells).
  auto sweep = [&]<int NM, int DIM>() { sweepRowsByLanes<NM, DIM, std::size_t>(box, sb, cellLanes, cell); };
  withFixedCounts<true>(nm, dim, sweep);
}

void IceSolver::computeFaceVelocities() {
  const int dim = mesh_.dim();
  const int nm = numMaterials();
  const double dt = dt_;
  const bool exch = anyK_ && nm > 1;
  const bool exchSolids = exch && anyExternal_;  // fluids held by a solid's exchange (heldShare)
  const core::Box& sb = st_.press.box();
  const std::int64_t strides[3] = {1, sb.length(0), std::int64_t(sb.length(0)) * sb.length(1)};
  const double* p = st_.press.data();
  // With the Riemann face pressure (fluids alone, the default) the face velocity's response to the
  // pressure jump is at least the two-shock Riemann solution's at faces in compression (docs/ice.md
  // "Shocks": ICE's dt v_r grad p alone vanishes with the local acoustic CFL number, and a slow
  // shock then rings: test 5 +8.4 % at 400 cells, +12.6 % at CFL 0.2).
  const bool riemannOn = riemannFacePressureOn();
  CellMixes& mix = mixes_;  // made a block of slabs at a time (forMixBlocks, below)
  mix.lowMach = riemannOn && riemannLowMach_;
  const std::array<std::int64_t, 3> mixStride = cellMixStrides(owned_, dim);
  const std::int64_t mixStrides[3] = {mixStride[0], mixStride[1], mixStride[2]};
  // Each cell's held share (heldShare) per fluid, once: the faces on both sides read it.
  HeldShares& H = held_;
  if (exchSolids) {
    H.box = owned_.grow(1, dim);
    const auto n = static_cast<std::size_t>(H.box.numPts());
    H.share.resize(static_cast<std::size_t>(nm));
    for (int r = 0; r < nm; ++r) {
      if (st_.mat[r].external) continue;
      std::vector<double>& hs = H.share[static_cast<std::size_t>(r)];
      hs.resize(n);
      forEach(H.box, [&](int i, int j, int k) {
        hs[static_cast<std::size_t>(H.box.index(i, j, k))] = heldShare(st_.mat, K_.data(), r, sb.index(i, j, k), dt);
      });
    }
  }
  const std::int64_t heldStrides[3] = {1, H.box.length(0), std::int64_t(H.box.length(0)) * H.box.length(1)};
  // The semi-implicit face mobilities, computed here with the face velocities (same exchange).
  std::vector<std::array<core::Field, 3>>* mobility = nullptr;
  if (semiImplicit_) {
    allocateSemiImplicitScratch();
    mobility = &semi_.mobility;
  }
  semi_.mobilityFresh = semiImplicit_;
  const int top = dim - 1;
  // The faces normal to d with index tlo .. thi in top (each face on its own: the order of the
  // blocks and directions changes no value).
  auto direction = [&](int d, int tlo, int thi) {
    const double dx = mesh_.dx(d);
    const double g = gravity_[d];
    const std::int64_t sd = strides[d];
    const core::Box fb = owned_.faces(d);
    const bool inLo = bc_.touches(2 * d) && bc_.type(2 * d) == core::BoundaryType::Inflow;
    const bool inHi = bc_.touches(2 * d + 1) && bc_.type(2 * d + 1) == core::BoundaryType::Inflow;
    // Per material: mass, velocity (component d), face velocity, volume fraction, specific volume.
    struct Ptr {
      const double *m, *u;
      double* uf;
      const double *th, *sv;
      bool external;
    };
    Ptr ptr[kMaxMaterials];
    for (int r = 0; r < nm; ++r) {
      MaterialState& m = st_.mat[r];
      ptr[r] = {m.mass.data(), m.vel.data(d), m.velFace[d].data(), m.theta.data(), m.spvol.data(), m.external};
    }
    const std::int64_t sdx = mixStrides[d];
    const std::int64_t hsd = heldStrides[d];
    // The face (i, j, k): stored cell cR = cL + sd on its high side, face index fi, cR's index R in
    // the cell mixtures' box and hR in the held shares'. NM > 0: the number of materials fixed at
    // compile time (the small loops unroll; the same operations in the same order).
    auto face = [&]<int NM>(int i, int j, int k, std::int64_t cR, std::int64_t fi, std::int64_t R, std::int64_t hR)
                    __attribute__((always_inline)) {  // inlined into the row loop (a call per face)
      const int n = NM > 0 ? NM : nm;
      const std::int64_t cL = cR - sd;
      const double dpdx = (p[cR] - p[cL]) / dx;
      double x[2 * kMaxMaterials], th[kMaxMaterials], vf[kMaxMaterials];
      for (int r = 0; r < n; ++r) {  // faceMaterialValues
        const Ptr& P = ptr[r];
        th[r] = 0.5 * (P.th[cL] + P.th[cR]);
        vf[r] = faceSpecificVolume(P.m[cL], P.sv[cL], P.m[cR], P.sv[cR]);
      }
      openSolidFaceExchange(st_, d, fi, th);
      // Whether the face exchange leaves the fluids free of the solids here (no solid at the face,
      // or an open face of the solids' face transport, solid_faces.h): their face velocities are
      // then their own. Where it holds them (a face inside a solid; every face a solid's cells
      // touch with solid_transport ice) the face velocity is the solid's, and the acoustic response
      // below would only let the fluid leak through the exchange's weights: the shock slab's
      // reflected plateau fell 0.25 % (its surface cells' gas is far below the plateau's
      // pressure, held there by that lock).
      bool freeOfSolids = exchSolids;
      for (int r = 0; r < n && freeOfSolids; ++r)
        if (ptr[r].external && th[r] > 0) freeOfSolids = false;
      // The two-shock Riemann solution's response of the face velocity to the pressure jump,
      // 1 / (W_L + W_R) (times dx: per unit gradient), at faces in compression (0 elsewhere).
      double riemann = 0;
      if (riemannOn) riemann = dx * riemannVelocityResponse(mix, R - sdx, R, d);
      for (int r = 0; r < n; ++r) {
        const Ptr& P = ptr[r];
        const double mL = P.m[cL], mR = P.m[cR];
        const double msum = mL + mR;
        const double t1 = msum > 0 ? (mL * P.u[cL] + mR * P.u[cR]) / msum : 0.5 * (P.u[cL] + P.u[cR]);
        // Beside a cell where the exchange holds this fluid to a solid that the fluid cannot move
        // (a gas against a metal), its cell velocity is the solid's after every step: it carries
        // none of the pressure gradient's past impulses, so dt v_r grad p is the only
        // pressure-velocity coupling the face has, and it vanishes with dt. A velocity bias of
        // the held cell (the gas in the piston's smeared surface cell moves with the copper) was
        // then balanced by a pressure deficit ~ 1 / dt: the surface cells lost gas to the pure
        // gas at every step, 0.75 / 1.81 / 2.30 % at the piston's CFL 0.4 / 0.1 / 0.05
        // (docs/verification-coupled.md, "The error grew as the step shrank"). The response
        // without memory is the acoustic (linearised Riemann) one, 1 / (Z_L + Z_R) with the
        // fluid's own impedances, whatever dt; weighted by the held share h (heldShare, the larger
        // of the two cells'), and never below dt v_r. Only at faces free of the solids (above).
        // Its gain in the explicit pressure increment, (open face / theta_r) max(C^2, C / 2) with
        // C the fluid's acoustic Courant number, is at most what dt v_r gives at C = 1 / 2.
        double held = 0;
        if (freeOfSolids && !P.external) {
          const double* hs = H.share[static_cast<std::size_t>(r)].data();
          const std::int64_t hL = hR - hsd;
          const double h = std::max(hs[hL], hs[hR]);
          if (h > 0) {
            const double zL = impedance(st_.mat[r], cL), zR = impedance(st_.mat[r], cR);
            if (zL > 0 && zR > 0) held = h * dx / (zL + zR);
          }
        }
        x[r] = t1 - std::max({dt * vf[r], riemann, held}) * dpdx + dt * g;
      }
      // The semi-implicit face mobilities (assembleSemiImplicit) solve the same exchange with the
      // face specific volumes as right-hand side: one factorisation for both.
      if (mobility) {
        double* phi = x + n;
        for (int r = 0; r < n; ++r) phi[r] = vf[r];
        if (exch) faceExchangeFixed<NM>(n, dt, K_.data(), th, vf, x, 2);
        for (int r = 0; r < n; ++r) (*mobility)[static_cast<std::size_t>(r)][d].data()[fi] = phi[r];
      } else if (exch) {
        faceExchangeFixed<NM>(n, dt, K_.data(), th, vf, x, 1);
      }
      const int idx[3] = {i, j, k};
      const bool atLo = inLo && idx[d] == owned_.lo[d], atHi = inHi && idx[d] == owned_.hi[d] + 1;
      for (int r = 0; r < n; ++r) {
        double u = x[r];
        if (atLo) u = bc_.inflow(2 * d).velocity[d];
        if (atHi) u = bc_.inflow(2 * d + 1).velocity[d];
        ptr[r].uf[fi] = u;
      }
    };
    // Four faces of a row at once (the lanes, lanes.h), where the face needs no more than the
    // fluids' own values: no fluid held by a solid's exchange (exchSolids), no solids' face
    // transport, no mobilities, no inflow side in d. The same operations in the same order as
    // face() there; its divisions four at a time.
    const bool lanesOk = !exchSolids && !mobility && !st_.solidFaces.on && !inLo && !inHi && !mix.lowMach;
    auto faceLanes = [&]<int NM>(std::int64_t cR, std::int64_t fi, std::int64_t R) __attribute__((always_inline)) {
      using lanes::v4d, lanes::v4m, lanes::load, lanes::sel;
      const std::int64_t cL = cR - sd;
      const v4d dpdx = (load(p + cR) - load(p + cL)) / dx;
      v4d x[NM], th[NM], vf[NM];
      for (int r = 0; r < NM; ++r) {  // faceMaterialValues (faceSpecificVolume)
        const Ptr& P = ptr[r];
        th[r] = 0.5 * (load(P.th + cL) + load(P.th + cR));
        const v4d mL = load(P.m + cL), mR = load(P.m + cR), vL = load(P.sv + cL), vR = load(P.sv + cR);
        const v4m on = mL + mR > 0;
        vf[r] = sel(on, mL * vL + mR * vR, 2.0 * vL * vR) / sel(on, mL + mR, vL + vR);
      }
      v4d riemann = lanes::splat(0.0);
      if (riemannOn) {  // dx * riemannVelocityResponse
        const double *u = mix.u[static_cast<std::size_t>(d)].data(), *z = mix.z.data(), *rho = mix.rho.data();
        const std::int64_t L = R - sdx;
        const v4d du = load(u + R) - load(u + L), zL = load(z + L), zR = load(z + R);
        const v4m on = (du < 0) & (zL > 0) & (zR > 0);
        const v4d wL = zL - kShockImpedanceSlope * load(rho + L) * du, wR = zR - kShockImpedanceSlope * load(rho + R) * du;
        riemann = dx * sel(on, 1.0 / (wL + wR), lanes::splat(0.0));
      }
      for (int r = 0; r < NM; ++r) {
        const Ptr& P = ptr[r];
        const v4d mL = load(P.m + cL), mR = load(P.m + cR), uL = load(P.u + cL), uR = load(P.u + cR);
        const v4d msum = mL + mR;
        const v4m on = msum > 0;
        const v4d t1 = sel(on, mL * uL + mR * uR, 0.5 * (uL + uR)) / sel(on, msum, lanes::splat(1.0));
        v4d mx = dt * vf[r];  // std::max({dt vf, riemann, held = 0})
        mx = sel(mx < riemann, riemann, mx);
        mx = sel(mx < 0.0, lanes::splat(0.0), mx);
        x[r] = t1 - mx * dpdx + dt * g;
      }
      if (exch) faceExchangeLanes<NM>(dt, K_.data(), th, vf, x);
      for (int r = 0; r < NM; ++r) lanes::store(ptr[r].uf + fi, x[r]);
    };
    // The faces in forEach's order, by rows (flat indices along each row).
    core::Box rows = fb;
    rows.lo[top] = std::max(fb.lo[top], tlo);
    rows.hi[top] = std::min(fb.hi[top], thi);
    auto sweep = [&]<int NM>() {
      for (int k = rows.lo[2]; k <= rows.hi[2]; ++k)
        for (int j = rows.lo[1]; j <= rows.hi[1]; ++j) {
          const int i0 = rows.lo[0];
          std::int64_t cR = sb.index(i0, j, k), fi = fb.index(i0, j, k);
          std::int64_t R = riemannOn ? mix.box.index(i0, j, k) : 0, hR = exchSolids ? H.box.index(i0, j, k) : 0;
          int i = i0;
          if constexpr (NM > 0)
            if (lanesOk)
              for (; i + 3 <= rows.hi[0]; i += 4, cR += 4, fi += 4, R += 4, hR += 4)
                faceLanes.template operator()<NM>(cR, fi, R);
          for (; i <= rows.hi[0]; ++i, ++cR, ++fi, ++R, ++hR) face.template operator()<NM>(i, j, k, cR, fi, R, hR);
        }
    };
    if (nm == 1) sweep.template operator()<1>();
    else if (nm == 2) sweep.template operator()<2>();
    else if (nm == 3) sweep.template operator()<3>();
    else sweep.template operator()<0>();
  };
  if (riemannOn)
    forMixBlocks(st_, owned_, dim, mix, owned_.lo[top], owned_.hi[top] + 1, [&](int lo, int hi) {
      for (int d = 0; d < dim; ++d) direction(d, lo, hi);
    });
  else
    for (int d = 0; d < dim; ++d) direction(d, owned_.lo[top], owned_.hi[top] + 1);
}

double riemannImpedance(double zL, double rhoL, double zR, double rhoR, double du, double scale) {
  if (!(du < 0) || !(zL > 0 && zR > 0)) return 0.0;
  const double wL = zL - kShockImpedanceSlope * rhoL * du, wR = zR - kShockImpedanceSlope * rhoR * du;
  return scale * wL * wR / (wL + wR);
}

double riemannDissipationRate(const IceState& st, const core::Mesh& mesh, const core::Box& owned,
                              std::int64_t* cell, CellMixes* mixes) {
  const int dim = mesh.dim();
  const core::Box& sb = st.press.box();
  CellMixes own;
  CellMixes& x = mixes ? *mixes : own;
  const std::array<std::int64_t, 3> stride = cellMixStrides(owned, dim);
  const std::int64_t strides[3] = {stride[0], stride[1], stride[2]};
  double rate = 0;
  // The cell's rate at the four cells c .. c + 3 (the lanes, lanes.h: the same operations); the
  // maximum taken cell by cell in order, as below.
  auto cellLanes = [&](int i, int j, int k, std::int64_t c) __attribute__((always_inline)) {
    using lanes::v4d, lanes::load;
    const double *z = x.z.data(), *rh = x.rho.data();
    const v4d zC = load(z + c), rC = load(rh + c);
    v4d s = lanes::splat(0.0);
    for (int d = 0; d < dim; ++d) {
      const double* u = x.u[static_cast<std::size_t>(d)].data();
      const std::int64_t L = c - strides[d], R = c + strides[d];
      const v4d uC = load(u + c);
      s += (riemannImpedanceLanes(load(z + L), load(rh + L), zC, rC, uC - load(u + L)) +
            riemannImpedanceLanes(zC, rC, load(z + R), load(rh + R), load(u + R) - uC)) /
           mesh.dx(d);
    }
    s = lanes::sel(rC > 0, s / rC, lanes::splat(0.0));
    for (int l = 0; l < 4; ++l)
      if (s[l] > rate) {
        rate = s[l];
        if (cell) *cell = sb.index(i + l, j, k);
      }
  };
  // The owned cells in forEach's order, by rows (c: the index in the mixtures' box), those of
  // `rows` (a block of slabs: forMixBlocks).
  core::Box rows = owned;
  auto sweep = [&](auto&& f) {
    for (int k = rows.lo[2]; k <= rows.hi[2]; ++k)
      for (int j = rows.lo[1]; j <= rows.hi[1]; ++j) {
        std::int64_t c = x.box.index(rows.lo[0], j, k);
        int i = rows.lo[0];
        if (dim > 0 && !x.lowMach)  // riemann_low_mach: the scalar path (lowMachScale)
          for (; i + 3 <= rows.hi[0]; i += 4, c += 4) cellLanes(i, j, k, c);
        for (; i <= rows.hi[0]; ++i, ++c) f(i, j, k, c);
      }
  };
  auto one = [&](int i, int j, int k, std::int64_t c) {
    const auto C = static_cast<std::size_t>(c);
    double s = 0;
    for (int d = 0; d < dim; ++d) {
      const std::vector<double>& u = x.u[static_cast<std::size_t>(d)];
      const auto L = static_cast<std::size_t>(c - strides[d]), R = static_cast<std::size_t>(c + strides[d]);
      const double sL = x.lowMach ? lowMachScale(x, L, C) : 1.0, sR = x.lowMach ? lowMachScale(x, C, R) : 1.0;
      s += (riemannImpedance(x.z[L], x.rho[L], x.z[C], x.rho[C], u[C] - u[L], sL) +
            riemannImpedance(x.z[C], x.rho[C], x.z[R], x.rho[R], u[R] - u[C], sR)) /
           mesh.dx(d);
    }
    const double rho = dim > 0 ? x.rho[C] : 0.0;
    s = rho > 0 ? s / rho : 0.0;
    if (s > rate) {
      rate = s;
      if (cell) *cell = sb.index(i, j, k);
    }
  };
  const int top = dim - 1;
  forMixBlocks(st, owned, dim, x, owned.lo[top], owned.hi[top], [&](int lo, int hi) {
    rows.lo[top] = lo;
    rows.hi[top] = hi;
    sweep(one);
  });
  return rate;
}

void computeFacePressures(IceState& st, const core::Box& owned, int dim, double q1, double q2, bool riemann,
                          CellMixes* mixes) {
  const bool q = q1 > 0 || q2 > 0;
  CellMixes own;
  CellMixes& x = mixes ? *mixes : own;
  const std::array<std::int64_t, 3> stride = cellMixStrides(owned, dim);
  const std::int64_t strides[3] = {stride[0], stride[1], stride[2]};
  const core::Box& sb = st.press.box();
  const std::int64_t cellStrides[3] = {1, sb.length(0), std::int64_t(sb.length(0)) * sb.length(1)};
  std::vector<const double*> mass;
  for (const MaterialState& m : st.mat) mass.push_back(m.mass.data());
  const double* press = st.press.data();
  const int nm = static_cast<int>(mass.size());
  const int top = dim - 1;
  // The faces normal to d with index tlo .. thi in top (each face on its own).
  auto direction = [&](int d, int tlo, int thi) {
    const core::Box fb = owned.faces(d);
    double* pface = st.pressFace[d].data();
    // The face (i, j, k): stored cell cR on its high side, face index fi, cR's index R in the
    // mixtures' box. NM > 0: the number of materials fixed at compile time (the same operations
    // in the same order).
    auto face = [&]<int NM>(int i, int j, int k, std::int64_t cR, std::int64_t fi, std::int64_t R) {
      const int n = NM > 0 ? NM : nm;
      const std::int64_t cL = cR - cellStrides[d];
      double rL = 0, rR = 0;
      for (int r = 0; r < n; ++r) {
        const double* ms = mass[static_cast<std::size_t>(r)];
        rL += ms[cL];
        rR += ms[cR];
      }
      const double pL = press[cL], pR = press[cR];
      double pf = (rL + rR) > 0 ? (pL * rR + pR * rL) / (rL + rR) : 0.5 * (pL + pR);
      if (q && rL > 0 && rR > 0) {
        int l[3] = {i, j, k};
        l[d] -= 1;
        pf += shockViscosity(st, l, i, j, k, d, rL, rR, q1, q2);
      }
      if (riemann && rL > 0 && rR > 0) pf += riemannDissipation(x, R - strides[d], R, d);
      pface[fi] = pf;
    };
    // face() at the four faces fi .. fi + 3 without the shock viscosity (the lanes, lanes.h: the
    // same operations, selects for its branches).
    auto faceLanes = [&]<int NM>(std::int64_t cR, std::int64_t fi, std::int64_t R) __attribute__((always_inline)) {
      using lanes::v4d, lanes::v4m, lanes::load, lanes::sel;
      const std::int64_t cL = cR - cellStrides[d];
      v4d rL = lanes::splat(0.0), rR = lanes::splat(0.0);
      for (int r = 0; r < NM; ++r) {
        const double* ms = mass[static_cast<std::size_t>(r)];
        rL += load(ms + cL);
        rR += load(ms + cR);
      }
      const v4d pL = load(press + cL), pR = load(press + cR);
      const v4m on = rL + rR > 0;
      v4d pf = sel(on, pL * rR + pR * rL, 0.5 * (pL + pR)) / sel(on, rL + rR, lanes::splat(1.0));
      if (riemann) {  // riemannDissipation
        const double *u = x.u[static_cast<std::size_t>(d)].data(), *z = x.z.data(), *rh = x.rho.data();
        const std::int64_t L = R - strides[d];
        const v4d du = load(u + R) - load(u + L);
        const v4d diss = -riemannImpedanceLanes(load(z + L), load(rh + L), load(z + R), load(rh + R), du) * du;
        pf = sel((rL > 0) & (rR > 0), pf + diss, pf);
      }
      lanes::store(pface + fi, pf);
    };
    // The faces in forEach's order, by rows (flat indices along each row).
    core::Box rows = fb;
    rows.lo[top] = std::max(fb.lo[top], tlo);
    rows.hi[top] = std::min(fb.hi[top], thi);
    auto sweep = [&]<int NM>() {
      for (int k = rows.lo[2]; k <= rows.hi[2]; ++k)
        for (int j = rows.lo[1]; j <= rows.hi[1]; ++j) {
          const int i0 = rows.lo[0];
          std::int64_t cR = sb.index(i0, j, k), fi = fb.index(i0, j, k), R = riemann ? x.box.index(i0, j, k) : 0;
          int i = i0;
          if constexpr (NM > 0)
            if (!q && !x.lowMach)  // riemann_low_mach: the scalar path (lowMachScale)
              for (; i + 3 <= rows.hi[0]; i += 4, cR += 4, fi += 4, R += 4) faceLanes.template operator()<NM>(cR, fi, R);
          for (; i <= rows.hi[0]; ++i, ++cR, ++fi, ++R) face.template operator()<NM>(i, j, k, cR, fi, R);
        }
    };
    if (nm == 1) sweep.template operator()<1>();
    else if (nm == 2) sweep.template operator()<2>();
    else if (nm == 3) sweep.template operator()<3>();
    else sweep.template operator()<0>();
  };
  if (riemann)
    forMixBlocks(st, owned, dim, x, owned.lo[top], owned.hi[top] + 1, [&](int lo, int hi) {
      for (int d = 0; d < dim; ++d) direction(d, lo, hi);
    });
  else
    for (int d = 0; d < dim; ++d) direction(d, owned.lo[top], owned.hi[top] + 1);
}

// With external materials the energy correction is off, so the Riemann term's work would not
// return as heat: coupled runs keep the average (docs/ice.md "Face pressure").
// The impedances need kappa in the ghost cells: the equilibrium fills them with the other fields'
// (fillMaterialGhosts) when the Riemann face pressure is on, for this phase and the stable step.
void IceSolver::computeFacePressure() {
  mixes_.lowMach = riemannLowMach_;
  // lowMachScale's strain reads the step's equilibrium pressure, as in the stable step and the
  // face velocities (before the increment): kept by computePressureIncrement.
  if (riemannLowMach_ && lowMachPressure_.size() == static_cast<std::size_t>(st_.press.npts()))
    mixes_.pressure = lowMachPressure_.data();
  computeFacePressures(st_, owned_, mesh_.dim(), q1_, q2_, riemannFacePressureOn(), &mixes_);
  mixes_.pressure = nullptr;
}

}  // namespace mpmice::ice
