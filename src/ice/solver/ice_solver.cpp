#include "ice/solver/ice_solver.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "core/health/health.h"
#include "ice/exchange/pointwise_exchange.h"  // kMaxMaterials
#include "ice/ice_constants.h"
#include "ice/solver/health_check.h"
#include "ice/state/phase_units.h"

namespace mpmice::ice {

using core::Field;
using core::forEach;

IceSolver::~IceSolver() = default;

IceSolver::IceSolver(const core::Scene& scene, const core::Comm& comm, bool coupledStart)
    : comm_(comm), mesh_(scene.mesh), decomp_(scene.mesh, comm.size(), scene.periodic()) {
  initialize(scene, coupledStart);
}

void IceSolver::fillGhosts(const std::vector<std::pair<Field*, FieldKind>>& fields, const std::vector<int>& mats) {
  std::vector<Field*> fs;
  fs.reserve(fields.size());
  for (const auto& f : fields) fs.push_back(f.first);
  ghosts_->fill(fs);
  for (std::size_t i = 0; i < fields.size(); ++i) bc_.apply(*fields[i].first, fields[i].second, mats[i]);
}

void IceSolver::fillMaterialGhosts(bool lagrangian) {
  std::vector<std::pair<Field*, FieldKind>> fs;
  std::vector<int> mats;
  for (int r = 0; r < numMaterials(); ++r) {
    MaterialState& m = st_.mat[r];
    if (lagrangian) {
      fs.insert(fs.end(), {{&m.lagVel(), FieldKind::Velocity}, {&m.lagEint(), FieldKind::Energy},
                           {&m.lagSpvol(), FieldKind::SpecificVolume}});
      mats.insert(mats.end(), {r, r, r});
    } else {
      fs.insert(fs.end(), {{&m.mass, FieldKind::Mass}, {&m.vel, FieldKind::Velocity}, {&m.eint, FieldKind::Energy},
                           {&m.spvol, FieldKind::SpecificVolume}, {&m.theta, FieldKind::VolumeFraction}});
      mats.insert(mats.end(), {r, r, r, r, r});
      if (riemannFacePressureOn() || anyExternal_) {  // impedances: face pressure, stable step; beside solids the face velocity
        fs.push_back({&m.kappa, FieldKind::Scalar});
        mats.push_back(r);
      }
    }
  }
  if (!lagrangian) {
    fs.push_back({&st_.press, FieldKind::Pressure});
    mats.push_back(-1);
  }
  fillGhosts(fs, mats);
}

double IceSolver::stableTimeStep() const { return stableTimeStep(nullptr); }

double IceSolver::stableTimeStep(StepBound* where) const {
  const int dim = mesh_.dim();
  const double V = mesh_.cellVolume();
  double rate = 0;  // max over cells of sum_d (|u_d| + c) / dx_d
  // Explicit pressure: max over cells of c sum_d 1 / dx_d (kMaxAcousticCourant's bound).
  double acoustic = 0;
  std::int64_t acousticCell = -1;
  const bool acousticBoundOn = !semiImplicit_ && cfl_ > kMaxAcousticCourant;  // it cannot bind otherwise
  // Semi-implicit with two or more fluids, the run's first step (no step bound before it) without
  // time.dt_initial: the explicit pressure's bound, max over cells of sum_d (|u_d| + c) / dx_d
  // (kSemiImplicitStepGrowth).
  const bool startBoundOn = stepRamp_ && !(lastBound_ > 0) && !(dtInitial_ > 0);
  double startRate = 0;
  std::int64_t startCell = -1;
  const int nm = numMaterials();
  const core::Box& sb = st_.press.box();
  std::int64_t rateCell = -1;
  const std::int64_t strides[3] = {1, sb.length(0), std::int64_t(sb.length(0)) * sb.length(1)};
  // Acoustic impedance rho c = sqrt(rho / kbar) of the mixture in stored cell q (0 if empty).
  auto impedance = [&](std::int64_t q) {
    double kb = 0, rh = 0;
    for (int r = 0; r < nm; ++r) {
      kb += st_.mat[r].theta.data()[q] * st_.mat[r].kappa.data()[q];
      rh += st_.mat[r].mass.data()[q] / V;
    }
    return kb > 0 && rh > 0 ? std::sqrt(rh / kb) : 0.0;
  };
  const double* press = st_.press.data();
  // Semi-implicit: each cell's impedance once (owned cells and one ghost layer), read by its
  // 2 dim neighbours below.
  const core::Box zb = owned_.grow(1, dim);
  const std::int64_t zstr[3] = {1, zb.length(0), std::int64_t(zb.length(0)) * zb.length(1)};
  if (semiImplicit_) {
    impedanceScratch_.resize(static_cast<std::size_t>(zb.numPts()));
    forEach(zb, [&](int i, int j, int k) {
      impedanceScratch_[static_cast<std::size_t>(zb.index(i, j, k))] = impedance(sb.index(i, j, k));
    });
  }
  // Per material: volume fraction, compressibility, mass, velocity.
  struct Ptr {
    const double *th, *ka, *m, *u[3];
  };
  std::vector<Ptr> ptrs(static_cast<std::size_t>(nm));
  for (int r = 0; r < nm; ++r) {
    const MaterialState& m = st_.mat[r];
    ptrs[r] = {m.theta.data(), m.kappa.data(), m.mass.data(), {nullptr, nullptr, nullptr}};
    for (int d = 0; d < dim; ++d) ptrs[r].u[d] = m.vel.data(d);
  }
  const Ptr* const ptr = ptrs.data();
  // One owned cell (i, j, k), stored index c. NM, DIM > 0: the number of materials and the mesh's
  // dimension fixed at compile time (the small loops unroll; the same operations in the same order).
  auto cell = [&]<int NM, int DIM>(int i, int j, int k, std::int64_t c) {
    const int nmt = NM > 0 ? NM : nm;
    const int nd = DIM > 0 ? DIM : dim;
    double kbar = 0, rho = 0;
    double umax[3] = {0, 0, 0};
    for (int r = 0; r < nmt; ++r) {
      const Ptr& m = ptr[r];
      const double th = m.th[c];
      kbar += th * m.ka[c];
      rho += m.m[c] / V;
      if (th > kPresentFraction)
        for (int d = 0; d < nd; ++d) umax[d] = std::max(umax[d], std::abs(m.u[d][c]));
    }
    const double cs = kbar > 0 && rho > 0 ? std::sqrt(1.0 / (rho * kbar)) : 0.0;
    // Semi-implicit: the convective bound must hold for the velocities the step creates, not only
    // for those it starts from. A pressure jump between two cells accelerates them to the linear
    // Riemann solution's |p_n - p_c| / (Z_c + Z_n) (Z = rho c) within the step, so that speed
    // joins |u_d|. Without it a tube at rest took 0.1 c as its speed (10 times the explicit
    // step) and its shock started at an acoustic CFL number of 3: Sod at 100 cells +7.5 % /
    // +11.9 % behind the shock (docs/ice.md "Shocks", semi-implicit).
    if (semiImplicit_) {
      const std::int64_t zc = zb.index(i, j, k);
      for (int d = 0; d < dim; ++d)
        for (const int side : {-1, 1}) {
          const double z = impedanceScratch_[static_cast<std::size_t>(zc)] +
                           impedanceScratch_[static_cast<std::size_t>(zc + side * zstr[d])];
          const std::int64_t n = c + side * strides[d];
          if (z > 0) umax[d] = std::max(umax[d], std::abs(press[n] - press[c]) / z);
        }
    }
    if (startBoundOn) {
      double e = 0;
      for (int d = 0; d < nd; ++d) e += (umax[d] + cs) / mesh_.dx(d);
      if (e > startRate) {
        startRate = e;
        startCell = c;
      }
    }
    double s = 0;
    for (int d = 0; d < nd; ++d)
      s += (semiImplicit_ ? std::max(umax[d], soundFraction_ * cs) : umax[d] + cs) / mesh_.dx(d);
    if (acousticBoundOn) {
      double a = 0;
      for (int d = 0; d < nd; ++d) a += cs / mesh_.dx(d);
      if (a > acoustic) {
        acoustic = a;
        acousticCell = c;
      }
    }
    // The shock viscosity is an explicit diffusion with nu = (q1 c + q2 |du|) dx: stable for
    // dt <= dx / (2 (q1 c + q2 |du|)); added to the rate, so the CFL factor covers it as well.
    if (q1_ > 0 || q2_ > 0)
      for (int d = 0; d < dim; ++d) {
        const std::int64_t sd = strides[d];
        double du = 0;
        for (int r = 0; r < nm; ++r) {
          const MaterialState& m = st_.mat[r];
          if (!(m.theta.data()[c] > kPresentFraction)) continue;
          const double* u = m.vel.data(d);
          du = std::max({du, std::abs(u[c + sd] - u[c]), std::abs(u[c] - u[c - sd])});
        }
        s += 2.0 * (q1_ * cs + q2_ * du) / mesh_.dx(d) * cfl_;
      }
    if (s > rate) {
      rate = s;
      rateCell = c;
    }
  };
  // The owned cells in forEach's order, by rows (flat indices along each row).
  auto sweep = [&]<int NM, int DIM>() {
    for (int k = owned_.lo[2]; k <= owned_.hi[2]; ++k)
      for (int j = owned_.lo[1]; j <= owned_.hi[1]; ++j) {
        std::int64_t c = sb.index(owned_.lo[0], j, k);
        for (int i = owned_.lo[0]; i <= owned_.hi[0]; ++i, ++c) cell.template operator()<NM, DIM>(i, j, k, c);
      }
  };
  if (nm == 2 && dim == 2) sweep.template operator()<2, 2>();
  else if (nm == 2 && dim == 3) sweep.template operator()<2, 3>();
  else if (nm == 3 && dim == 2) sweep.template operator()<3, 2>();
  else if (nm == 3 && dim == 3) sweep.template operator()<3, 3>();
  else sweep.template operator()<0, 0>();
  const double localRate = rate, localAcoustic = acoustic;
  rate = comm_.max(rate);
  double dt = rate > 0 ? cfl_ / rate : dtMax_;
  // The explicit step's acoustic Courant number (ice_constants.h, kMaxAcousticCourant): the
  // convective-acoustic bound above keeps it below time.cfl, which may be up to 1; where the flow
  // is slow against c and time.cfl > kMaxAcousticCourant, this bound sets the step. At time.cfl <=
  // kMaxAcousticCourant it never does (c sum_d 1 / dx_d <= sum_d (|u_d| + c) / dx_d cell by cell).
  bool acousticBound = false;
  if (acousticBoundOn) {
    acoustic = comm_.max(acoustic);
    if (acoustic > 0 && kMaxAcousticCourant / acoustic < dt) {
      dt = kMaxAcousticCourant / acoustic;
      acousticBound = true;
    }
  }
  // The semi-implicit step with two or more fluids starts from the explicit one (or time.dt_initial)
  // and grows by at most kSemiImplicitStepGrowth a step (ice_constants.h). time.dt_initial bounds
  // the run's first step in every setting.
  bool startBound = false, growthBound = false, initialBound = false;
  if (!(lastBound_ > 0) && dtInitial_ > 0 && dtInitial_ < dt) {
    dt = dtInitial_;
    initialBound = true;
  }
  const double localStart = startRate;
  if (startBoundOn) {
    startRate = comm_.max(startRate);
    if (startRate > 0 && std::min(cfl_, kMaxAcousticCourant) / startRate < dt) {
      dt = std::min(cfl_, kMaxAcousticCourant) / startRate;
      startBound = true;
    }
  } else if (stepRamp_ && lastBound_ > 0 && kSemiImplicitStepGrowth * lastBound_ < dt) {
    dt = kSemiImplicitStepGrowth * lastBound_;
    growthBound = true;
  }
  // Explicit viscosity (computeSourcesAndLagrangian: forward Euler on the face fluxes of the
  // Newtonian stress) is stable for dt nu lambda <= 2 (lambda below: dt <= 3 dx^2 / (14 nu) in 2D on
  // a uniform mesh, 3 / 4 of the Laplacian's dx^2 / (2 dim nu) in 1D, 6 / 7 in 2D, 9 / 10 in 3D), with
  // nu = mu / rho the kinematic viscosity of every viscous fluid present in a cell (theta > kPresentFraction).
  // rho = m / (theta V), which is 1 / v at equilibrium; before the first equilibrium of a coupled
  // run (solids just placed) v may still be that of a trace that filled a solid cell (1e10 m^3/kg)
  // while m / (theta V) stays the cell's real mass.
  // The Riemann face pressure's dissipation (-Z du at faces in compression) is an explicit
  // diffusion of velocity too (nu = Z dx / rho): its rate R = max_cells sum_d (Z_lo + Z_hi) /
  // (rho dx_d) adds to the viscous one, dt <= 1 / (nu lambda / 2 + R). A velocity
  // checkerboard (one face in compression per cell and direction) keeps its amplitude there.
  double inv2 = 0, maxInv2 = 0;
  for (int d = 0; d < dim; ++d) {
    inv2 += 1.0 / (mesh_.dx(d) * mesh_.dx(d));
    maxInv2 = std::max(maxInv2, 1.0 / (mesh_.dx(d) * mesh_.dx(d)));
  }
  // The discrete Newtonian stress's largest decay rate over nu (computeSourcesAndLagrangian): for a
  // Fourier mode with x_d = sin^2(k_d dx_d / 2) the operator is -nu [L I + M / 3], L = 4 sum_d x_d /
  // dx_d^2 (the Laplacian), M = s s^T + diag(4 x_d^2 / dx_d^2) (s_d = sin(k_d dx_d) / dx_d, the
  // central cross differences), whose largest eigenvalue is at most |s|^2 + max_d 4 x_d^2 / dx_d^2;
  // L + that / 3 grows with every x_d, so the checkerboard x_d = 1 (s = 0) has the largest:
  // lambda = 4 sum_d dx_d^-2 + (4/3) max_d dx_d^-2 (16/3 dx^-2 in 1D, 28/3 in 2D, 40/3 in 3D).
  const double lambdaNu = 4.0 * inv2 + 4.0 / 3.0 * maxInv2;
  double rRate = 0, localR = 0;
  std::int64_t rCell = -1;
  if (riemannFacePressureOn()) {
    mixes_.lowMach = riemannLowMach_;
    localR = riemannDissipationRate(st_, mesh_, owned_, &rCell, &mixes_);
    rRate = comm_.max(localR);
  }
  double nu = 0, localNu = 0;
  std::int64_t nuCell = -1;
  int nuMaterial = -1;
  bool viscous = false;
  if (anyViscous_) {
    // A viscous fluid held to the cell's other materials by the momentum exchange does not diffuse
    // on its own: the exchange (implicit, after the Lagrangian phase) gives the momentum its
    // viscous update made to the whole cell. Its own velocity's deviation from the others', which
    // the update multiplies by at most 1 - dt nu_r lambda (nu_r = mu / rho_r), the exchange
    // divides by 1 + dt k_r, k_r = v_r sum_s theta_s K_rs; so with k_r >= nu_r lambda, i.e.
    // sum_s theta_s K_rs >= mu lambda (the density cancels), no step makes it grow, and
    // what bounds the step is the cell's mixture: nu = mu theta_r V / M with M the cell's mass of
    // every material (summed over the fluids so held). A rarefied trace of a viscous liquid in a
    // solid's cells (nu_r = mu / rho_r ~ 1e2 m^2/s) no longer sets the step (docs/ice.md).
    const double* th[kMaxMaterials];
    const double* ms[kMaxMaterials];
    for (int r = 0; r < nm; ++r) th[r] = st_.mat[r].theta.data(), ms[r] = st_.mat[r].mass.data();
    forEach(owned_, [&](int i, int j, int k) {
      const std::int64_t c = sb.index(i, j, k);
      double held = 0, heldMost = 0, M = -1;  // M: computed on first need
      int heldMaterial = -1;
      for (int r = 0; r < nm; ++r) {
        const MaterialState& m = st_.mat[r];
        if (m.external || !(m.viscosity > 0)) continue;
        if (!(th[r][c] > kPresentFraction && ms[r][c] > 0)) continue;
        double coupling = 0;
        if (anyK_)
          for (int s = 0; s < nm; ++s)
            if (s != r && th[s][c] > kPresentFraction && ms[s][c] > 0) coupling += th[s][c] * momentumExchange(r, s);
        if (coupling > 0 && coupling >= m.viscosity * lambdaNu) {
          if (M < 0) {
            M = 0;
            for (int s = 0; s < nm; ++s) M += std::max(ms[s][c], 0.0);
          }
          const double part = m.viscosity * th[r][c] * V / M;
          held += part;
          if (part > heldMost) heldMost = part, heldMaterial = r;
        } else if (m.viscosity * th[r][c] * V / ms[r][c] > localNu) {
          localNu = m.viscosity * th[r][c] * V / ms[r][c];
          nuCell = c;
          nuMaterial = r;
        }
      }
      if (held > localNu) {
        localNu = held;
        nuCell = c;
        nuMaterial = heldMaterial;
      }
    });
    nu = comm_.max(localNu);
  }
  const double diffusive = 0.5 * nu * lambdaNu + rRate;
  if (diffusive > 0 && 1.0 / diffusive < dt) {
    dt = 1.0 / diffusive;
    viscous = true;
  }
  // Explicit heat conduction (computeSourcesAndLagrangian: forward Euler on the face-flux Laplacian
  // of T, weighted like the viscous one by the smaller theta) is stable for dt <= 1 / (2 alpha
  // sum_d dx_d^-2), alpha = k / (rho cv) the thermal diffusivity of each conducting fluid present
  // (theta > kPresentFraction; rho = m / (theta V), cv the EOS's de/dT). Before 6 Dec 2026 (evening)
  // there was no such bound: a conducting gas on a fine mesh (the Becker shock's Prandtl 3/4 gas)
  // diverged.
  double alpha = 0, localAlpha = 0;
  std::int64_t alphaCell = -1;
  int alphaMaterial = -1;
  bool conduction = false;
  if (anyConduction_) {
    // As the held viscous fluid above: a conducting fluid held to the cell's other materials by the
    // heat exchange (implicit, after the Lagrangian phase), which divides its temperature's
    // deviation from theirs by 1 + dt h_r, h_r = sum_s theta_s H_rs / (rho_r cv_r), while its
    // conduction multiplies it by at most 1 - dt alpha_r lambda_T (lambda_T = 4 sum_d dx_d^-2):
    // with sum_s theta_s H_rs >= k lambda_T no step makes the deviation grow, and the cell's
    // temperature diffuses with the mixture's alpha = k theta_r V / C, C the cell's heat capacity
    // sum_s m_s cv_s (summed over the fluids so held). A rarefied conducting gas's trace in a
    // solid's cells (alpha_r = k / (rho_r cv_r) without bound as rho_r -> 0) then sets no step.
    const double lambdaT = 4.0 * inv2;
    forEach(owned_, [&](int i, int j, int k) {
      const std::int64_t c = sb.index(i, j, k);
      double held = 0, heldMost = 0, C = -1;  // C: computed on first need
      int heldMaterial = -1;
      for (int r = 0; r < nm; ++r) {
        const MaterialState& m = st_.mat[r];
        if (m.external || !(m.conductivity > 0)) continue;
        const double th = m.theta.data()[c], ms = m.mass.data()[c];
        if (!(th > kPresentFraction && ms > 0)) continue;
        double coupling = 0;
        if (anyH_)
          for (int s = 0; s < nm; ++s) {
            const MaterialState& o = st_.mat[s];
            if (s != r && o.theta.data()[c] > kPresentFraction && o.mass.data()[c] > 0)
              coupling += o.theta.data()[c] * H_[static_cast<std::size_t>(r * nm + s)];
          }
        if (coupling > 0 && coupling >= m.conductivity * lambdaT) {
          if (C < 0) {
            C = 0;
            for (int s = 0; s < nm; ++s) C += std::max(st_.mat[s].mass.data()[c], 0.0) * st_.mat[s].eos->cv();
          }
          const double part = m.conductivity * th * V / C;
          held += part;
          if (part > heldMost) heldMost = part, heldMaterial = r;
          continue;
        }
        const double a = m.conductivity * th * V / (ms * m.eos->cv());
        if (a > localAlpha) localAlpha = a, alphaCell = c, alphaMaterial = r;
      }
      if (held > localAlpha) localAlpha = held, alphaCell = c, alphaMaterial = heldMaterial;
    });
    alpha = comm_.max(localAlpha);
    if (alpha > 0 && 1.0 / (2.0 * alpha * inv2) < dt) {
      dt = 1.0 / (2.0 * alpha * inv2);
      conduction = true;
      viscous = false;
    }
  }
  if (where) {
    *where = {};
    if (conduction) {
      where->limit = "the ICE explicit conduction bound 1 / (2 alpha sum_d dx_d^-2), alpha = k / (rho cv)";
      where->here = localAlpha == alpha;
      where->cell = alphaCell;
      where->material = alphaMaterial;
      where->value = alpha;
      where->conduction = true;
    } else if (viscous && 0.5 * nu * lambdaNu >= rRate) {
      where->limit = rRate > 0 ? "the ICE explicit viscous + Riemann face-pressure bound 1 / (nu lambda / 2 + R)"
                               : "the ICE explicit viscous bound 2 / (nu lambda), lambda = 4 sum_d dx_d^-2 + (4/3) max_d dx_d^-2";
      where->here = localNu == nu;
      where->cell = nuCell;
      where->material = nuMaterial;
      where->value = nu;
    } else if (viscous) {
      where->limit = nu > 0 ? "the ICE explicit viscous + Riemann face-pressure bound 1 / (nu lambda / 2 + R)"
                            : "the ICE Riemann face-pressure bound 1 / R";
      where->here = localR == rRate;
      where->cell = rCell;
      where->riemann = true;
      where->value = rRate;
    } else if (initialBound && dt < dtMax_) {
      where->limit = "time.dt_initial (the run's first step)";  // no cell
    } else if (startBound && dt < dtMax_) {
      where->limit = "the ICE semi-implicit step's start, the explicit bound min(cfl, 0.7) / sum_d (|u_d| + c) / dx_d";
      where->here = localStart == startRate;
      where->cell = startCell;
      where->value = startRate;
    } else if (growthBound && dt < dtMax_) {
      static_assert(kSemiImplicitStepGrowth == 1.1, "the message below quotes it");
      where->limit = "the ICE semi-implicit step's growth (at most 1.1 times the step before's bound)";  // no cell
    } else if (acousticBound && dt < dtMax_) {
      static_assert(kMaxAcousticCourant == 0.7, "the message below quotes it");
      where->limit = "the ICE explicit acoustic bound 0.7 / (c sum_d 1 / dx_d) (time.cfl above 0.7)";
      where->here = localAcoustic == acoustic;
      where->cell = acousticCell;
      where->value = acoustic;
      where->acoustic = true;
    } else if (rate > 0 && cfl_ / rate < dtMax_) {
      where->limit = semiImplicit_ ? "the ICE CFL bound (convective, sound speed share)"
                                   : "the ICE CFL bound (convective + acoustic)";
      where->here = localRate == rate;
      where->cell = rateCell;
      where->value = rate;
    } else {
      where->limit = "time.dt_max";  // no cell
    }
  }
  bound_ = dt;
  return dt;
}

std::string IceSolver::stableTimeStepLimit() const {
  StepBound b;
  const double dt = stableTimeStep(&b);
  std::ostringstream os;
  os.precision(6);
  os << b.limit << " (dt " << dt << " s)";
  if (b.cell < 0) return comm_.firstMessage(comm_.root() ? os.str() : "");  // time.dt_max: no cell
  if (!b.here) return comm_.firstMessage("");  // another rank holds the limiting cell
  const core::Box& sb = st_.press.box();
  const std::int64_t nx = sb.length(0), ny = sb.length(1);
  const int ijk[3] = {static_cast<int>(b.cell % nx) + sb.lo[0], static_cast<int>((b.cell / nx) % ny) + sb.lo[1],
                      static_cast<int>(b.cell / (nx * ny)) + sb.lo[2]};
  double x[3];
  for (int d = 0; d < 3; ++d) x[d] = mesh_.cellCenter(d, ijk[d]);
  os << " in cell (" << ijk[0] << "," << ijk[1] << "," << ijk[2] << ") at x = " << core::formatPoint(x, mesh_.dim())
     << " m";
  if (b.material >= 0) {
    os << ", fluid '" << st_.mat[b.material].name << "', " << (b.conduction ? "alpha" : "nu") << " = " << b.value
       << " m^2/s";
  } else {
    if (b.riemann)
      os << ", R = sum_d (Z_lo + Z_hi) / (rho dx_d) = " << b.value << " 1/s; materials:";
    else if (b.acoustic)
      os << ", c sum_d 1 / dx_d = " << b.value << " 1/s; materials:";
    else
      os << ", sum_d (|u_d| + c) / dx_d = " << b.value << " 1/s; materials:";
    const double V = mesh_.cellVolume();
    const std::int64_t c = b.cell;
    for (const MaterialState& m : st_.mat) {
      double u = 0;
      for (int d = 0; d < m.vel.ncomp(); ++d) u += m.vel.data(d)[c] * m.vel.data(d)[c];
      os << " '" << m.name << "' (theta " << m.theta.data()[c] << ", density " << m.mass.data()[c] / V
         << " kg/m^3, |u| " << std::sqrt(u) << " m/s, c " << std::sqrt(m.spvol.data()[c] / m.kappa.data()[c])
         << " m/s)";
    }
    // Why the fluid there is not held by a solid nearby (health_check.h).
    for (int r = 0; r < numMaterials(); ++r)
      if (!st_.mat[r].external && st_.mat[r].theta.data()[c] > kPresentFraction) {
        const std::string note = weakExchangeNote(*this, ijk[0], ijk[1], ijk[2], r, dt);
        if (!note.empty()) {
          os << note;
          break;
        }
      }
  }
  return comm_.firstMessage(os.str());
}

void IceSolver::step() {
  computeEquilibriumPressure();
  double dt = std::min(stableTimeStep(), dtMax_);
  if (collapse_.collapsed(dt))
    throw core::HealthError(collapse_.message(dt, t_, nsteps_ + 1, stableTimeStepLimit()), comm_.root());
  if (dt < dtMin_)
    throw std::runtime_error("ice: the stable time step " + std::to_string(dt) + " s at t = " + std::to_string(t_) +
                             " s fell below time.dt_min = " + std::to_string(dtMin_) + " s");
  if (tEnd_ > 0 && t_ + dt > tEnd_) dt = tEnd_ - t_;
  beginStep(dt);
  computeFaceVelocities();
  computePressureIncrement();
  computeFacePressure();
  computeSourcesAndLagrangian();
  exchange();
  advectFluids();
}

void IceSolver::beginStep(double dt) {
  if (!(dt > 0) || !std::isfinite(dt))
    throw std::runtime_error("ice: time step " + std::to_string(dt) + " at t = " + std::to_string(t_) +
                             " is not positive and finite");
  dt_ = dt;
  lastBound_ = bound_;
}

void IceSolver::setExternalMaterialState(int material, std::span<const double> mass, std::span<const double> velocity,
                                         std::span<const double> temperature, std::span<const double> specificVolume) {
  MaterialState& m = st_.mat.at(static_cast<std::size_t>(material));
  if (!m.external) throw std::invalid_argument("ice: material '" + m.name + "' is not external");
  const std::size_t n = static_cast<std::size_t>(owned_.numPts());
  if (mass.size() != n || temperature.size() != n || specificVolume.size() != n || velocity.size() != 3 * n)
    throw std::invalid_argument("ice: external state of '" + m.name + "' has the wrong size (owned cells " +
                                std::to_string(n) + ")");
  forEach(owned_, [&](int i, int j, int k) {
    const auto q = static_cast<std::size_t>(owned_.index(i, j, k));
    const double v = specificVolume[q];
    m.mass(i, j, k) = mass[q];
    for (int d = 0; d < m.vel.ncomp(); ++d) m.vel(i, j, k, d) = velocity[d * n + q];  // 3 given, the mesh's kept
    m.spvol(i, j, k) = v;
    m.eint(i, j, k) = m.eos->energyFromTemperature(1.0 / v, temperature[q]);
  });
}

void IceSolver::setExternalFaceTransport(int material, std::span<const double> density, std::span<const double> flux) {
  MaterialState& m = st_.mat.at(static_cast<std::size_t>(material));
  if (!m.external) throw std::invalid_argument("ice: material '" + m.name + "' is not external");
  const std::size_t n = static_cast<std::size_t>(owned_.numPts());
  if (density.size() != 3 * n || flux.size() != 3 * n)
    throw std::invalid_argument("ice: face transport of '" + m.name + "' has the wrong size (owned cells " +
                                std::to_string(n) + ")");
  if (m.faceDensity.npts() == 0) {
    m.faceDensity = Field(m.name + "/face_density", core::Centering::Cell, st_.press.box(), 3, kGhost);
    m.faceFlux = Field(m.name + "/face_flux", core::Centering::Cell, st_.press.box(), 3, kGhost);
  }
  forEach(owned_, [&](int i, int j, int k) {
    const auto q = static_cast<std::size_t>(owned_.index(i, j, k));
    for (int d = 0; d < 3; ++d) {
      m.faceDensity(i, j, k, d) = density[d * n + q];
      m.faceFlux(i, j, k, d) = flux[d * n + q];
    }
  });
  ghosts_->fill(std::vector<Field*>{&m.faceDensity, &m.faceFlux});
  st_.solidFaces.on = true;
}

namespace {
template <class State, class F>
void forCheckpointFields(State& st, F&& f) {
  for (auto& m : st.mat)
    for (auto* x : {&m.mass, &m.vel, &m.eint, &m.spvol, &m.theta, &m.kappa}) f(*x);
  f(st.press);
}
}  // namespace

IceSolver::Checkpoint IceSolver::checkpoint() const {
  Checkpoint c;
  c.t = t_;
  c.steps = nsteps_;
  forCheckpointFields(st_, [&](const core::Field& x) { c.fields.push_back(x); });
  return c;
}

void IceSolver::restore(const Checkpoint& c) {
  semi_.mobilityFresh = false;
  std::size_t n = 0;
  forCheckpointFields(st_, [&](core::Field& x) { x = c.fields.at(n++); });
  t_ = c.t;
  nsteps_ = c.steps;
}

void IceSolver::fitFluidsToExternalVolume() {
  if (initialPressure_.npts() == 0)
    throw std::logic_error("ice: fitFluidsToExternalVolume needs a solver built for a coupled start");
  const double V = mesh_.cellVolume();
  forEach(owned_, [&](int i, int j, int k) {
    // Fluids at the scene's initial pressure of the cell (their micro density from the EOS).
    const double p0 = initialPressure_(i, j, k);
    // In a cell whose centre lies in a solid object, every fluid starts as a trace of the same
    // volume fraction (initial_state.cpp); the fluids of the region the solid sits in fill what the
    // solid leaves free, the others stay traces. Scaling every trace alike gave each fluid an equal
    // share: in the filled lattices the buffer gas meant for above the plate took half of the
    // free volume in the polymer's surface cells (docs/slides.md, "Filled lattices").
    const std::uint32_t held = solidCellFluids_.empty() ? 0u : solidCellFluids_[static_cast<std::size_t>(owned_.index(i, j, k))];
    const int nm = numMaterials();
    double vext = 0, vheld = 0, vother = 0;  // the solids' volume; the fluids', the region's and the others'
    for (int r = 0; r < nm; ++r) {
      const MaterialState& m = st_.mat[r];
      if (m.external) {
        vext += m.mass(i, j, k) * m.spvol(i, j, k);
        continue;
      }
      const double rho = m.eos->density(p0, m.eint(i, j, k));
      if (rho > 0) ((held >> r) & 1u ? vheld : vother) += m.mass(i, j, k) / rho;
    }
    // No solid here: the fluids fill the cell already (regions of different pressures may share
    // it, initial_regions.h cellShares, each fluid at its own).
    if (!(vext > 0) && held == 0) return;
    if (!(vheld + vother > 0)) return;
    const double vfree = std::max(V - vext, (1.0 - kMaxSolidFraction) * V);
    // The region's fluids fill what the other traces leave; without them every fluid is scaled alike.
    const bool regionFills = vheld > 0 && vfree > vother;
    const double scale = regionFills ? (vfree - vother) / vheld : vfree / (vheld + vother);
    for (int r = 0; r < nm; ++r)
      if (!st_.mat[r].external && (!regionFills || ((held >> r) & 1u))) st_.mat[r].mass(i, j, k) *= scale;
  });
  solidCellFluids_ = {};
  fillMaterialGhosts(false);
}

void IceSolver::setExternalLagrangianMomentum(int material, std::span<const double> momentum) {
  MaterialState& m = st_.mat.at(static_cast<std::size_t>(material));
  const std::size_t n = static_cast<std::size_t>(owned_.numPts());
  if (momentum.size() != 3 * n) throw std::invalid_argument("ice: external momentum has the wrong size");
  forEach(owned_, [&](int i, int j, int k) {
    const auto q = static_cast<std::size_t>(owned_.index(i, j, k));
    const double mass = m.mass(i, j, k);
    core::Field& uL = m.lagVel();
    for (int d = 0; d < uL.ncomp(); ++d) uL(i, j, k, d) = mass > 0 ? momentum[d * n + q] / mass : m.vel(i, j, k, d);
  });
}

void IceSolver::setExternalLagrangianEnergy(int material, std::span<const double> energy) {
  MaterialState& m = st_.mat.at(static_cast<std::size_t>(material));
  const std::size_t n = static_cast<std::size_t>(owned_.numPts());
  if (energy.size() != n) throw std::invalid_argument("ice: external energy has the wrong size");
  forEach(owned_, [&](int i, int j, int k) {
    const auto q = static_cast<std::size_t>(owned_.index(i, j, k));
    const double mass = m.mass(i, j, k);
    m.lagEint()(i, j, k) = mass > 0 ? energy[q] / mass : m.eint(i, j, k);
  });
}

namespace {
// One value per owned cell of an external material's input (setExternalCouplingWork and
// setExternalVolumeChange): checks that the material is external and the size, then copies.
void setOwnedValues(MaterialState& m, core::Field& f, std::span<const double> values, const core::Box& owned,
                    const char* what) {
  if (!m.external) throw std::invalid_argument("ice: material '" + m.name + "' is not external");
  if (values.size() != static_cast<std::size_t>(owned.numPts()))
    throw std::invalid_argument(std::string("ice: external ") + what + " has the wrong size");
  forEach(owned, [&](int i, int j, int k) { f(i, j, k) = values[static_cast<std::size_t>(owned.index(i, j, k))]; });
}
}  // namespace

void IceSolver::setExternalCouplingWork(int material, std::span<const double> work) {
  MaterialState& m = st_.mat.at(static_cast<std::size_t>(material));
  setOwnedValues(m, m.couplingWork, work, owned_, "coupling work");
}

void IceSolver::setExternalVolumeChange(int material, std::span<const double> volumeChange) {
  MaterialState& m = st_.mat.at(static_cast<std::size_t>(material));
  setOwnedValues(m, m.volumeChange, volumeChange, owned_, "volume change");
  m.volumeChangeGiven = true;
}

Field IceSolver::pressureForce(int material) const {
  const MaterialState& m = st_.mat.at(static_cast<std::size_t>(material));
  Field f(m.name + "/pressure_force", core::Centering::Cell, owned_, 3, 0);
  const double V = mesh_.cellVolume();
  forEach(owned_, [&](int i, int j, int k) {
    const int c[3] = {i, j, k};
    for (int d = 0; d < mesh_.dim(); ++d) {
      int u[3] = {i, j, k};
      u[d] = c[d] + 1;
      const double g = (st_.pressFace[d](u[0], u[1], u[2]) - st_.pressFace[d](i, j, k)) / mesh_.dx(d);
      f(i, j, k, d) = -V * m.theta(i, j, k) * g;
    }
  });
  return f;
}

Totals IceSolver::totals() const {
  Totals t;
  for (const MaterialState& m : st_.mat) {
    if (m.external) continue;
    forEach(owned_, [&](int i, int j, int k) {
      const double mass = m.mass(i, j, k);
      double ke = 0;
      for (int d = 0; d < m.vel.ncomp(); ++d) {
        const double u = m.vel(i, j, k, d);
        t.momentum[d] += mass * u;
        ke += u * u;
      }
      t.mass += mass;
      t.energy += mass * (m.eint(i, j, k) + 0.5 * ke);
      t.kinetic += 0.5 * mass * ke;
    });
  }
  t.mass = comm_.sum(t.mass);
  t.energy = comm_.sum(t.energy);
  t.kinetic = comm_.sum(t.kinetic);
  for (int d = 0; d < 3; ++d) t.momentum[d] = comm_.sum(t.momentum[d]);
  return t;
}

double IceSolver::density(int m, int i, int j, int k) const {
  return st_.mat[m].mass(i, j, k) / mesh_.cellVolume();
}

std::vector<std::string> IceSolver::outputFieldNames() const {
  std::vector<std::string> names{"pressure", "pressure_iterations"};
  for (const MaterialState& m : st_.mat)
    for (const char* q : {"_density", "_velocity", "_temperature", "_volume_fraction"}) names.push_back(m.name + q);
  return names;
}

std::vector<Field> IceSolver::outputFields(const std::function<bool(const std::string&)>& wanted) const {
  using core::Centering;
  std::vector<Field> out;
  // Only the wanted fields are built (a field per owned cell each: all of them at once were the
  // run's largest allocation).
  auto want = [&](const std::string& n) { return !wanted || wanted(n); };
  auto add = [&](const std::string& n, int nc, auto&& value) {
    if (!want(n)) return;
    Field f(n, Centering::Cell, owned_, nc, 0);
    forEach(owned_, [&](int i, int j, int k) { value(f, i, j, k); });
    out.push_back(std::move(f));
  };
  add("pressure", 1, [&](Field& f, int i, int j, int k) { f(i, j, k) = st_.press(i, j, k); });
  const core::Box& sb = st_.press.box();
  if (!st_.iters.empty())  // kept where the output writes them (ice_state.h)
    add("pressure_iterations", 1, [&](Field& f, int i, int j, int k) {
      f(i, j, k) = st_.iters[static_cast<std::size_t>(sb.index(i, j, k))];
    });
  const double V = mesh_.cellVolume();
  for (const MaterialState& m : st_.mat) {
    add(m.name + "_density", 1, [&](Field& f, int i, int j, int k) { f(i, j, k) = m.mass(i, j, k) / V; });
    add(m.name + "_velocity", 3, [&](Field& f, int i, int j, int k) {
      for (int d = 0; d < m.vel.ncomp(); ++d) f(i, j, k, d) = m.vel(i, j, k, d);  // beyond: 0
    });
    add(m.name + "_temperature", 1, [&](Field& f, int i, int j, int k) {
      f(i, j, k) = m.eos->temperature(1.0 / m.spvol(i, j, k), m.eint(i, j, k));
    });
    add(m.name + "_volume_fraction", 1, [&](Field& f, int i, int j, int k) { f(i, j, k) = m.theta(i, j, k); });
  }
  return out;
}

}  // namespace mpmice::ice
