// IceSolver phases 2 and 5 (and the units computeVolumeFluxes, explicitPressureIncrement): the equilibrium pressure of each cell and the explicit pressure
// increment dp = -dt div(sum_r theta_r u_f,r) / sum_r theta_r kappa_r (the paper's Eq. 11).
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <stdexcept>
#include <vector>

#include "ice/face/solid_faces.h"
#include "ice/ice_constants.h"
#include "ice/solver/health_check.h"
#include "ice/solver/ice_solver.h"
#include "ice/state/phase_units.h"

namespace mpmice::ice {

using core::forEach;

void IceSolver::computeEquilibriumPressure() {
  semi_.mobilityFresh = false;
  const int nm = numMaterials();
  const double V = mesh_.cellVolume();
  // External (solid) materials enter with the volume their particles occupy, m_e v_e (v_e as
  // supplied), and stay compressible about it through their EOS. The node-to-cell average smears
  // a solid's mass, so m_e v_e can exceed the cell near its surface; the solids' mass is then
  // clipped to what fits (kMaxSolidFraction of the cell), so the smearing never turns into
  // compression. In a cell the solids fill, the trace of fluid left makes the pressure the
  // solid's own, continuously with the mixed cells around it.
  std::vector<double> clip(anyExternal_ ? ownedCells_.size() : 0, 1.0);
  if (anyExternal_) {
    ownedCells_.forEach([&](std::size_t a, std::int64_t c) {
      double vext = 0;
      for (const MaterialState& m : st_.mat)
        if (m.external) vext += m.mass.data()[c] * m.spvol.data()[c];
      if (vext > kMaxSolidFraction * V) clip[a] = kMaxSolidFraction * V / vext;
    });
  }
  // Traces (ice.trace_mass_fraction, docs/ice.md "Traces") without an admissible state at their
  // energy (a gas at e <= 0: advection's round-off in masses of 1e-60 kg) take the temperature of
  // the cell's heaviest fluid, which pays for the change (the total energy is unchanged).
  if (const double Y = equil_->traceMassFraction(); Y > 0 && nm > 1) {
    std::vector<std::int64_t> tc;
    std::vector<double> te, tf;
    for (MaterialState& m : st_.mat) {
      if (m.external) continue;
      tc.clear();
      te.clear();
      ownedCells_.forEach([&](std::size_t, std::int64_t c) {
        const double mr = m.mass.data()[c];
        if (!(mr > 0)) return;
        // The cell's fluid mass (summed where it is read: the loop changes energies only).
        double mf = 0;
        for (const MaterialState& s : st_.mat)
          if (!s.external) mf += s.mass.data()[c];
        if (mr < Y * mf) tc.push_back(c), te.push_back(m.eint.data()[c]);
      });
      tf.resize(tc.size());
      m.eos->pressureFloor(tc.size(), te.data(), tf.data());
      for (std::size_t a = 0; a < tc.size(); ++a) {
        if (tf[a] < std::numeric_limits<double>::infinity()) continue;  // admissible
        const std::int64_t c = tc[a];
        MaterialState* dom = nullptr;
        for (MaterialState& s : st_.mat)
          if (!s.external && (!dom || s.mass.data()[c] > dom->mass.data()[c])) dom = &s;
        const double vd = dom->spvol.data()[c], T = dom->eos->temperature(1.0 / vd, dom->eint.data()[c]);
        if (!(T > 0) || !(vd > 0)) continue;  // the health check names a broken heaviest fluid
        const double vt = m.spvol.data()[c];
        const double e1 = m.eos->energyFromTemperature(vt > 0 && std::isfinite(vt) ? 1.0 / vt : 1.0 / vd, T);
        dom->eint.data()[c] -= m.mass.data()[c] * (e1 - m.eint.data()[c]) / dom->mass.data()[c];
        m.eint.data()[c] = e1;
      }
    }
  }
  // Coupled runs: each fluid's temperature as the step found it, from which the embedded-fluid
  // rule measures its change over the whole cycle (trace_temperature.cpp), in the cells it reads (a
  // solid has mass there); NaN elsewhere and where the fluid has none.
  if (anyExternal_) {
    std::vector<char> solid(ownedCells_.size(), 0);
    for (const MaterialState& m : st_.mat)
      if (m.external)
        ownedCells_.forEach([&](std::size_t a, std::int64_t c) { solid[a] |= m.mass.data()[c] > 0; });
    for (MaterialState& m : st_.mat) {
      if (m.external) continue;
      if (m.tempCycle.npts() == 0) m.tempCycle = m.eint;
      double* T = m.tempCycle.data();
      const double *ms = m.mass.data(), *sv = m.spvol.data(), *es = m.eint.data();
      ownedCells_.forEach([&](std::size_t a, std::int64_t c) {
        T[c] = solid[a] && ms[c] > 0 && sv[c] > 0 && std::isfinite(sv[c]) ? m.eos->temperature(1.0 / sv[c], es[c])
                                                                          : std::numeric_limits<double>::quiet_NaN();
      });
    }
  }
  std::vector<const double*> rho, e;
  std::vector<double*> rhoMicro;
  for (MaterialState& m : st_.mat) {  // theta holds m/V and spvol the micro density meanwhile
    double* th = m.theta.data();
    const double* ms = m.mass.data();
    ownedCells_.forEach([&](std::size_t a, std::int64_t c) { th[c] = ms[c] / V * (m.external ? clip[a] : 1.0); });
    rho.push_back(th);
    e.push_back(m.eint.data());
    rhoMicro.push_back(m.spvol.data());
  }
  // spvol holds each material's carried specific volume on entry (the trace rule reads it first).
  const std::vector<const double*> carried(rhoMicro.begin(), rhoMicro.end());
  // ice.equilibrium: with_work keeps the carried volumes, from which each fluid's work is measured.
  std::vector<std::vector<double>> carriedCopy;
  if (equilibriumWork_ && nm > 1)
    for (const MaterialState& m : st_.mat) {
      carriedCopy.emplace_back(ownedCells_.size());
      ownedCells_.forEach([&](std::size_t a, std::int64_t c) { carriedCopy.back()[a] = m.spvol.data()[c]; });
    }
  auto failures = equil_->solve(ownedCells_, rho, e, st_.press.data(), rhoMicro, pressureIterationsOut(), &carried);
  mostPressureIterations_ = equil_->lastMostIterations();
  reportEquilibriumFailures(failures);
  std::vector<std::pair<int, std::int64_t>> held = equil_->heldTraces(), cavitated = equil_->cavitated();
  if (!carriedCopy.empty()) {
    failures = equilibrateWithWork(rho, rhoMicro, carriedCopy, held, cavitated);
    reportEquilibriumFailures(failures);
  }
  finishEquilibrium(held, cavitated);
}

void IceSolver::reportEquilibriumFailures(const std::vector<EquilibriumFailure>& failures) {
  const int nm = numMaterials();
  const double V = mesh_.cellVolume();
  const int anyFail = comm_.max(failures.empty() ? 0 : 1);
  if (anyFail) {
    std::ostringstream os;
    os.precision(10);
    if (failures.empty()) {
      os << "ice: the equilibrium pressure failed on another rank at t = " << t_;
    } else {
      const EquilibriumFailure& f = failures.front();
      const core::Box& sb = st_.press.box();
      const std::int64_t nx = sb.length(0), ny = sb.length(1);
      const int i = static_cast<int>(f.cell % nx) + sb.lo[0];
      const int j = static_cast<int>((f.cell / nx) % ny) + sb.lo[1];
      const int k = static_cast<int>(f.cell / (nx * ny)) + sb.lo[2];
      const std::string mat = f.material >= 0 ? "'" + st_.mat[f.material].name + "'" : std::string("?");
      std::ostringstream w;
      w << "in cell (" << i << "," << j << "," << k << ") at x = (";
      const int ijk[3] = {i, j, k};
      for (int d = 0; d < mesh_.dim(); ++d) w << (d ? ", " : "") << mesh_.cellCenter(d, ijk[d]);
      w << ") m";
      const std::string where = w.str();
      switch (f.kind) {
        case EquilibriumFailure::Kind::NoAdmissibleState:
          os << "ice: no equilibrium pressure " << where << " at t = " << t_ << ": material " << mat
             << " has no admissible state at its specific internal energy " << st_.mat[f.material].eint(i, j, k)
             << " J/kg (" << st_.mat[f.material].eos->name() << " needs e > 0)";
          break;
        case EquilibriumFailure::Kind::NoRootAboveFloor:
          os << "ice: no equilibrium pressure " << where << " at t = " << t_ << ": down to the lower end "
             << f.floor << " Pa of material " << mat << "'s admissible pressures the materials fill only "
             << 1.0 - f.residual << " of the cell (residual " << f.residual << ")";
          break;
        case EquilibriumFailure::Kind::NotConverged:
          os << "ice: the equilibrium pressure did not converge " << where << " at t = " << t_ << " after "
             << f.iterations << " iterations; last p = " << f.p << ", bracket [" << f.lo << ", " << f.hi
             << "] (admissible above " << f.floor << " Pa, set by " << mat << "), residual " << f.residual;
          break;
      }
      os << " (" << failures.size() << " cells failed on rank " << comm_.rank() << "); materials:";
      for (int r = 0; r < nm; ++r) {
        const MaterialState& m = st_.mat[r];
        os << "\n  " << m.name << " (" << m.eos->name() << "): mass " << m.mass(i, j, k) << " kg, density "
           << m.mass(i, j, k) / V << " kg/m^3 of cell, e " << m.eint(i, j, k) << " J/kg, velocity "
           << m.vel(i, j, k, 0) << " m/s";
      }
    }
    throw std::runtime_error(os.str());
  }
}

void IceSolver::finishEquilibrium(const std::vector<std::pair<int, std::int64_t>>& held,
                                  const std::vector<std::pair<int, std::int64_t>>& cavitated) {
  const int nm = numMaterials();
  // Scratch kept from step to step (each entry is written before it is read): the sound speed's
  // batch a chunk of owned cells at a time (each cell's values are its own).
  std::vector<double>& ra = eqRho_;
  std::vector<double>& ea = eqE_;
  std::vector<double>& c2 = eqC2_;
  const std::size_t chunk = kEquilibriumChunk, n = ownedCells_.size();
  ra.resize(chunk);
  ea.resize(chunk);
  c2.resize(chunk);
  eqCells_.resize(chunk);
  // The health check's sound speed (soundSpeedSquared) where kappa is made: its array holds the
  // Lagrangian specific volume from the Lagrangian phase on (MaterialState::lagSpvol). The cells
  // found here are checked again below, with the held and cavitated ones' kappa.
  soundBad_.clear();
  for (int r = 0; r < nm; ++r) {
    MaterialState& m = st_.mat[r];
    const bool fluid = !m.external, cav = m.eos->cavitates();
    double* th = m.theta.data();
    double* sv = m.spvol.data();
    double* ka = m.kappa.data();
    const double* en = m.eint.data();
    const double* ms = m.mass.data();
    for (std::size_t a0 = 0; a0 < n; a0 += chunk) {
      const std::size_t nc = std::min(chunk, n - a0);
      ownedCells_.fill(a0, nc, eqCells_.data());
      const std::int64_t* cells = eqCells_.data();
      for (std::size_t a = 0; a < nc; ++a) {
        ra[a] = sv[cells[a]];
        ea[a] = en[cells[a]];
      }
      m.eos->soundSpeed2(nc, ra.data(), ea.data(), c2.data());
      for (std::size_t a = 0; a < nc; ++a) {
        const std::int64_t c = cells[a];
        const double rm = ra[a];
        th[c] = nm == 1 ? 1.0 : th[c] / rm;
        sv[c] = 1.0 / rm;
        ka[c] = 1.0 / (rm * c2[a]);
        // An absent material's compressibility is never weighted (theta = 0); at p = 0 (a cavitated
        // liquid's cut-off) a JWL's density is ~1e-300 and 1 / (rho c^2) overflows: 0 * inf was NaN.
        if (!(ms[c] > 0) && !std::isfinite(ka[c])) ka[c] = 0.0;
        if (fluid && th[c] > kPresentFraction && ms[c] > 0 && !soundSpeedAdmissible(soundSpeedSquared(sv[c], ka[c], cav)))
          soundBad_.push_back({r, c, 0.0});
      }
    }
  }
  // A trace held at its carried volume takes no share of the cell's volume change (and so does no
  // p dV work) in this step: it is incompressible below its own pressure.
  for (const auto& [r, c] : held) st_.mat[static_cast<std::size_t>(r)].kappa.data()[c] = 0.0;
  // A cavitated liquid (docs/ice.md "Cavitation") is at its cut-off pressure at any density below
  // the law's there: zero sound speed, infinite compressibility. The cell's kbar is then infinite:
  // the pressure increment is 0 and the cavitated liquids take the cell's whole volume change
  // (computeSourcesAndLagrangian), so the pressure stays at the cut-off while the cavity opens or closes.
  for (const auto& [r, c] : cavitated)
    st_.mat[static_cast<std::size_t>(r)].kappa.data()[c] = std::numeric_limits<double>::infinity();
  // The sound speeds found above and the cavitated liquids' (held traces: kappa = 0, admissible).
  for (const auto& [r, c] : cavitated)
    if (!st_.mat[static_cast<std::size_t>(r)].external) soundBad_.push_back({r, c, 0.0});
  std::erase_if(soundBad_, [&](SoundSpeedViolation& b) {
    const MaterialState& m = st_.mat[static_cast<std::size_t>(b.material)];
    const std::int64_t c = b.cell;
    if (!(m.theta.data()[c] > kPresentFraction) || !(m.mass.data()[c] > 0)) return true;
    b.c2 = soundSpeedSquared(m.spvol.data()[c], m.kappa.data()[c], m.eos->cavitates());
    return soundSpeedAdmissible(b.c2);
  });

  fillMaterialGhosts(false);
  if (st_.solidFaces.on) computeSolidFaces(st_, mesh_, owned_, bc_);
}

void computeVolumeFluxes(IceState& st, const core::Mesh& mesh, const core::Box& owned) {
  const int dim = mesh.dim();
  const core::Box& sb = st.press.box();
  const std::int64_t strides[3] = {1, sb.length(0), std::int64_t(sb.length(0)) * sb.length(1)};
  const std::size_t nm = st.mat.size();
  std::vector<const double*> uf(nm), th(nm);
  // Face volume fluxes U_f = sum_r theta_r,f u_f,r, theta from the upwind cell.
  for (int d = 0; d < dim; ++d) {
    const core::Box fb = owned.faces(d);
    const std::int64_t sd = strides[d];
    double* U = st.volFlux[d].data();
    for (std::size_t r = 0; r < nm; ++r) uf[r] = st.mat[r].velFace[d].data(), th[r] = st.mat[r].theta.data();
    const SolidFaces& sf = st.solidFaces;
    // The face fi with stored cell cR on its high side. NM > 0: the number of materials fixed at
    // compile time (the same operations in the same order).
    auto face = [&]<int NM>(std::int64_t cR, std::int64_t fi) {
      const std::size_t n = NM > 0 ? NM : nm;
      const std::int64_t cL = cR - sd;
      double f = 0;
      if (sf.on) {  // the solids' own transport, the fluids through the open part of the face
        double open = 0, S = 0;
        for (std::size_t r = 0; r < n; ++r) {
          if (st.mat[r].external) continue;
          const double u = uf[r][fi], t = th[r][u > 0 ? cL : cR];
          open += u * t;
          S += t;
        }
        f = sf.flux[d].data()[fi] + (S > 0 ? (1.0 - sf.cover[d].data()[fi]) * open / S : 0.0);
      } else {
        for (std::size_t r = 0; r < n; ++r) {
          const double u = uf[r][fi];
          f += u * th[r][u > 0 ? cL : cR];
        }
      }
      U[fi] = f;
    };
    // The faces in forEach's order, by rows (flat indices along each row).
    auto sweep = [&]<int NM>() {
      for (int k = fb.lo[2]; k <= fb.hi[2]; ++k)
        for (int j = fb.lo[1]; j <= fb.hi[1]; ++j) {
          std::int64_t cR = sb.index(fb.lo[0], j, k), fi = fb.index(fb.lo[0], j, k);
          for (int i = fb.lo[0]; i <= fb.hi[0]; ++i, ++cR, ++fi) face.template operator()<NM>(cR, fi);
        }
    };
    if (nm == 2) sweep.template operator()<2>();
    else if (nm == 3) sweep.template operator()<3>();
    else sweep.template operator()<0>();
  }
}

void explicitPressureIncrement(IceState& st, const core::Mesh& mesh, const core::Box& owned, double dt) {
  const int dim = mesh.dim();
  const core::Box& sb = st.press.box();
  const std::size_t nm = st.mat.size();
  std::vector<const double*> th(nm), ka(nm);
  for (std::size_t r = 0; r < nm; ++r) th[r] = st.mat[r].theta.data(), ka[r] = st.mat[r].kappa.data();
  const VolumeFluxFaces faces(st, mesh, owned);  // their divergence per cell
  // p holds the equilibrium pressure (finishEquilibrium) and becomes p_eq + dp; the increment
  // itself is kept only where st.dp is stored (the semi-implicit pressure's unknown).
  double *dpp = st.dp.npts() > 0 ? st.dp.data() : nullptr, *p = st.press.data();
  bool anyCav = false;
  for (const MaterialState& m : st.mat) anyCav = anyCav || (!m.external && m.eos->cavitates());
  // Stored cell c, f[d] its low face normal to d. NM > 0: the number of materials fixed at
  // compile time (the same operations in the same order).
  auto cell = [&]<int NM>(std::int64_t c, const std::int64_t* f) {
    const std::size_t n = NM > 0 ? NM : nm;
    double kbar = 0;
    for (std::size_t r = 0; r < n; ++r) kbar += th[r][c] * ka[r][c];
    const double pe = p[c];
    double dp = kbar > 0 ? -dt * faces.divergence(dim, f) / kbar : 0.0;
    // A cavitating liquid's cut-off bounds the increment too (docs/ice.md "Cavitation"): a cell
    // that would expand through it in this step cavitates at it (its volume change beyond is the
    // cavity's, which the next equilibrium pressure finds).
    if (anyCav) {
      double pc = -std::numeric_limits<double>::infinity();
      for (const MaterialState& m : st.mat)
        if (!m.external && m.mass.data()[c] > 0 && m.theta.data()[c] > kPresentFraction)
          pc = std::max(pc, m.eos->cavitationPressure());
      if (pe + dp < pc) dp = std::min(0.0, pc - pe);
    }
    if (dpp) dpp[c] = dp;
    p[c] = pe + dp;
  };
  // The owned cells in forEach's order, by rows (flat indices along each row).
  auto sweep = [&]<int NM>() {
    for (int k = owned.lo[2]; k <= owned.hi[2]; ++k)
      for (int j = owned.lo[1]; j <= owned.hi[1]; ++j) {
        std::int64_t c = sb.index(owned.lo[0], j, k), f[3] = {0, 0, 0};
        for (int d = 0; d < dim; ++d) f[d] = faces.box[d].index(owned.lo[0], j, k);
        for (int i = owned.lo[0]; i <= owned.hi[0]; ++i, ++c) {
          cell.template operator()<NM>(c, f);
          for (int d = 0; d < dim; ++d) ++f[d];
        }
      }
  };
  if (nm == 2) sweep.template operator()<2>();
  else if (nm == 3) sweep.template operator()<3>();
  else sweep.template operator()<0>();
}

void IceSolver::computePressureIncrement() {
  if (riemannLowMach_)  // the face pressure's lowMachScale reads the equilibrium pressure (ghosts and all)
    lowMachPressure_.assign(st_.press.data(), st_.press.data() + st_.press.npts());
  if (semiImplicit_) {
    solveSemiImplicit();
  } else {
    computeVolumeFluxes(st_, mesh_, owned_);
    explicitPressureIncrement(st_, mesh_, owned_, dt_);
  }
  fillGhosts({{&st_.press, FieldKind::Pressure}}, {-1});
}

}  // namespace mpmice::ice
