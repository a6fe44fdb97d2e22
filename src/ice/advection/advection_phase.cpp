// IceSolver phase 12: advection of the fluids' mass, momentum, total energy and volume with the
// face velocities, in flux form (each face flux is computed once from the same values on every
// rank that sees the face, so closed boxes conserve to round-off).
//   mass flux   F_r = theta_f,r |u_f| dt A / v_f,r   (theta, v: donor-cell or limited linear
//               reconstruction, time-centred: q_D +- (1 - |u_f| dt / dx) slope / 2)
//   then F_r u_f, F_r (e_f + |u_f|^2 / 2), F_r v_f for momentum, total energy, volume.
// The reconstructed face volume fractions are rescaled so that they sum, over the fluids, to the
// donor-cell sum: uniform pressure and velocity stay uniform across material interfaces.
// Donors whose outflows over all faces would exceed 90% of their mass have them scaled down
// (positivity; conservative). The part of a donor's fluid that stays keeps at least
// kMinRemainderShare of its specific thermal energy and volume: where the limited face values of
// its outgoing faces would take more (a trace whose neighbours carry larger e or v), they are
// blended toward the donor's own values (the positivity blend, below; conservative). Internal energy = total - kinetic; where round-off of that difference would lose more than 90%
// of the thermal energy (e - e_cold) advected directly (strong rarefactions), the direct value is used.
// Second order with the Riemann face pressure: the face's (specific volume, internal energy) pair
// is kept between the isentropes of its two cells where both hold the material alone
// (entropy-bounded face state, below).
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <type_traits>

#include "ice/advection/limiter.h"
#include "ice/exchange/pointwise_exchange.h"
#include "ice/ice_constants.h"
#include "ice/solver/ice_solver.h"

namespace mpmice::ice {

using core::forEach;

namespace {
using namespace advected;
constexpr int kNumAcc = kCount;
// The positivity blend's per-donor sums (AdvectionScratch::remainder, two slabs): the mass left
// after the outflows, and over the outgoing faces (w = the scaled outgoing mass flux, D the donor's
// Lagrangian values) sum w (e_f - e_D), sum w |u_f - u_D|^2, sum w (u_f - u_D) (3), sum w (v_f - v_D).
enum RemSum : int { kRemMass, kRemE, kRemU2, kRemUx, kRemUy, kRemUz, kRemV, kRemSums };

// The positivity blend of one donor (the largest b in [0, 1] with face values q_D + b (q_f - q_D)
// on its outgoing faces that keeps its remainder admissible). The remainder (mass m_r, momentum,
// total energy after the outflows) has the internal energy
//   I(b) = m_r e_D - b sum w (e_f - e_D) - b^2 / 2 (sum w |du|^2 + |sum w du|^2 / m_r)
// (the terms in u_D cancel: Galilean invariance), concave in b, and m_r e_D at b = 0; its volume
// m_r v_D - b sum w (v_f - v_D) is linear. Both are kept above kMinRemainderShare of m_r e_D
// (thermal: e - e_cold at the donor's density) and m_r v_D. Every inflow carries a positive
// (e_f, v_f) (the limited reconstruction stays within the neighbours' values, the entropy bound
// between two isentropes), and the internal energy of a sum of parts is at least the sum of
// theirs (|P|^2 / 2m is convex and of degree 1), so the cell's e and v after advection are
// positive by construction, whatever the face values.
// R: the donor's first sum, the others rs apart (AdvectionScratch::remainder: one array per sum).
// Inlined: one per cell.
[[gnu::always_inline]] inline double positivityBlend(const double* R, std::int64_t rs, double eThermal, double vD) {
  auto sum = [&](int q) { return R[q * rs]; };
  const double mr = sum(kRemMass);
  if (!(mr > 0)) return 1.0;
  double b = 1.0;
  const double C = (1.0 - kMinRemainderShare) * mr * eThermal;
  const double A = sum(kRemE);
  const double P2 = sum(kRemUx) * sum(kRemUx) + sum(kRemUy) * sum(kRemUy) + sum(kRemUz) * sum(kRemUz);
  if (C > 0 && (A + 0.5 * sum(kRemU2) - C) * mr + 0.5 * P2 > 0) {  // I(1) below the share (no division)
    const double B = sum(kRemU2) + P2 / mr;
    b = std::min(b, 2.0 * C / (A + std::sqrt(A * A + 2.0 * B * C)));
  }
  if (C > 0 && -A > C) b = std::min(b, C / -A);
  const double Cv = (1.0 - kMinRemainderShare) * mr * vD;
  if (Cv > 0 && std::abs(sum(kRemV)) > Cv) b = std::min(b, Cv / std::abs(sum(kRemV)));
  return b;
}

// The face reconstruction, chosen once per advection (the face loops are instantiated for each):
// donor cell (first order) or the limited linear one with limiter L.
template <bool Second, Limiter L>
struct Recon {};

// At a face with velocity uf between cells cL and cR = cL + sd: the donor cell D and the
// time-centred face value of a cell field f, f[D] (first order) or f[D] + w slope_L(f) with
// w = sgn(uf) (1 - |uf| dt / dx) / 2 (both passes use this one helper).
template <bool Second, Limiter L>
struct FaceValue {
  std::int64_t D, sd;
  double w;
  FaceValue(Recon<Second, L>, double uf, std::int64_t cL, std::int64_t sd_, double dt, double dx)
      : D(uf > 0 ? cL : cL + sd_), sd(sd_), w(0.5 * (uf > 0 ? 1.0 : -1.0) * (1.0 - std::abs(uf) * dt / dx)) {}
  // Inlined: several per face.
  [[gnu::always_inline]] double operator()(const double* f) const {
    const double q0 = f[D];
    if constexpr (!Second) return q0;
    else return q0 + w * limitedSlope<L>(q0 - f[D - sd], f[D + sd] - q0);
  }
};
// FaceValue at four faces of a row (the lanes, lanes.h; cL: the first face's low cell, the others
// follow it): the donor's value and the two around it are selected per lane from the four cells
// cL - sd, cL, cR, cR + sd; the same operations as FaceValue.
template <bool Second, Limiter L>
struct FaceValueLanes {
  std::int64_t cL, sd;
  lanes::v4m up;  // uf > 0: the donor is cL
  lanes::v4d w;
  FaceValueLanes(Recon<Second, L>, lanes::v4d uf, std::int64_t cL_, std::int64_t sd_, double dt, double dx)
      : cL(cL_), sd(sd_), up(uf > 0),
        w(0.5 * lanes::sel(uf > 0, lanes::splat(1.0), lanes::splat(-1.0)) * (1.0 - lanes::abs(uf) * dt / dx)) {}
  // The donor's value f[D].
  [[gnu::always_inline]] lanes::v4d donor(const double* f) const {
    return lanes::sel(up, lanes::load(f + cL), lanes::load(f + cL + sd));
  }
  [[gnu::always_inline]] lanes::v4d operator()(const double* f) const {
    using lanes::load, lanes::sel;
    const lanes::v4d a = load(f + cL), b = load(f + cL + sd);
    const lanes::v4d q0 = sel(up, a, b);
    if constexpr (!Second) return q0;
    else {
      const lanes::v4d qm = sel(up, load(f + cL - sd), a), qp = sel(up, b, load(f + cL + 2 * sd));
      return q0 + w * limitedSlopeLanes<L>(q0 - qm, qp - q0);
    }
  }
};

// acc[cL] -= v and acc[cR] += v at the four faces (lanes) with nz set, cL = cR - sd, each cell's
// terms in the order of the face-by-face loop: along a row (alongRow, sd = 1) lane l's high cell is
// lane l + 1's low cell, and a cell's low face's term (+=) comes before its high face's (-=).
// ownL, ownR: whether the low and high cells take their terms (across rows only).
[[gnu::always_inline]] inline void applyLanes(double* acc, lanes::v4d v, lanes::v4m nz, std::int64_t cL,
                                              std::int64_t cR, bool alongRow, bool ownL = true, bool ownR = true) {
  using lanes::v4d, lanes::load, lanes::store, lanes::sel;
  if (alongRow) {
    const lanes::v4m keep3 = {-1, -1, -1, 0};
    auto next = [](auto x) { return __builtin_shufflevector(x, x, 1, 2, 3, 3); };  // lane l + 1's
    v4d a = load(acc + cR);
    a = sel(nz, a + v, a);
    a = sel(next(nz) & keep3, a - next(v), a);
    store(acc + cR, a);
    if (nz[0]) acc[cL] -= v[0];
  } else {
    if (ownL) {
      const v4d aL = load(acc + cL);
      store(acc + cL, sel(nz, aL - v, aL));
    }
    if (ownR) {
      const v4d aR = load(acc + cR);
      store(acc + cR, sel(nz, aR + v, aR));
    }
  }
}

// The isentrope through each stored cell's Lagrangian state (v_c, e_c) of one fluid, from the local
// stiffened-gas fit of its EOS, p = Gamma e / v - P: Gamma = v dp/de at fixed v and P from the
// cell's own pressure, both from two batch pressure calls, at e and 2 e (exact for the ideal and
// stiffened gases, Mie-Gruneisen and JWL: each is linear in e at fixed v). Along it de = -p dv:
// e_s(v) = pi v + (e_c - pi v_c) (v_c / v)^Gamma with pi = P / (Gamma + 1) (exactly the
// isentrope of an ideal or stiffened gas). Gamma is NaN where the fit is not admissible (e <= 0,
// v <= 0, Gamma <= 0, e_c - pi v_c <= 0, non-finite): faces touching that cell are not bounded.
// Cells v[0 .. n - 1], e[0 .. n - 1] to gam[0 .. n - 1], pi[0 .. n - 1].
void isentropeFits(const Eos& eos, std::size_t n, const double* v, const double* e, AdvectionScratch& s, double* gam,
                   double* pi) {
  // The batch EOS arguments a chunk of cells at a time (each cell's fit is its own: the same
  // values as over the whole box, without four more arrays of the box).
  const std::size_t chunk = AdvectionScratch::kEosChunk;
  s.eosRho.resize(chunk);
  s.eosE.resize(chunk);
  s.eosP1.resize(chunk);
  s.eosP2.resize(chunk);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t c0 = 0; c0 < n; c0 += chunk) {
    const std::size_t m = std::min(chunk, n - c0);
    const double *vc = v + c0, *ec = e + c0;
    for (std::size_t c = 0; c < m; ++c) {
      s.eosRho[c] = vc[c] > 0 ? 1.0 / vc[c] : 1.0;
      s.eosE[c] = ec[c];
    }
    eos.pressure(m, s.eosRho.data(), s.eosE.data(), s.eosP1.data());
    for (std::size_t c = 0; c < m; ++c) s.eosE[c] = 2.0 * ec[c];
    eos.pressure(m, s.eosRho.data(), s.eosE.data(), s.eosP2.data());
    for (std::size_t c = 0; c < m; ++c) {
      const double p1 = s.eosP1[c], dp = s.eosP2[c] - p1;  // dp = Gamma e / v
      const double g = ec[c] > 0 && vc[c] > 0 ? dp * vc[c] / ec[c] : nan;
      const double P = dp - p1;
      const double w = P / (g + 1.0);
      const bool ok = g > 0 && std::isfinite(g) && std::isfinite(w) && ec[c] - w * vc[c] > 0;
      gam[c0 + c] = ok ? g : nan;
      pi[c0 + c] = ok ? w : 0.0;
    }
  }
}

// Whether a material with volume fraction theta fills its cell alone (the others together below
// kPresentFraction). Only there is its Lagrangian state the one its own fluxes and p dv work
// made: in a mixed cell the equilibrium pressure moves volume between the materials at fixed e,
// without that work (docs/ice.md "Traces", the semi-implicit water-air stops), so the entropy of a
// material's state there bounds nothing. The entropy bound applies between single-fluid cells;
// at a material interface (water against air: the contact's mixed cells) the face keeps its
// limited value (with the bound there the water-air contact smeared: L1 5.743 -> 5.759 at 400 cells).
inline bool singleFluid(double theta) { return theta >= 1.0 - kPresentFraction; }

// The face's internal energy ef at the face's specific volume vf, kept between the isentropes of
// the donor D and the other cell O of the face (an entropy bound: a face state whose entropy lies
// outside the range of its two cells' is a reconstruction artefact; Tadmor's minimum entropy
// principle). Independent limited reconstructions of e and v can pair them off their
// isentropes: Toro's test 3 then carried an entropy deficit of 4-6 % from its young shock into
// the gas between contact and shock (+3 % in density at 200 cells, docs/ice.md "Shocks").
// gam, pi: the fits of stored cell c at c - off (AdvectionScratch::isenGamma: a window of slabs).
inline double entropyBounded(double ef, double vf, std::int64_t D, std::int64_t O, const double* e, const double* v,
                             const double* gam, const double* pi, std::int64_t off) {
  const double gD = gam[D - off], gO = gam[O - off];
  if (!(gD > 0 && gO > 0 && vf > 0)) return ef;
  const double pD = pi[D - off], pO = pi[O - off];
  const double eD = pD * vf + (e[D] - pD * v[D]) * std::pow(v[D] / vf, gD);
  const double eO = pO * vf + (e[O] - pO * v[O]) * std::pow(v[O] / vf, gO);
  if (!(std::isfinite(eD) && std::isfinite(eO))) return ef;
  return std::clamp(ef, std::min(eD, eO), std::max(eD, eO));
}
}  // namespace

void IceSolver::advectFluids() {
  fillMaterialGhosts(true);
  const int dim = mesh_.dim();
  const int nm = numMaterials();
  const double V = mesh_.cellVolume();
  const double dt = dt_;
  const core::Box& sb = st_.press.box();
  const std::size_t npts = static_cast<std::size_t>(sb.numPts());
  // The fluids in order, their face fields: the first two fluids' mass fluxes are the state's face
  // volume fluxes and face pressures (lent below), the others' their own.
  std::vector<int> fluids;
  for (int r = 0; r < nm; ++r)
    if (!st_.mat[r].external) fluids.push_back(r);
  if (adv_.mat.size() != static_cast<std::size_t>(nm)) {
    adv_.mat.assign(static_cast<std::size_t>(nm), {});
    for (std::size_t q = 2; q < fluids.size(); ++q)
      for (int d = 0; d < dim; ++d)
        adv_.mat[static_cast<std::size_t>(fluids[q])].massFlux[d] =
            core::Field("mass_flux", core::Centering::Cell, owned_.faces(d), 1, 0);
  }
  // The face volume fluxes and face pressures (the pressure increment and the face pressure to
  // the Lagrangian phase; computed again before the next step reads them) hold the first two
  // fluids' mass fluxes. They are lent here and handed back at the end, storage and all (no
  // allocation per step).
  auto lend = [&] {
    for (std::size_t d = 0; d < 3; ++d) {
      if (!fluids.empty()) std::swap(adv_.mat[static_cast<std::size_t>(fluids[0])].massFlux[d], st_.volFlux[d]);
      if (fluids.size() > 1) std::swap(adv_.mat[static_cast<std::size_t>(fluids[1])].massFlux[d], st_.pressFace[d]);
    }
  };
  lend();
  struct HandBack {
    decltype(lend)& swap;
    ~HandBack() { swap(); }
  } handBack{lend};
  adv_.eint.resize(npts);  // the stored box's size, kept from step to step
  // With one fluid advected here the negligible-trace cut-off of the conversion (below) compares
  // its mass after advection with itself: never below kNegligibleMassFraction of it, no fluid
  // mass to sum.
  const bool oneFluid = fluids.size() == 1;

  const std::int64_t strides[3] = {1, sb.length(0), std::int64_t(sb.length(0)) * sb.length(1)};
  // The conserved amounts of the owned cells of the fluid being advected (advected::k* order): the
  // mass, m u, m (e + |u|^2 / 2) and m v in the state's own fields (its velocity and energy, the
  // face values' sources, are copied to a window of slabs before they are overwritten: lagWindow
  // below), m e in the scratch shared by the fluids; null: the momentum beyond the mesh's dimension.
  auto accumulators = [&](MaterialState& m, double** a) {
    a[kMass] = m.mass.data();
    for (int d = 0; d < 3; ++d) a[kMomX + d] = d < dim ? m.vel.data(d) : nullptr;
    a[kEnergy] = m.eint.data();
    a[kVolume] = m.spvol.data();
    a[kEint] = adv_.eint.data();
  };
  // The saved Lagrangian values of stored cell c (AdvectionScratch::lagKept, sorted once pass 2
  // is done); null where none are saved.
  auto lagSaved = [&](std::int64_t c) -> const AdvectionScratch::LagCell* {
    const auto& kept = adv_.lagKept;
    auto q = std::lower_bound(kept.begin(), kept.end(), c, [](const auto& e, std::int64_t x) { return e.cell < x; });
    return q != kept.end() && q->cell == c ? &*q : nullptr;
  };
  // The owned cells in forEach's order (ownedCells_), by rows: f4(c) for the four cells c .. c + 3
  // (the lanes), f1(c) for one (the rest of a row); row(j, k, c) before each row (c its first).
  // forRows: the same over the cells of b (owned).
  auto forRows = [&](const core::Box& b, auto&& f4, auto&& f1, auto&& row) {
    for (int k = b.lo[2]; k <= b.hi[2]; ++k)
      for (int j = b.lo[1]; j <= b.hi[1]; ++j) {
        std::int64_t c = sb.index(b.lo[0], j, k);
        row(j, k, c);
        int i = b.lo[0];
        for (; i + 3 <= b.hi[0]; i += 4, c += 4) f4(c);
        for (; i <= b.hi[0]; ++i, ++c) f1(c);
      }
  };
  auto forOwnedRows = [&](auto&& f4, auto&& f1, auto&& row) { forRows(owned_, f4, f1, row); };
  // The fluids' mass after advection at the owned cells ilo .. ihi of row (j, k) (more than one
  // fluid: the negligible-trace cut-off of the conversion, below), as fluid q's pass 2 completes them:
  // each fluid's mass terms (pass 2's, in the same order for every cell: x low, x high, y low,
  // y high, z low, z high) summed over the fluids in order. The fluids before q are converted
  // (their mass, or the trace their conversion dropped), q's mass is accumulated, and those after
  // q have their mass before advection, their mass fluxes and their outflow scale (in their
  // specific volume's array until their conserved amounts, outflowScale) for their terms.
  const std::int64_t faceStrides[3] = {1, owned_.faces(1).length(0),
                                       std::int64_t(owned_.faces(2).length(0)) * owned_.faces(2).length(1)};
  adv_.dropped.resize(static_cast<std::size_t>(nm));
  auto fluidMassRow = [&](int q, int j, int k, int ilo, int ihi) {
    const int nx = ihi - ilo + 1;
    adv_.fluidMassRow.assign(static_cast<std::size_t>(nx), 0.0);
    double* out = adv_.fluidMassRow.data();
    const std::int64_t c0 = sb.index(ilo, j, k);
    for (int r : fluids) {
      const MaterialState& m = st_.mat[r];
      const double* ms = m.mass.data();
      if (r <= q) {
        const auto& dropped = adv_.dropped[static_cast<std::size_t>(r)];  // in increasing cell order
        auto t = r < q ? std::lower_bound(dropped.begin(), dropped.end(), c0,
                                          [](const auto& e, std::int64_t c) { return e.first < c; })
                       : dropped.end();
        int i = 0;
        if (t == dropped.end() || t->first >= c0 + nx)  // none in the row: four at a time (the lanes)
          for (; i + 4 <= nx; i += 4) lanes::store(out + i, lanes::load(out + i) + lanes::load(ms + c0 + i));
        for (; i < nx; ++i) {
          double ma = ms[c0 + i];
          if (t != dropped.end() && t->first == c0 + i) ma = (t++)->second;
          out[i] += ma;
        }
        continue;
      }
      const double* sc = m.spvol.data();  // the outflow scale (outflowScale)
      const double* Fm[3] = {nullptr, nullptr, nullptr};
      std::int64_t f0[3] = {0, 0, 0};
      for (int d = 0; d < dim; ++d) {
        Fm[d] = adv_.mat[static_cast<std::size_t>(r)].massFlux[d].data();
        f0[d] = owned_.faces(d).index(ilo, j, k);
      }
      int i = 0;
      for (; i + 4 <= nx; i += 4) {  // the lanes: the same operations, a face with F = 0 a select
        using lanes::v4d, lanes::load, lanes::sel;
        const std::int64_t c = c0 + i;
        v4d ma = load(ms + c);
        for (int d = 0; d < dim; ++d) {
          const std::int64_t sd = strides[d], fl = f0[d] + i;
          const v4d FL = load(Fm[d] + fl), FH = load(Fm[d] + fl + faceStrides[d]);
          ma = sel(FL != 0, ma + sel(FL > 0, load(sc + c - sd), load(sc + c)) * FL, ma);
          ma = sel(FH != 0, ma - sel(FH > 0, load(sc + c), load(sc + c + sd)) * FH, ma);
        }
        lanes::store(out + i, load(out + i) + ma);
      }
      for (; i < nx; ++i) {
        const std::int64_t c = c0 + i;
        double ma = ms[c];
        for (int d = 0; d < dim; ++d) {
          const std::int64_t sd = strides[d], fl = f0[d] + i;
          const double FL = Fm[d][fl], FH = Fm[d][fl + faceStrides[d]];
          if (FL != 0) ma += (FL > 0 ? sc[c - sd] : sc[c]) * FL;
          if (FH != 0) ma -= (FH > 0 ? sc[c] : sc[c + sd]) * FH;
        }
        out[i] += ma;
      }
    }
  };
  // One fluid's primitive values from its conserved amounts, once its fluxes are all applied:
  // velocity, specific volume and internal energy (its velocity and energy, the face values'
  // sources, held the Lagrangian values until here).
  // DIM > 0: the mesh's dimension fixed at compile time (the same operations in the same order).
  auto convertDim = [&]<int DIM>(int r, auto&& lagAt) {
    const int nd = DIM > 0 ? DIM : dim;
    MaterialState& m = st_.mat[r];
    double* a[kNumAcc];
    accumulators(m, a);
    double *ms = m.mass.data(), *e = m.eint.data(), *v = m.spvol.data();
    const auto u = core::components(m.vel);
    const double* vL = m.lagSpvol().data();
    // The cells the conversion drops as traces (decided as pass 2 completed their slab:
    // dropCandidates), in increasing order: the next at *nextDrop (the cells come in that order).
    const std::int64_t* nextDrop = adv_.dropCells.data();
    const std::int64_t* const dropEnd = nextDrop + adv_.dropCells.size();
    auto& dropped = adv_.dropped[static_cast<std::size_t>(r)];
    dropped.clear();
    // The fallback guards the thermal energy e - e_cold(rho) (the health check's cv T), not e: a
    // Mie-Gruneisen liquid with a reference temperature has e = 0 at T0 (e_cold = -cv T0) and moves
    // through e = 0 at ~T0 (docs/ice.md "Health check"). Only EOS with a cold energy make the call.
    const bool cold = m.eos->hasColdEnergy();
    auto cell = [&](std::int64_t c) {
      const double mass = a[kMass][c];
      // Absent: traces below kTraceMass kg, or below kNegligibleMassFraction of the cell's fluid
      // mass, are dropped (their specific values, ratios of round-off, grow without bound; the
      // energy they held is audited). They keep the Lagrangian values (velocity and energy: as they are).
      if (nextDrop != dropEnd && *nextDrop == c) {
        ++nextDrop;
        if (mass > 0) audit_.add(std::abs(a[kEnergy][c]), c, r);
        if (!oneFluid && (mass != 0 || std::signbit(mass))) dropped.push_back({c, mass});  // not +0: fluidMassRow
        ms[c] = 0;
        v[c] = vL[c];
        // Its velocity and energy hold m u and m (e + |u|^2 / 2): the Lagrangian values back
        // (saved when pass 2 completed the cell's mass: dropCandidates).
        double lu[3], le;
        lagAt(m, c, lu, le);
        for (int d = 0; d < nd; ++d) u[d][c] = lu[d];
        e[c] = le;
        return;
      }
      const double inv = 1.0 / mass;
      double ke = 0;
      for (int d = 0; d < nd; ++d) {
        double ud = a[kMomX + d][c] * inv;
        if (std::abs(ud) < kTinyVelocity) ud = 0.0;  // no denormal tails ahead of waves
        u[d][c] = ud;
        ke += ud * ud;
      }
      ms[c] = mass;
      v[c] = a[kVolume][c] * inv;
      // The limited face volumes can drain more volume than a trace holds when its neighbours carry
      // far larger specific volumes (held traces, docs/ice.md "Traces"): keep the Lagrangian value
      // (specific volume is not a conserved quantity; the equilibrium pressure sets it again).
      if (!(v[c] > 0)) {
        v[c] = vL[c];
        ++fallbacks_;
      }
      const double eE = a[kEnergy][c] * inv - 0.5 * ke;
      const double eA = a[kEint][c] * inv;
      const double ec = cold ? m.eos->coldEnergy(1.0 / v[c]) : 0.0;
      if (eA - ec > 0 && eE - ec < kMinEnergyShare * (eA - ec)) {
        e[c] = eA;
        ++fallbacks_;
        audit_.add(mass * (eA - eE), c, r);  // not conservative: the energy it adds is audited
      } else {
        e[c] = eE;
      }
      audit_.localEnergy += mass * (e[c] + 0.5 * ke);
    };
    // cell() at the four cells c .. c + 3 (the lanes, the same operations) where each of them is
    // present, keeps its volume and needs no energy fallback (without a cold energy); otherwise
    // cell() one after the other. The audit's sum taken cell by cell in order.
    auto cellLanes = [&](std::int64_t c) {
      using lanes::v4d, lanes::v4m, lanes::load, lanes::sel;
      if constexpr (DIM > 0) {
        if (!cold) {
          const v4d mass = load(a[kMass] + c);
          v4m ok = {-1, -1, -1, -1};
          if (nextDrop != dropEnd && *nextDrop < c + 4) ok = v4m{0, 0, 0, 0};
          const v4d inv = 1.0 / mass;
          v4d ud[DIM], ke = lanes::splat(0.0);
          for (int d = 0; d < DIM; ++d) {
            ud[d] = load(a[kMomX + d] + c) * inv;
            ud[d] = sel(lanes::abs(ud[d]) < kTinyVelocity, lanes::splat(0.0), ud[d]);
            ke += ud[d] * ud[d];
          }
          const v4d vv = load(a[kVolume] + c) * inv;
          const v4d eE = load(a[kEnergy] + c) * inv - 0.5 * ke, eA = load(a[kEint] + c) * inv;
          const double ec = 0.0;
          ok = ok & (vv > 0) & ~((eA - ec > 0) & (eE - ec < kMinEnergyShare * (eA - ec)));
          if (!lanes::any(~ok)) {
            for (int d = 0; d < DIM; ++d) lanes::store(u[d] + c, ud[d]);
            lanes::store(v + c, vv);
            lanes::store(e + c, eE);
            const v4d t = mass * (eE + 0.5 * ke);
            for (int l = 0; l < 4; ++l) audit_.localEnergy += t[l];
            return;
          }
        }
      }
      for (int l = 0; l < 4; ++l) cell(c + l);
    };
    forOwnedRows(cellLanes, cell, [](int, int, std::int64_t) {});
  };
  // lagAt(m, c, u, e): the Lagrangian velocity and energy of stored cell c (after pass 2).
  auto convert = [&](int r, auto&& lagAt) {
    if (dim == 2) convertDim.template operator()<2>(r, lagAt);
    else if (dim == 3) convertDim.template operator()<3>(r, lagAt);
    else convertDim.template operator()<0>(r, lagAt);
  };
  // Passes 1 and 2 with the scene's reconstruction chosen here, once (Recon).
  auto passes = [&]<bool Second, Limiter L>(Recon<Second, L> rc) {
    // Pass 1: the mass flux through every face (what the positivity scale needs). The other
    // fluxes are the mass flux times a face value (pass 2).
    struct Ptr {
      const double *th, *sv, *uf;
      double* flux;
      bool skip;
    };
    std::vector<Ptr> ptr(static_cast<std::size_t>(nm));
    for (int d = 0; d < dim; ++d) {
      const double dx = mesh_.dx(d);
      const double A = V / dx;
      const std::int64_t sd = strides[d];
      const core::Box fb = owned_.faces(d);
      for (int r = 0; r < nm; ++r) {
        MaterialState& m = st_.mat[r];
        ptr[r] = {m.theta.data(), m.spvol.data(), m.velFace[d].data(),
                  m.external ? nullptr : adv_.mat[r].massFlux[d].data(), m.external};
      }
      const core::Field* solidFaces = st_.solidFaces.on ? &st_.solidFaces.cover[d] : nullptr;
      // The face fi with the stored cell cR on its high side. NM > 0: the number of materials
      // fixed at compile time (the small loops unroll, no memset of the arrays; the same
      // operations in the same order).
      auto face1 = [&]<int NM>(std::int64_t fi, std::int64_t cR) {
        const int n = NM > 0 ? NM : nm;
        const std::int64_t cL = cR - sd;
        double th1[kMaxMaterials], th2[kMaxMaterials], fm[kMaxMaterials];
        double s1 = 0, s2 = 0;
        for (int r = 0; r < n; ++r) {
          const Ptr& P = ptr[r];
          th1[r] = th2[r] = fm[r] = 0;  // fm is read only where th1 or th2 is set (with it)
          if (P.skip) continue;
          const double uf = P.uf[fi];
          if (uf == 0) continue;
          const FaceValue face(rc, uf, cL, sd, dt, dx);
          const double sgn = uf > 0 ? 1.0 : -1.0;
          th1[r] = P.th[face.D];
          th2[r] = face(P.th);
          s1 += th1[r];
          s2 += th2[r];
          fm[r] = sgn * std::abs(uf) * dt * A / face(P.sv);  // times theta below
        }
        // With the solids' face transport the fluids share the open part of the face, 1 - cover
        // (solid_faces.h), as in the volume fluxes of the pressure.
        const double target = solidFaces != nullptr && s1 > 0 ? 1.0 - solidFaces->data()[fi] : s1;
        const double scale = s2 > 0 ? target / s2 : 0.0;
        for (int r = 0; r < n; ++r) {
          const Ptr& P = ptr[r];
          if (th1[r] == 0 && th2[r] == 0) {
            if (!P.skip) P.flux[fi] = 0;
            continue;
          }
          P.flux[fi] = fm[r] * th2[r] * scale;
        }
      };
      // face1 at the four faces fi .. fi + 3 (the lanes, lanes.h): the same operations in the
      // same order, a face with uf = 0 or a zero volume fraction a select of what face1 leaves.
      auto face1Lanes = [&]<int NM>(std::int64_t fi, std::int64_t cR) __attribute__((always_inline)) {
        using lanes::v4d, lanes::v4m, lanes::load, lanes::sel, lanes::splat;
        const std::int64_t cL = cR - sd;
        const v4d zero = splat(0.0);
        v4d th1[NM], th2[NM], fm[NM];
        v4d s1 = zero, s2 = zero;
        for (int r = 0; r < NM; ++r) {
          const Ptr& P = ptr[r];
          th1[r] = th2[r] = fm[r] = zero;
          if (P.skip) continue;
          const v4d uf = load(P.uf + fi);
          const v4m on = uf != 0;
          const FaceValueLanes face(rc, uf, cL, sd, dt, dx);
          const v4d sgn = sel(uf > 0, splat(1.0), splat(-1.0));
          th1[r] = sel(on, face.donor(P.th), zero);
          th2[r] = sel(on, face(P.th), zero);
          s1 = sel(on, s1 + th1[r], s1);
          s2 = sel(on, s2 + th2[r], s2);
          fm[r] = sel(on, sgn * lanes::abs(uf) * dt * A / face(P.sv), zero);
        }
        const v4d target = solidFaces != nullptr ? sel(s1 > 0, 1.0 - load(solidFaces->data() + fi), s1) : s1;
        const v4d scale = sel(s2 > 0, target / s2, zero);
        for (int r = 0; r < NM; ++r) {
          const Ptr& P = ptr[r];
          if (P.skip) continue;
          const v4m none = (th1[r] == 0) & (th2[r] == 0);
          lanes::store(P.flux + fi, sel(none, zero, fm[r] * th2[r] * scale));
        }
      };
      // The faces in forEach's order, by rows (flat indices along each row).
      auto sweep1 = [&]<int NM>() {
        for (int k = fb.lo[2]; k <= fb.hi[2]; ++k)
          for (int j = fb.lo[1]; j <= fb.hi[1]; ++j) {
            std::int64_t fi = fb.index(fb.lo[0], j, k), cR = sb.index(fb.lo[0], j, k);
            int i = fb.lo[0];
            if constexpr (NM > 0)
              for (; i + 3 <= fb.hi[0]; i += 4, fi += 4, cR += 4) face1Lanes.template operator()<NM>(fi, cR);
            for (; i <= fb.hi[0]; ++i, ++fi, ++cR) face1.template operator()<NM>(fi, cR);
          }
      };
      if (nm == 1) sweep1.template operator()<1>();
      else if (nm == 2) sweep1.template operator()<2>();
      else if (nm == 3) sweep1.template operator()<3>();
      else sweep1.template operator()<0>();
    }

    // Positivity: a donor whose outflows over all its faces would exceed kMaxOutflowFraction of
    // its mass has them scaled down (it keeps at least 10% of its mass, so its specific values
    // stay well conditioned) (the same factor on both sides of each face, so conservation holds);
    // 1 elsewhere. One fluid at a time (the passes below take them one after the other): each
    // owned donor's outflow summed over its faces in the order x low, x high, y low, y high,
    // z low, z high; the ghosts' from their owners.
    // Computed once per fluid (for the fluid mass below) over the stored box in the fluid's own
    // specific volume's array (free from pass 1, its last reader, to the fluid's conserved
    // amounts: m v; its ghosts are filled again at the next equilibrium, before anything reads
    // them); where it is not 1 (few cells) it is kept, and put back two slabs at a time
    // (scaleWindow) when the fluid is advected.
    adv_.capped.resize(static_cast<std::size_t>(nm));
    auto outflowScale = [&](int r) {
      const double* ms = st_.mat[r].mass.data();
      core::Field& outScale = st_.mat[r].spvol;
      double* sc = outScale.data();
      const AdvectionScratch::Material& am = adv_.mat[static_cast<std::size_t>(r)];
      std::fill(sc, sc + npts, 0.0);
      for (int d = 0; d < dim; ++d) {
        const core::Box fb = owned_.faces(d);
        const double* Fm = am.massFlux[d].data();
        const std::int64_t up = d == 0 ? 1 : (d == 1 ? fb.length(0) : std::int64_t(fb.length(0)) * fb.length(1));
        for (int k = owned_.lo[2]; k <= owned_.hi[2]; ++k)
          for (int j = owned_.lo[1]; j <= owned_.hi[1]; ++j) {
            const double* F = Fm + fb.index(owned_.lo[0], j, k);  // the row's low faces
            double* out = sc + sb.index(owned_.lo[0], j, k);
            int i = 0;
            for (; i + 4 <= owned_.length(0); i += 4) {  // the lanes: the same operations
              using lanes::v4d, lanes::load, lanes::sel;
              const v4d lo = load(F + i), hi = load(F + i + up);
              v4d o = load(out + i);
              o = sel(lo < 0, o - lo, o);
              lanes::store(out + i, sel(hi > 0, o + hi, o));
            }
            for (; i < owned_.length(0); ++i) {
              if (F[i] < 0) out[i] -= F[i];
              if (F[i + up] > 0) out[i] += F[i + up];
            }
          }
      }
      std::size_t c = 0;
      for (; c + 4 <= npts; c += 4) {  // the lanes: the same operations
        const lanes::v4d o = lanes::load(sc + c), mx = kMaxOutflowFraction * lanes::load(ms + c);
        lanes::store(sc + c, lanes::sel(o > mx, mx / o, lanes::splat(1.0)));
      }
      for (; c < npts; ++c) sc[c] = sc[c] > kMaxOutflowFraction * ms[c] ? kMaxOutflowFraction * ms[c] / sc[c] : 1.0;
      ghosts_->fill(outScale);
      auto& capped = adv_.capped[static_cast<std::size_t>(r)];
      capped.clear();
      for (c = 0; c < npts; ++c) {
        if (c + 4 <= npts && !lanes::any(lanes::load(sc + c) != 1.0)) {  // four at a time where all are 1
          c += 3;
          continue;
        }
        if (sc[c] != 1.0) capped.push_back({static_cast<std::int64_t>(c), sc[c]});
      }
    };

    // The conserved amounts of one fluid's owned cells of slab s (accumulators): m (mass, as it
    // is), m u and m (e + |u|^2 / 2) in place of u and e (each cell reads its own before it
    // writes them; the window holds them for the face values: lagWindow), m v (in the specific
    // volume, which nothing below reads), m e.
    auto conservedDim = [&]<int DIM>(int r, int s) {
      const int nd = DIM > 0 ? DIM : dim;
      MaterialState& m = st_.mat[r];
      double* a[kNumAcc];
      accumulators(m, a);
      const double *e = m.eint.data(), *v = m.lagSpvol().data();  // Lagrangian (ice_state.h)
      const auto u = core::components(m.vel);
      // One cell (T double) or four (T lanes::v4d, the same operations) from c on.
      auto cell = [&]<class T>(std::int64_t c) {
        auto ld = [&](const double* f) -> T {
          if constexpr (std::is_same_v<T, double>) return f[c];
          else return lanes::load(f + c);
        };
        auto st = [&](double* f, T x) {
          if constexpr (std::is_same_v<T, double>) f[c] = x;
          else lanes::store(f + c, x);
        };
        const T mass = ld(a[kMass]);
        T ke = T{} + 0.0;
        for (int d = 0; d < nd; ++d) {
          const T ud = ld(u[d]);
          st(a[kMomX + d], mass * ud);
          ke += ud * ud;
        }
        const T ec = ld(e);
        st(a[kEnergy], mass * (ec + 0.5 * ke));
        st(a[kVolume], mass * ld(v));
        st(a[kEint], mass * ec);
      };
      core::Box b = owned_;
      b.lo[dim - 1] = b.hi[dim - 1] = s;
      forRows(
          b, [&](std::int64_t c) { cell.template operator()<lanes::v4d>(c); },
          [&](std::int64_t c) { cell.template operator()<double>(c); }, [](int, int, std::int64_t) {});
    };
    auto conserved = [&](int r, int s) {
      if (dim == 2) conservedDim.template operator()<2>(r, s);
      else if (dim == 3) conservedDim.template operator()<3>(r, s);
      else conservedDim.template operator()<0>(r, s);
    };

    // The isentrope fits of the entropy-bounded face state (second order; first order takes the
    // donor's own state, which is on its isentrope). Only with the Riemann face pressure: the
    // average face pressure has no dissipation at shocks, every shock rings there (up to +65 %)
    // and the bound cannot make up for it; with it, Toro's test 2
    // with superbee and water against air with superbee stopped on a negative temperature
    // (docs/ice.md "The full sweep").
    const bool entropyBound = Second && riemannFacePressureOn();
    // One fluid's fits at a time (the passes below take the fluids one after the other), over
    // two slabs of stored cells only (rows in 2D, planes in 3D, along the last direction: the
    // flux passes sweep them in order, and a face reads the fits of the two cells beside it): the
    // fits of stored cell c at c - fitOffset, slabs s - 1 and s consecutive as in the stored box.
    // The fits are read only at faces between two cells the fluid fills alone (faceState): where
    // it fills none (every cell mixed), they are not made (fitsOn false).
    const int top = dim - 1;
    const std::int64_t slabStored = top == 0 ? 1 : (top == 1 ? sb.length(0) : std::int64_t(sb.length(0)) * sb.length(1));
    bool fitsOn = false;
    std::int64_t fitOffset = 0;
    auto fitIsentropes = [&](int r) {
      const MaterialState& m = st_.mat[r];
      fitsOn = false;
      if (!entropyBound) return;
      const double* th = m.theta.data();
      bool alone = false;
      std::size_t c = 0;
      for (; c + 4 <= npts && !alone; c += 4) alone = lanes::any(lanes::load(th + c) >= 1.0 - kPresentFraction);  // singleFluid
      for (; c < npts && !alone; ++c) alone = singleFluid(th[c]);
      fitsOn = alone;
      if (alone) {
        adv_.isenGamma.resize(static_cast<std::size_t>(2 * slabStored));
        adv_.isenPi.resize(static_cast<std::size_t>(2 * slabStored));
      }
    };
    // The Lagrangian velocity and energy of the fluid being advected over a window of W
    // consecutive stored slabs (AdvectionScratch::lagWindow; the state's arrays turn into the
    // conserved amounts slab by slab, conserved): what the flux passes read at the faces of slab s
    // lies in slabs s - 2 .. s + 1 (the donor's reconstruction; its isentrope fit and the
    // positivity blend's test of slab s - 1). lagU[d], lagE: the stored cell c's values at c
    // (pointers offset by the stored index of the window's first cell). W slabs, at least 4, about
    // kLagWindowCells cells (the window moves by W - 3 slabs at a time); in 1D all of them.
    constexpr std::int64_t kLagWindowCells = 16384;
    const int storedSlabs = sb.length(top);
    const int W =
        dim == 1 ? storedSlabs : static_cast<int>(std::min<std::int64_t>(storedSlabs, 4 + kLagWindowCells / slabStored));
    const std::size_t winArray = static_cast<std::size_t>(W * slabStored);
    adv_.lagWindow.resize(static_cast<std::size_t>(dim + 1) * winArray);
    int winLo = sb.lo[top], winEnd = sb.lo[top];  // the slabs held: winLo .. winEnd - 1
    const double* lagU[3] = {nullptr, nullptr, nullptr};
    const double* lagE = nullptr;
    auto lagPointers = [&] {
      const std::int64_t first = std::int64_t(winLo - sb.lo[top]) * slabStored;
      double* w = adv_.lagWindow.data();
      for (int d = 0; d < dim; ++d) lagU[d] = w + d * winArray - first;
      lagE = w + dim * winArray - first;
    };
    // Makes the window of fluid r hold slabs t - 3 .. t (those of the stored box), copying the
    // state's values of the slabs it did not hold yet; afresh (a new fluid) with restart.
    auto lagWindowTo = [&](int r, int t, bool restart) {
      const MaterialState& m = st_.mat[r];
      t = std::min(t, sb.hi[top]);
      if (restart) winLo = winEnd = sb.lo[top];
      const std::size_t S = static_cast<std::size_t>(slabStored);
      double* w = adv_.lagWindow.data();
      if (t >= winLo + W) {  // move: the last three slabs held to the front
        const int lo = std::max(winLo, t - 3);
        for (int q = 0; q <= dim; ++q) {
          double* a = w + q * winArray;
          std::copy(a + (lo - winLo) * S, a + (winEnd - winLo) * S, a);
        }
        winLo = lo;
      }
      for (; winEnd <= t; ++winEnd) {
        const std::size_t at = (winEnd - winLo) * S, from = (winEnd - sb.lo[top]) * S;
        for (int d = 0; d < dim; ++d) std::copy(m.vel.data(d) + from, m.vel.data(d) + from + S, w + d * winArray + at);
        std::copy(m.eint.data() + from, m.eint.data() + from + S, w + dim * winArray + at);
      }
      lagPointers();
    };
    // The Lagrangian velocity and energy of stored cell c of the fluid advected last, after its
    // pass 2: saved (lagKept: the owned cells the blend pass reads and the dropped traces), in
    // the window, or the state's at a ghost (never converted).
    const std::int64_t len0 = sb.length(0), len1 = sb.length(1);
    auto lagAt = [&](const MaterialState& m, std::int64_t c, double* u, double& e) {
      if (const AdvectionScratch::LagCell* k = lagSaved(c)) {
        for (int q = 0; q < dim; ++q) u[q] = k->u[q];
        e = k->e;
        return;
      }
      const int t = sb.lo[top] + static_cast<int>(c / slabStored);
      if (t >= winLo && t < winEnd) {
        for (int q = 0; q < dim; ++q) u[q] = lagU[q][c];
        e = lagE[c];
        return;
      }
      const int i = sb.lo[0] + static_cast<int>(c % len0), j = sb.lo[1] + static_cast<int>(c / len0 % len1),
                k = sb.lo[2] + static_cast<int>(c / (len0 * len1));
      if (owned_.contains(i, j, k)) throw std::logic_error("advection: a converted cell's Lagrangian values read");
      for (int q = 0; q < dim; ++q) u[q] = m.vel.data(q)[c];
      e = m.eint.data()[c];
    };
    // The window at slab s (stored slabs s - 1 and s) of fluid r, from the window at slab s - 1
    // (next) or afresh. Each cell's fit is its own: the values of a fit over the whole box.
    auto fitWindow = [&](int r, int s, bool next) {
      if (!fitsOn) return;
      const MaterialState& m = st_.mat[r];
      const std::size_t S = static_cast<std::size_t>(slabStored);
      double *g = adv_.isenGamma.data(), *pi = adv_.isenPi.data();
      const double *v = m.lagSpvol().data(), *e = lagE;  // the energy from the window (lagWindowTo)
      const std::int64_t lo = std::int64_t(s - 1 - sb.lo[top]) * slabStored;  // slab s - 1's first stored cell
      if (next) {
        std::copy(g + S, g + 2 * S, g);
        std::copy(pi + S, pi + 2 * S, pi);
      } else {
        isentropeFits(*m.eos, S, v + lo, e + lo, adv_, g, pi);
      }
      isentropeFits(*m.eos, S, v + lo + slabStored, e + lo + slabStored, adv_, g + S, pi + S);
      fitOffset = lo;
    };
    // The outflow scale of fluid r over the same window of two slabs (its stored cell c at
    // c - scaleOffset), from its capped cells (the rest 1), as the flux passes reach slab s.
    std::int64_t scaleOffset = 0;
    adv_.scaleWindow.resize(static_cast<std::size_t>(2 * slabStored));
    auto scaleWindow = [&](int r, int s, bool next) {
      const std::size_t S = static_cast<std::size_t>(slabStored);
      double* w = adv_.scaleWindow.data();
      const std::int64_t lo = std::int64_t(s - 1 - sb.lo[top]) * slabStored;  // slab s - 1's first stored cell
      const auto& capped = adv_.capped[static_cast<std::size_t>(r)];  // in increasing cell order
      auto slabFrom = [&](double* to, std::int64_t c0) {  // the stored slab from cell c0
        std::fill(to, to + S, 1.0);
        auto q = std::lower_bound(capped.begin(), capped.end(), c0, [](const auto& e, std::int64_t c) { return e.first < c; });
        for (; q != capped.end() && q->first < c0 + slabStored; ++q) to[q->first - c0] = q->second;
      };
      if (next) std::copy(w + S, w + 2 * S, w);
      else slabFrom(w, lo);
      slabFrom(w + S, lo + slabStored);
      scaleOffset = lo;
    };

    // The face values of one fluid at one face: velocity (the mesh's dimension of components),
    // specific volume, internal energy (the entropy-bounded pair at second order, above).
    struct FaceState {
      double u[3], v, e;
    };
    // DIM > 0: the mesh's dimension fixed at compile time.
    auto faceStateDim = [&]<int DIM>(const FaceValue<Second, L>& face, std::int64_t cL, std::int64_t cR,
                                     const double* const* u, const double* vL, const double* eL, const double* th,
                                     const double* isG, const double* isP) {
      const int nd = DIM > 0 ? DIM : dim;
      FaceState f;
      for (int q = 0; q < nd; ++q) f.u[q] = face(u[q]);
      f.v = face(vL);
      f.e = face(eL);
      if constexpr (Second) {
        const std::int64_t O = face.D == cL ? cR : cL;
        if (entropyBound && singleFluid(th[face.D]) && singleFluid(th[O]))
          f.e = entropyBounded(f.e, f.v, face.D, O, eL, vL, isG, isP, fitOffset);
      } else {
        (void)cR, (void)th, (void)isG, (void)isP;
      }
      return f;
    };
    auto faceState = [&](const FaceValue<Second, L>& face, std::int64_t cL, std::int64_t cR, const double* const* u,
                         const double* vL, const double* eL, const double* th, const double* isG, const double* isP) {
      return faceStateDim.template operator()<0>(face, cL, cR, u, vL, eL, th, isG, isP);
    };

    // The pointers the flux passes (pass 2 and the blend's) read and write for one fluid at the
    // faces normal to one direction.
    struct FluxPtrs {
      core::Box fb;  // the faces normal to the direction that bound the owned cells
      std::int64_t sd;
      double dx;
      const double *Fm, *sc, *uf;                    // mass flux, outflow scale (scaleWindow), face velocity
      const double *u[3], *eL, *vL, *isG, *isP, *th;  // the face values' sources
      double* a[kNumAcc];
    };
    auto fluxPtrs = [&](int d, int r) {
      MaterialState& m = st_.mat[r];
      AdvectionScratch::Material& am = adv_.mat[static_cast<std::size_t>(r)];
      const auto uL = core::components(m.vel);  // the Lagrangian values (ice_state.h)
      FluxPtrs P{owned_.faces(d), strides[d], mesh_.dx(d), am.massFlux[d].data(), adv_.scaleWindow.data(),
                 m.velFace[d].data(), {uL[0], uL[1], uL[2]}, m.eint.data(),
                 m.lagSpvol().data(), Second ? adv_.isenGamma.data() : nullptr, Second ? adv_.isenPi.data() : nullptr,
                 m.theta.data(), {}};
      accumulators(m, P.a);
      return P;
    };

    // Pass 2: every flux (the mass flux, scaled for positivity, times the face values) applied to
    // the owned cells on both sides; each owned donor's sums for the positivity blend. One fluid
    // at a time, sweeping the slabs of cells along the last direction (top: rows in 2D, planes in
    // 3D) with the faces inside a slab before its low faces in top; every cell still receives its
    // faces' terms in the order x low, x high, y low, y high, z low, z high (the order of a sweep
    // per direction), and a slab's sums are complete once the faces above it are done: only two
    // slabs of sums are kept.
    auto slab = [&](int s) {  // the owned cells with index s in top
      core::Box b = owned_;
      b.lo[top] = b.hi[top] = s;
      return b;
    };
    std::int64_t slabSize = 1;
    for (int q = 0; q < top; ++q) slabSize *= owned_.length(q);
    adv_.remainder.resize(static_cast<std::size_t>(2 * slabSize * kRemSums));
    adv_.blends.clear();
    double* rem = adv_.remainder.data();
    // An owned cell (i, j, k)'s sums: R = rem + remRow(j, k) + remCol(i), sum q at R[q rs] (one
    // array of the two slabs per sum: a row's cells are consecutive in each, for the lanes).
    const std::int64_t rs = 2 * slabSize;
    const std::int64_t nx = owned_.length(0);
    auto remRow = [&](int j, int k) -> std::int64_t {
      if (top == 0) return 0;
      const int t = top == 1 ? j : k;
      return (t & 1) * slabSize + (top == 2 ? nx * (j - owned_.lo[1]) : 0);
    };
    auto remCol = [&](int i) -> std::int64_t { return top == 0 ? (i & 1) : i - owned_.lo[0]; };
    // Calls f4(c, R) for four consecutive owned cells of slab s along x (c the first's stored
    // index, R its sums: the lanes) and f1(c, R) for one, every cell once, in forEach's order.
    auto forSlabLanes = [&](int s, auto&& f4, auto&& f1) {
      const core::Box b = slab(s);
      for (int k = b.lo[2]; k <= b.hi[2]; ++k)
        for (int j = b.lo[1]; j <= b.hi[1]; ++j) {
          double* R = rem + remRow(j, k);
          const std::int64_t c0 = sb.index(b.lo[0], j, k);
          if (top == 0) {
            for (int i = b.lo[0]; i <= b.hi[0]; ++i) f1(c0 + (i - b.lo[0]), R + remCol(i));
          } else {  // remCol(i) = i - lo
            double* Ri = R + remCol(b.lo[0]);
            int i = b.lo[0];
            for (; i + 3 <= b.hi[0]; i += 4, Ri += 4) f4(c0 + (i - b.lo[0]), Ri);
            for (; i <= b.hi[0]; ++i, ++Ri) f1(c0 + (i - b.lo[0]), Ri);
          }
        }
    };
    // Pass 2 over the faces normal to d from (ilo, j, k) to (ihi, j, k). Inner: every one of these
    // faces has owned cells on both sides (the tests below are then known at compile time). DIM:
    // the mesh's dimension fixed at compile time (the loops over components unroll).
    auto pass2Faces = [&]<bool Inner, int DIM>(const FluxPtrs& P, int d, int j, int k, int ilo, int ihi) {
      static_assert(DIM > 0);
      constexpr int tp = DIM - 1;  // top
      auto col = [&](int ii) -> std::int64_t { return tp == 0 ? (ii & 1) : ii - owned_.lo[0]; };
      const int lo = owned_.lo[d], hi = owned_.hi[d];
      std::int64_t fi = P.fb.index(ilo, j, k), cR = sb.index(ilo, j, k);
      // The sums' rows of the cells on the high and the low side (owned rows only are read).
      const std::int64_t rowR = remRow(j, k), rowL = d == 0 ? rowR : remRow(j - (d == 1), k - (d == 2));
      int i = ilo;
      if constexpr (Inner && DIM >= 2) {
        // Four faces at once (the lanes, lanes.h): the loop below's operations, a face with F = 0
        // a select of what it leaves. Along x lane l's high cell is lane l + 1's low cell: each
        // cell's terms in the loop's order, its low face's (+=) before its high face's (-=).
        using lanes::v4d, lanes::v4m, lanes::load, lanes::store, lanes::sel;
        const v4m keep3 = {-1, -1, -1, 0};
        auto next = [](auto v) { return __builtin_shufflevector(v, v, 1, 2, 3, 3); };  // lane l + 1's
        for (; i + 3 <= ihi; i += 4, fi += 4, cR += 4) {
          const v4d F = load(P.Fm + fi);
          const v4m nz = F != 0;
          if (!lanes::any(nz)) continue;
          const std::int64_t cL = cR - P.sd;
          const v4d lam = sel(F > 0, load(P.sc + (cL - scaleOffset)), load(P.sc + (cR - scaleOffset)));
          const FaceValueLanes face(rc, load(P.uf + fi), cL, P.sd, dt, P.dx);
          v4d fu[DIM];
          for (int q = 0; q < DIM; ++q) fu[q] = face(P.u[q]);
          const v4d fv = face(P.vL);
          v4d fe = face(P.eL);
          if constexpr (Second) {  // faceStateDim's entropy bound, lane by lane where it applies
            if (entropyBound) {
              const v4d tD = face.donor(P.th), tO = sel(face.up, load(P.th + cR), load(P.th + cL));
              const v4m b = nz & (tD >= 1.0 - kPresentFraction) & (tO >= 1.0 - kPresentFraction);  // singleFluid
              if (lanes::any(b))
                for (int l = 0; l < 4; ++l)
                  if (b[l]) {
                    const std::int64_t D = face.up[l] ? cL + l : cR + l, O = face.up[l] ? cR + l : cL + l;
                    fe[l] = entropyBounded(fe[l], fv[l], D, O, P.eL, P.vL, P.isG, P.isP, fitOffset);
                  }
            }
          }
          auto apply = [&](double* acc, v4d flux) { applyLanes(acc, lam * flux, nz, cL, cR, d == 0); };
          v4d ke = lanes::splat(0.0);
          for (int q = 0; q < DIM; ++q) {
            apply(P.a[kMomX + q], F * fu[q]);
            ke += fu[q] * fu[q];
          }
          apply(P.a[kMass], F);
          apply(P.a[kEnergy], F * (fe + 0.5 * ke));
          apply(P.a[kVolume], F * fv);
          apply(P.a[kEint], F * fe);
          // The donors' sums: lanes with the donor cL (dL) or cR (dR); nt terms t added (or
          // subtracted) to sum q in order.
          const v4d w = lam * lanes::abs(F);
          const v4m dL = nz & face.up, dR = nz & ~face.up;
          const std::int64_t sR = rowR + col(i), sL = rowL + col(i - (d == 0));
          auto sums = [&](int q, const v4d* t, int nt, bool sub) {
            double* Rq = rem + q * rs;
            auto add = [&](v4d a, v4d x) { return sub ? a - x : a + x; };
            if (d == 0) {  // sL = sR - 1
              v4d a = load(Rq + sR);
              for (int n = 0; n < nt; ++n) a = sel(dR, add(a, t[n]), a);
              const v4m mL = next(dL) & keep3;
              for (int n = 0; n < nt; ++n) a = sel(mL, add(a, next(t[n])), a);
              store(Rq + sR, a);
              if (dL[0])
                for (int n = 0; n < nt; ++n) Rq[sL] = sub ? Rq[sL] - t[n][0] : Rq[sL] + t[n][0];
            } else {
              v4d aR = load(Rq + sR), aL = load(Rq + sL);
              for (int n = 0; n < nt; ++n) aR = sel(dR, add(aR, t[n]), aR), aL = sel(dL, add(aL, t[n]), aL);
              store(Rq + sR, aR);
              store(Rq + sL, aL);
            }
          };
          sums(kRemMass, &w, 1, true);
          const v4d tE = w * (fe - face.donor(P.eL));
          sums(kRemE, &tE, 1, false);
          v4d tU2[DIM];
          for (int q = 0; q < DIM; ++q) {
            const v4d du = fu[q] - face.donor(P.u[q]);
            tU2[q] = w * du * du;
            const v4d tU = w * du;
            sums(kRemUx + q, &tU, 1, false);
          }
          sums(kRemU2, tU2, DIM, false);
          const v4d tV = w * (fv - face.donor(P.vL));
          sums(kRemV, &tV, 1, false);
        }
      }
      for (; i <= ihi; ++i, ++fi, ++cR) {
        const double F = P.Fm[fi];
        if (F == 0) continue;
        const std::int64_t cL = cR - P.sd;
        const int id = d == 0 ? i : (d == 1 ? j : k);  // the face's index in d
        const bool ownL = Inner || id > lo, ownR = Inner || id <= hi;
        const double lam = F > 0 ? P.sc[cL - scaleOffset] : P.sc[cR - scaleOffset];
        const FaceValue face(rc, P.uf[fi], cL, P.sd, dt, P.dx);
        const FaceState f = faceStateDim.template operator()<DIM>(face, cL, cR, P.u, P.vL, P.eL, P.th, P.isG, P.isP);
        auto apply = [&](double* acc, double flux) {
          const double v = lam * flux;
          if (ownL) acc[cL] -= v;
          if (ownR) acc[cR] += v;
        };
        double ke = 0;
        for (int q = 0; q < DIM; ++q) {
          apply(P.a[kMomX + q], F * f.u[q]);
          ke += f.u[q] * f.u[q];
        }
        apply(P.a[kMass], F);
        apply(P.a[kEnergy], F * (f.e + 0.5 * ke));
        apply(P.a[kVolume], F * f.v);
        apply(P.a[kEint], F * f.e);
        const std::int64_t D = face.D;
        if (D == cL ? ownL : ownR) {
          double* R = rem + (D == cL ? rowL + col(i - (d == 0)) : rowR + col(i));
          const double w = lam * std::abs(F);
          R[kRemMass * rs] -= w;
          R[kRemE * rs] += w * (f.e - P.eL[D]);
          for (int q = 0; q < DIM; ++q) {  // beyond dim the face velocity is the donor's
            const double du = f.u[q] - P.u[q][D];
            R[kRemU2 * rs] += w * du * du;
            R[(kRemUx + q) * rs] += w * du;
          }
          R[kRemV * rs] += w * (f.v - P.vL[D]);
        }
      }
    };
    // The same faces in the same order, the inner ones (owned cells on both sides) apart.
    auto pass2RowDim = [&]<int DIM>(const FluxPtrs& P, int d, int j, int k, int ilo, int ihi) {
      if (d == 0) {
        const int a = std::max(ilo, owned_.lo[0] + 1), b = std::min(ihi, owned_.hi[0]);
        if (a > b) return pass2Faces.template operator()<false, DIM>(P, d, j, k, ilo, ihi);
        if (ilo < a) pass2Faces.template operator()<false, DIM>(P, d, j, k, ilo, a - 1);
        pass2Faces.template operator()<true, DIM>(P, d, j, k, a, b);
        if (b < ihi) pass2Faces.template operator()<false, DIM>(P, d, j, k, b + 1, ihi);
        return;
      }
      const int id = d == 1 ? j : k;
      if (id > owned_.lo[d] && id <= owned_.hi[d]) pass2Faces.template operator()<true, DIM>(P, d, j, k, ilo, ihi);
      else pass2Faces.template operator()<false, DIM>(P, d, j, k, ilo, ihi);
    };
    auto pass2Row = [&](const FluxPtrs& P, int d, int j, int k, int ilo, int ihi) {
      if (dim == 1) pass2RowDim.template operator()<1>(P, d, j, k, ilo, ihi);
      else if (dim == 2) pass2RowDim.template operator()<2>(P, d, j, k, ilo, ihi);
      else pass2RowDim.template operator()<3>(P, d, j, k, ilo, ihi);
    };
    // More than one fluid: every fluid's outflow scale before the first is advected (the fluid
    // mass after advection, fluidMassRow, reads those of the fluids after the one converted); with
    // one fluid where it is advected.
    if (!oneFluid)
      for (int r : fluids) outflowScale(r);

    // One fluid after the other: its outflow scale, isentrope fits, pass 2 slab by slab (each
    // slab's Lagrangian values into the window, its conserved amounts, its faces) with its blend
    // sums, the blend pass, and its conversion back to primitive values.
    for (int r = 0; r < nm; ++r) {
      MaterialState& m = st_.mat[r];
      if (m.external) continue;
      if (oneFluid) outflowScale(r);
      fitIsentropes(r);
      FluxPtrs P[3];
      for (int d = 0; d < dim; ++d) P[d] = fluxPtrs(d, r);
      // The face values' velocity and energy from the window (lagWindowTo; its pointers move with it).
      auto lagTo = [&](int t, bool restart) {
        lagWindowTo(r, t, restart);
        for (int d = 0; d < dim; ++d) {
          for (int q = 0; q < dim; ++q) P[d].u[q] = lagU[q];
          P[d].eL = lagE;
        }
      };
      const double* ms = m.mass.data();
      const double* vL = m.lagSpvol().data();
      const bool cold = m.eos->hasColdEnergy();
      adv_.blends.clear();
      adv_.lagKept.clear();
      // Saves the Lagrangian values of stored cell c (in the window) for after its slab leaves it.
      auto keep = [&](std::int64_t c) {
        AdvectionScratch::LagCell k{c, {0, 0, 0}, lagE[c]};
        for (int q = 0; q < dim; ++q) k.u[q] = lagU[q][c];
        adv_.lagKept.push_back(k);
      };
      // Slab t's owned cells that the conversion drops as traces: absent (below kTraceMass) or
      // below kNegligibleMassFraction of the cell's fluid mass after advection (with one fluid its
      // own), decided here, once pass 2 has completed the slab's mass (the blend moves none), as
      // dropCells. Those and the cells beside a ghost (a ghost donor's blend comes from its owner
      // after pass 2) keep their Lagrangian values where the window moves on (lagAt).
      adv_.dropCells.clear();
      const bool moves = W < storedSlabs;
      auto dropCandidates = [&](int t) {
        const core::Box b = slab(t);
        for (int k = b.lo[2]; k <= b.hi[2]; ++k)
          for (int j = b.lo[1]; j <= b.hi[1]; ++j) {
            const std::int64_t c0 = sb.index(b.lo[0], j, k);
            const int n = b.length(0);
            const bool edge = (dim > 1 && (j == owned_.lo[1] || j == owned_.hi[1])) ||
                              (dim > 2 && (k == owned_.lo[2] || k == owned_.hi[2]));
            const double* fm = ms + c0;  // one fluid: its own mass
            if (!oneFluid) {
              fluidMassRow(r, j, k, b.lo[0], b.hi[0]);
              fm = adv_.fluidMassRow.data();
            }
            // The row's first and last owned cells are beside a ghost (in 1D the slab is one cell).
            const bool sides = moves && (b.lo[0] == owned_.lo[0] || b.hi[0] == owned_.hi[0]);
            if (sides) keep(c0);
            auto one = [&](int i) {
              const std::int64_t c = c0 + i;
              const double mass = ms[c];
              const bool drop = !(mass > kTraceMass) || mass < kNegligibleMassFraction * fm[i];
              if (drop) adv_.dropCells.push_back(c);
              if (moves && (drop || edge)) keep(c);
            };
            int i = 0;
            if (!edge)
              for (; i + 4 <= n; i += 4) {  // four at a time (the lanes) where none is dropped
                using lanes::v4d, lanes::load;
                const v4d mass = load(ms + c0 + i);
                if (lanes::any(~(mass > kTraceMass) | (mass < kNegligibleMassFraction * load(fm + i))))
                  for (int l = 0; l < 4; ++l) one(i + l);
              }
            for (; i < n; ++i) one(i);
            if (sides) keep(c0 + n - 1);
          }
      };
      // The faces of slab s (lo[top] .. hi[top] + 1) in the flux passes' order: with s <= hi[top]
      // those inside it (along x; in 3D x and y row by row), then its low faces in top (the
      // slabs in order give every cell its faces' terms in the order x low, x high, y low, y
      // high, z low, z high). row(d, j, k, ilo, ihi): the faces normal to d from (ilo, j, k) to (ihi, j, k).
      auto slabFaces = [&](int s, auto&& row) {
        const int ilo = owned_.lo[0], ihi = owned_.hi[0];
        if (s <= owned_.hi[top]) {
          if (dim == 2) row(0, s, owned_.lo[2], ilo, ihi + 1);
          if (dim == 3) {
            for (int j = owned_.lo[1]; j <= owned_.hi[1]; ++j) {
              row(0, j, s, ilo, ihi + 1);
              row(1, j, s, ilo, ihi);
            }
            row(1, owned_.hi[1] + 1, s, ilo, ihi);
          }
        }
        if (dim == 1) row(0, owned_.lo[1], owned_.lo[2], s, s);
        if (dim == 2) row(1, s, owned_.lo[2], ilo, ihi);
        if (dim == 3)
          for (int j = owned_.lo[1]; j <= owned_.hi[1]; ++j) row(2, j, s, ilo, ihi);
      };
      auto row = [&](int d, int j, int k, int ilo, int ihi) { pass2Row(P[d], d, j, k, ilo, ihi); };
      for (int s = owned_.lo[top]; s <= owned_.hi[top] + 1; ++s) {
        lagTo(s + 1, s == owned_.lo[top]);
        fitWindow(r, s, s != owned_.lo[top]);
        scaleWindow(r, s, s != owned_.lo[top]);
        if (s <= owned_.hi[top]) {
          conserved(r, s);
          auto init = [&](std::int64_t c, double* R) {  // the mass before advection, no outflow yet
            R[kRemMass * rs] = ms[c];
            for (int q = 1; q < kRemSums; ++q) R[q * rs] = 0.0;
          };
          forSlabLanes(
              s,
              [&](std::int64_t c, double* R) {
                lanes::store(R + kRemMass * rs, lanes::load(ms + c));
                for (int q = 1; q < kRemSums; ++q) lanes::store(R + q * rs, lanes::splat(0.0));
              },
              init);
        }
        slabFaces(s, row);
        if (s == owned_.lo[top]) continue;
        // Slab s - 1 is complete: the positivity blend of its donors (positivityBlend).
        const double* eL = lagE;
        auto blend1 = [&](std::int64_t c, const double* R) {
          const double ec = cold && vL[c] > 0 ? m.eos->coldEnergy(1.0 / vL[c]) : 0.0;
          const double b = positivityBlend(R, rs, eL[c] - ec, vL[c]);
          if (b < 1.0) {
            adv_.blends.push_back({c, b});
            ++positivityBlends_;
            keep(c);  // the blend pass reads the donor's values and its face neighbours'
            for (int d = 0; d < dim; ++d) keep(c - strides[d]), keep(c + strides[d]);
          }
        };
        // Four donors at once: blend1 only where one of positivityBlend's tests can lower b (the
        // same operations; b is 1 exactly where none does). Without a cold energy (ec = 0).
        auto blend4 = [&](std::int64_t c, const double* R) {
          using lanes::v4d, lanes::v4m, lanes::load;
          if (!cold) {
            auto sum = [&](int q) { return load(R + q * rs); };
            const v4d mr = sum(kRemMass), A = sum(kRemE), vD = load(vL + c);
            const v4d C = (1.0 - kMinRemainderShare) * mr * (load(eL + c) - 0.0);
            const v4d P2 = sum(kRemUx) * sum(kRemUx) + sum(kRemUy) * sum(kRemUy) + sum(kRemUz) * sum(kRemUz);
            const v4d Cv = (1.0 - kMinRemainderShare) * mr * vD;
            const v4m lower = ((C > 0) & ((A + 0.5 * sum(kRemU2) - C) * mr + 0.5 * P2 > 0)) | ((C > 0) & (-A > C)) |
                              ((Cv > 0) & (lanes::abs(sum(kRemV)) > Cv));
            if (!lanes::any((mr > 0) & lower)) return;
          }
          for (int l = 0; l < 4; ++l) blend1(c + l, R + l);
        };
        forSlabLanes(s - 1, blend4, blend1);
        dropCandidates(s - 1);
      }
      // In increasing cell order as dropCandidates kept them, unless a blend kept its neighbours.
      if (!adv_.blends.empty())
        std::sort(adv_.lagKept.begin(), adv_.lagKept.end(), [](const auto& a, const auto& b) { return a.cell < b.cell; });
      adv_.lagKept.erase(std::unique(adv_.lagKept.begin(), adv_.lagKept.end(),
                                     [](const auto& a, const auto& b) { return a.cell == b.cell; }),
                         adv_.lagKept.end());

      // At the outgoing faces of the few donors with a blend below 1, the difference between the
      // blended fluxes and those applied above (the same on both sides of the face: conservative).
      if (comm_.max(adv_.blends.empty() ? 0.0 : 1.0) > 0) {
        core::Field& blend = adv_.blend;
        if (blend.ncomp() != 1) blend = core::Field("positivity_blend", core::Centering::Cell, sb, 1, kGhost);
        blend.fill(1.0);
        for (const AdvectionScratch::Blend& e : adv_.blends) blend.data()[e.cell] = e.b;
        ghosts_->fill(blend);
        const double* bl = blend.data();
        const double nan = std::numeric_limits<double>::quiet_NaN();
        fitOffset = 0;  // the fits below are the face's own (local cells)
        // Slab by slab as pass 2: each cell takes its faces' terms in the order of a sweep per
        // direction. The face values from the four cells cL - sd, cL, cR, cR + sd (local 0 .. 3),
        // those of the donor's reconstruction (D - sd, D, D + sd) gathered, with their fits.
        auto face = [&](int d, int i, int j, int k) {
          const FluxPtrs& Q = P[d];
          const std::int64_t fi = Q.fb.index(i, j, k);
          const double F = Q.Fm[fi];
          if (F == 0) return;
          const std::int64_t cR = sb.index(i, j, k), cL = cR - Q.sd;
          const std::int64_t D = F > 0 ? cL : cR;
          const double b = bl[D];
          if (!(b < 1.0)) return;
          const int id = d == 0 ? i : (d == 1 ? j : k);
          const bool ownL = id > owned_.lo[d], ownR = id <= owned_.hi[d];
          const double lam = Q.sc[D - scaleOffset];
          double lu[3][4], le[4], lv[4], lth[4], lg[4] = {nan, nan, nan, nan}, lp[4] = {0, 0, 0, 0};
          const int lD = D == cL ? 1 : 2;  // the donor's local index
          for (int n = 0; n < 4; ++n) {
            const std::int64_t c = cL + (n - 1) * Q.sd;
            double u[3] = {nan, nan, nan}, e = nan;
            if (n >= lD - 1 && n <= lD + 1) lagAt(m, c, u, e);
            for (int q = 0; q < 3; ++q) lu[q][n] = u[q];
            le[n] = e;
            lv[n] = Q.vL[c];
            lth[n] = Q.th[c];
          }
          if (Second && entropyBound && singleFluid(lth[1]) && singleFluid(lth[2]))
            isentropeFits(*m.eos, 2, lv + 1, le + 1, adv_, lg + 1, lp + 1);
          const double* lup[3] = {lu[0], lu[1], lu[2]};
          const FaceValue fv(rc, Q.uf[fi], 1, 1, dt, Q.dx);
          const FaceState f = faceState(fv, 1, 2, lup, lv, le, lth, lg, lp);
          double fl[kNumAcc];
          double ke1 = 0, keB = 0;
          for (int q = 0; q < dim; ++q) {
            const double ub = lu[q][lD] + b * (f.u[q] - lu[q][lD]);
            fl[kMomX + q] = F * (ub - f.u[q]);
            ke1 += f.u[q] * f.u[q];
            keB += ub * ub;
          }
          const double eb = le[lD] + b * (f.e - le[lD]), vb = lv[lD] + b * (f.v - lv[lD]);
          fl[kMass] = 0.0;
          fl[kEnergy] = F * ((eb + 0.5 * keB) - (f.e + 0.5 * ke1));
          fl[kVolume] = F * (vb - f.v);
          fl[kEint] = F * (eb - f.e);
          for (int q = 0; q < kNumAcc; ++q) {
            if (Q.a[q] == nullptr) continue;
            const double v = lam * fl[q];
            if (ownL) Q.a[q][cL] -= v;
            if (ownR) Q.a[q][cR] += v;
          }
        };
        for (int s = owned_.lo[top]; s <= owned_.hi[top] + 1; ++s) {
          scaleWindow(r, s, s != owned_.lo[top]);
          slabFaces(s, [&](int d, int j, int k, int ilo, int ihi) {
            for (int i = ilo; i <= ihi; ++i) face(d, i, j, k);
          });
        }
      }
      convert(r, lagAt);
      // The velocity's ghosts as they were before the Lagrangian values' fill above (the state's
      // at the step's equilibrium), as when the Lagrangian values were copies: a coupled run's
      // stable step reads them (the shock viscosity's du) before the next equilibrium fills them.
      if (q1_ > 0 || q2_ > 0)
        forEach(sb, [&](int i, int j, int k) {
          if (owned_.contains(i, j, k)) return;
          for (int d = 0; d < dim; ++d) m.vel(i, j, k, d) = m.velStart(i, j, k, d);
        });
    }
  };
  switch (secondOrder_ ? static_cast<Limiter>(limiter_) : Limiter::Minmod) {
    case Limiter::Minmod:
      if (secondOrder_) passes(Recon<true, Limiter::Minmod>{});
      else passes(Recon<false, Limiter::Minmod>{});
      break;
    case Limiter::VanLeer: passes(Recon<true, Limiter::VanLeer>{}); break;
    case Limiter::Superbee: passes(Recon<true, Limiter::Superbee>{}); break;
  }
  audit_.endStep(comm_);
  t_ += dt;
  ++nsteps_;
}

}  // namespace mpmice::ice
