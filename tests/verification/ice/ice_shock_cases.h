#pragma once
// Shock-tube cases of the ICE shock verification (Toro's tests 1-5, water against air at the real
// density ratio), run with a chosen ICE setting and measured against the exact Riemann solution:
// L1(rho), the overshoot behind every shock (% of the jump, density and pressure), the velocity
// error at a stationary contact (relative to the fastest wave), whether the run completed (the
// health check after every step, as the programs run it) or stopped with an error.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include "ice_test_scenes.h"
#include "ice/solver/health_check.h"
#include "test_comm.h"

namespace mpmice::test {

struct ShockCase {
  std::string name;
  Primitive L, R;
  GasLaw gl, gr;
  double x0, t;
  bool twoMaterials = false;  // two materials: left | right (each an ideal or stiffened gas by its law)
  std::string leftName = "water", rightName = "air";
};

inline std::vector<ShockCase> toroCases() {
  return {{"sod", {1, 0, 1}, {0.125, 0, 0.1}, {}, {}, 0.5, 0.2},
          {"toro1", {1, 0.75, 1}, {0.125, 0, 0.1}, {}, {}, 0.3, 0.2},
          {"toro2", {1, -2, 0.4}, {1, 2, 0.4}, {}, {}, 0.5, 0.15},
          {"toro3", {1, 0, 1000}, {1, 0, 0.01}, {}, {}, 0.5, 0.012},
          {"toro4", {5.99924, 19.5975, 460.894}, {5.99242, -6.19633, 46.0950}, {}, {}, 0.4, 0.035},
          {"toro5", {1, -19.59745, 1000}, {1, -19.59745, 0.01}, {}, {}, 0.8, 0.012}};
}

/// Water (stiffened gas 4.4 / 6e8, 1000 kg/m^3, 1e9 Pa) against air at 1.2 kg/m^3, 1e5 Pa.
inline ShockCase waterAirRealDensity() {
  return {"water_air", {1000, 0, 1e9}, {1.2, 0, 1e5}, {4.4, 6e8}, {1.4, 0}, 0.7, 2.4e-4, true};
}

/// The water-air case's star state on one side (-1 the water, on its isentrope at p*; +1 the
/// shocked air), moving at u* at p*.
inline Primitive waterAirStar(int side) {
  const ShockCase wa = waterAirRealDensity();
  const ExactRiemann ex(wa.L, wa.R, wa.gl, wa.gr);
  return {ex.rhoStar(side), ex.uStar(), ex.pStar()};
}

// The water-air case taken apart (docs/ice.md "Water-air: start-up or scheme"), each with the
// water-air case's mesh, end time and initial interface:
// water_piston: the water already in its star state drives the air shock as a piston (the exact
//   solution is that contact and shock only);
// moving_contact: both star states, one pressure and one velocity (the contact moving at u*);
// water_fan: the water's rarefaction alone, one material (the water at rest against its star state);
// air_shock: the air shock alone, one material (the shocked air against the air at rest).
inline ShockCase waterPiston() {
  ShockCase c = waterAirRealDensity();
  c.name = "water_piston";
  c.L = waterAirStar(-1);
  return c;
}
inline ShockCase movingContact() {
  ShockCase c = waterPiston();
  c.name = "moving_contact";
  c.R = waterAirStar(1);
  return c;
}
inline ShockCase waterFan() {
  const ShockCase wa = waterAirRealDensity();
  return {"water_fan", wa.L, waterAirStar(-1), wa.gl, wa.gl, wa.x0, wa.t};
}
inline ShockCase airShock() {
  const ShockCase wa = waterAirRealDensity();
  return {"air_shock", waterAirStar(1), wa.R, wa.gr, wa.gr, wa.x0, wa.t};
}

/// Water (the stiffened gas above) at 1e9 Pa against water at 1e5 Pa, both at 1000 kg/m^3: one
/// material, a strong rarefaction at a Mach number of ~0.2 (the explicit step's acoustic limit,
/// kMaxAcousticCourant, binds there above time.cfl 0.7) and a shock.
inline ShockCase waterRarefaction() {
  return {"water_rarefaction", {1000, 0, 1e9}, {1000, 0, 1e5}, {4.4, 6e8}, {4.4, 6e8}, 0.5, 1e-4};
}

/// Neighbours of the suite above (not tuned against): other states and other material pairs,
/// each with its exact solution, run by `ice_shock_sweep --cases neighbours` (docs/ice.md "The
/// neighbours"). The end time puts the fastest wave 0.35 of the tube from the interface.
/// - lax: Lax's shock tube (0.445, 0.698, 3.528 | 0.5, 0, 0.571);
/// - slow_shock: a single Mach 3 shock moving at 0.1 into gas flowing at it (the states of
///   Rankine-Hugoniot, Jin and Liu's slowly moving shock, whose post-shock noise Godunov schemes
///   are known for);
/// - stationary_contact: a density jump 1.4 | 1 at one pressure and at rest (Toro's test 6 states);
/// - air_helium: air at 10 atm and 12 kg/m^3 against helium at 1 atm (gamma 5/3);
/// - gas_water: a gas bubble (ideal, 100 kg/m^3, 1e8 Pa) against water at 1 atm: the shock goes
///   into the water;
/// - water_air_1e7: the water-air case at 1e7 Pa instead of 1e9.
inline std::vector<ShockCase> neighbourCases() {
  auto endTime = [](ShockCase c) {
    const ExactRiemann ex(c.L, c.R, c.gl, c.gr);
    const double cL = std::sqrt(c.gl.gamma * (c.L.p + c.gl.pinf) / c.L.rho);
    const double cR = std::sqrt(c.gr.gamma * (c.R.p + c.gr.pinf) / c.R.rho);
    double s = std::max(std::abs(c.L.u - cL), std::abs(c.R.u + cR));
    for (int side : {-1, 1})
      if (ex.pStar() > (side < 0 ? c.L.p : c.R.p)) s = std::max(s, std::abs(ex.shockSpeed(side)));
    c.t = 0.35 / s;
    return c;
  };
  const double g = 1.4, M = 3, S = 0.1, cR = std::sqrt(g);
  const double rhoL = (g + 1) * M * M / ((g - 1) * M * M + 2), pL = (2 * g * M * M - (g - 1)) / (g + 1);
  const double wR = -M * cR, wL = wR / rhoL;
  std::vector<ShockCase> v = {
      {"lax", {0.445, 0.698, 3.528}, {0.5, 0, 0.571}, {}, {}, 0.5, 0},
      {"slow_shock", {rhoL, wL + S, pL}, {1, wR + S, 1}, {}, {}, 0.3, 1.0},
      {"stationary_contact", {1.4, 0, 1}, {1, 0, 1}, {}, {}, 0.5, 2.0},
      {"air_helium", {12, 0, 1e6}, {0.166, 0, 1e5}, {1.4, 0}, {5.0 / 3.0, 0}, 0.4, 0, true, "air", "helium"},
      {"air_helium_1mat", {12, 0, 1e6}, {0.166, 0, 1e5}, {1.4, 0}, {1.4, 0}, 0.4, 0},
      {"air_helium_2mat_air", {12, 0, 1e6}, {0.166, 0, 1e5}, {1.4, 0}, {1.4, 0}, 0.4, 0, true, "air", "helium"},
      {"gas_water", {100, 0, 1e8}, {1000, 0, 1e5}, {1.4, 0}, {4.4, 6e8}, 0.3, 0, true, "gas", "water"},
      {"water_air_1e7", {1000, 0, 1e7}, {1.2, 0, 1e5}, {4.4, 6e8}, {1.4, 0}, 0.5, 0, true}};
  for (ShockCase& c : v)
    if (c.t == 0) c = endTime(c);
  return v;
}

inline core::Scene shockCaseScene(const ShockCase& c, int n, const TubeOptions& o) {
  if (!c.twoMaterials) {
    core::Scene s = shockTube(n, c.L, c.R, c.x0, c.t, o, c.gl.gamma);
    if (c.gl.pinf > 0) s.materials = {stiffenedGas("gas", c.gl.gamma, c.gl.pinf)};  // one law on both sides
    return s;
  }
  core::Scene s;
  s.name = c.name;
  s.mesh = core::Mesh(1, {0, 0, 0}, {1.0 / n, 1, 1}, {n, 1, 1});
  for (auto& b : s.boundary) b.type = core::BoundaryType::Outflow;
  s.time.end = c.t;
  s.time.cfl = o.cfl;
  auto law = [](const std::string& name, const GasLaw& g) {
    return g.pinf > 0 ? stiffenedGas(name, g.gamma, g.pinf) : idealGas(name, g.gamma);
  };
  s.materials = {law(c.leftName, c.gl), law(c.rightName, c.gr)};
  s.geometry = {region(c.leftName, box({0, 0, 0}, {c.x0, 1, 1}), {{c.leftName, 1.0}}, c.L.p, c.L.rho, {c.L.u, 0, 0}),
                region(c.rightName, box({c.x0, -1, -1}, {2, 2, 2}), {{c.rightName, 1.0}}, c.R.p, c.R.rho, {c.R.u, 0, 0})};
  s.ice.advection = o.advection;
  s.ice.pressure_solver = o.pressure;
  s.ice.limiter = o.limiter;
  s.ice.face_pressure = o.facePressure;
  s.ice.equilibrium = o.equilibrium;
  s.ice.semi_implicit_theta = o.semiTheta;
  // ICE_TRACE_MASS_FRACTION (the sweep's --trace-mass-fraction): ice.trace_mass_fraction.
  if (const char* y = std::getenv("ICE_TRACE_MASS_FRACTION")) s.ice.trace_mass_fraction = std::atof(y);
  return s;
}

struct ShockResult {
  bool completed = false;
  std::string error;
  long steps = 0;
  double l1 = 0;                   // L1 of the mixture density
  double overRho = 0, overP = 0;   // the largest overshoot behind any shock, % of the jump
  // Two materials: the shocked material's own density (1 / v) behind its shock, % of its jump, in
  // the window's cells it fills the most of (theta > 1/2). The mixture density above also counts
  // the other material smeared by the contact into the window (water at 100 cells: +27 %).
  double overRhoOwn = 0;
  double contactU = 0;             // max |u - u*| within 5 cells of a stationary contact / fastest wave speed
  double minP = 0;
  double createdShare = 0;         // energy the fallbacks created / total energy (energy_audit.h)
};

/// ICE_SHOCK_T0CELLS=k (runShockCase's exactStartCells where it is not given): start a
/// two-material case from its exact solution.
/// ICE_SHOCK_TRACE="case,from,to,i0,i1": after each step from..to of that case, every material's
/// mass, volume fraction, e, v and u in cells i0..i1 (the water-air analysis in docs/ice.md).
inline void traceCells(const ice::IceSolver& s, const std::string& name) {
  const char* env = std::getenv("ICE_SHOCK_TRACE");
  if (!env) return;
  char which[64] = "";
  long from = 0, to = 0;
  int i0 = 0, i1 = -1;
  if (std::sscanf(env, "%63[^,],%ld,%ld,%d,%d", which, &from, &to, &i0, &i1) != 5 || name != which) return;
  if (s.steps() < from || s.steps() > to) return;
  std::printf("step %ld t %g\n", s.steps(), s.time());
  for (int i = i0; i <= i1; ++i) {
    std::printf("%5d p %+.4e", i, s.pressure()(i, 0, 0));
    for (const auto& M : s.state().mat)
      std::printf(" | %s m %.3e th %.3e e %.4e v %.4e u %+.3e", M.name.c_str(), M.mass(i, 0, 0), M.theta(i, 0, 0),
                  M.eint(i, 0, 0), M.spvol(i, 0, 0), M.vel(i, 0, 0, 0));
    // The pressure increment dp where it is kept (the semi-implicit pressure; the face pressures and
    // volume fluxes hold the advection's mass fluxes after a step: ice_state.h).
    if (s.state().dp.npts() > 0) std::printf(" | dp %+.4e", s.state().dp(i, 0, 0));
    std::printf("\n");
  }
}

/// exactStartCells k > 0 (two materials): start from the exact solution at the time t0 its contact
/// has moved k cells (so it lies on a face), each cell the exact state at its centre, and run to
/// t - t0: what the start-up at a sharp interface adds (docs/ice.md "Water-air: start-up or
/// scheme"); negative: ICE_SHOCK_T0CELLS, else 0 (the case's own start).
inline ShockResult runShockCase(const ShockCase& c, int n, const TubeOptions& o, double exactStartCells = -1) {
  ShockResult r;
  const ExactRiemann ex(c.L, c.R, c.gl, c.gr);
  if (exactStartCells < 0) {
    const char* e0 = std::getenv("ICE_SHOCK_T0CELLS");
    exactStartCells = e0 ? std::atof(e0) : 0.0;
  }
  try {
    ice::IceSolver s(shockCaseScene(c, n, o), comm());
    double t0 = 0;
    if (c.twoMaterials && exactStartCells > 0) {
      const double k = exactStartCells, dxx = 1.0 / n;
      t0 = k * dxx / ex.uStar();
      auto& st = s.state();
      const double V = dxx;
      core::forEach(s.ownedBox(), [&](int i, int, int) {
        const double x = s.mesh().cellCenter(0, i);
        const Primitive q = ex.sample((x - c.x0) / t0);
        const bool water = x < c.x0 + ex.uStar() * t0;
        for (int m = 0; m < 2; ++m) {
          auto& M = st.mat[m];
          const bool on = (m == 0) == water;
          const GasLaw& g = m == 0 ? c.gl : c.gr;
          const double rho = on ? q.rho : (m == 0 ? 1000.0 : 1.2);
          M.mass(i, 0, 0) = on ? rho * V : 0.0;
          M.vel(i, 0, 0, 0) = on ? q.u : 0.0;
          M.spvol(i, 0, 0) = 1.0 / rho;
          M.theta(i, 0, 0) = on ? 1.0 : 0.0;
          M.eint(i, 0, 0) = ((on ? q.p : 1e5) + g.gamma * g.pinf) / ((g.gamma - 1) * rho);
        }
        st.press(i, 0, 0) = q.p;
      });
    }
    while (s.time() < (c.t - t0) * (1 - 1e-12)) {
      s.step();
      traceCells(s, c.name);
      ice::checkHealth(s);
    }
    r.steps = s.steps();
    r.createdShare = s.energyAudit().created / std::abs(s.energyAudit().energy);
    r.l1 = l1Density(s, [&](double x) { return ex.sample((x - c.x0) / c.t).rho; });
    const double dx = 1.0 / n, xc = c.x0 + ex.uStar() * c.t;
    const double cL = std::sqrt(c.gl.gamma * (c.L.p + c.gl.pinf) / c.L.rho);
    const double cR = std::sqrt(c.gr.gamma * (c.R.p + c.gr.pinf) / c.R.rho);
    double speed = std::max(std::abs(c.L.u) + cL, std::abs(c.R.u) + cR);
    for (int side : {-1, 1})
      if (ex.pStar() > (side < 0 ? c.L.p : c.R.p)) speed = std::max(speed, std::abs(ex.shockSpeed(side)));
    const bool stationary = std::abs(ex.uStar()) < 1e-3 * speed;
    r.overRho = r.overP = r.overRhoOwn = -1e300;
    r.minP = 1e300;
    for (int side : {-1, 1}) {
      const Primitive& K = side < 0 ? c.L : c.R;
      if (!(ex.pStar() > K.p * (1 + 1e-9))) continue;  // a rarefaction (or no wave: a single shock's other side)
      const double xs = c.x0 + ex.shockSpeed(side) * c.t;
      const double rPost = ex.rhoStar(side), pPost = ex.pStar();
      double mr = -1e300, mp = -1e300, mo = -1e300;
      const int own = side < 0 ? 0 : s.numMaterials() - 1;  // two materials: water (left) | air (right)
      core::forEach(s.ownedBox(), [&](int i, int j, int k) {
        const double x = s.mesh().cellCenter(0, i);
        // From halfway between contact and shock to 5 cells ahead of the shock.
        const bool in = side > 0 ? (x > 0.5 * (xc + xs) && x < xs + 5 * dx) : (x < 0.5 * (xc + xs) && x > xs - 5 * dx);
        if (!in) return;
        double rho = 0;
        for (int m = 0; m < s.numMaterials(); ++m) rho += s.density(m, i, j, k);
        mr = std::max(mr, rho);
        mp = std::max(mp, s.pressure()(i, j, k));
        if (s.state().mat[own].theta(i, j, k) > 0.5) mo = std::max(mo, 1.0 / s.state().mat[own].spvol(i, j, k));
      });
      r.overRho = std::max(r.overRho, 100 * (mr - rPost) / (rPost - K.rho));
      r.overRhoOwn = std::max(r.overRhoOwn, 100 * (mo - rPost) / (rPost - K.rho));
      r.overP = std::max(r.overP, 100 * (mp - pPost) / (pPost - K.p));
    }
    if (r.overRho < -1e299) r.overRho = r.overP = r.overRhoOwn = 0;  // no shock
    core::forEach(s.ownedBox(), [&](int i, int j, int k) {
      const double x = s.mesh().cellCenter(0, i);
      r.minP = std::min(r.minP, s.pressure()(i, j, k));
      // Within 5 cells of the stationary contact, and more than 3 cells from any shock (at 100
      // cells test 5's slow shock is within one cell of the contact).
      if (!stationary || std::abs(x - xc) >= 5 * dx) return;
      for (int side : {-1, 1})
        if (ex.pStar() > (side < 0 ? c.L.p : c.R.p) && std::abs(x - c.x0 - ex.shockSpeed(side) * c.t) < 3 * dx) return;
      for (int m = 0; m < s.numMaterials(); ++m)
        if (s.state().mat[m].mass(i, j, k) > 0)
          r.contactU = std::max(r.contactU, std::abs(s.state().mat[m].vel(i, j, k, 0) - ex.uStar()) / speed);
    });
    if (const char* dump = std::getenv("ICE_SHOCK_DUMP"); dump && c.name == dump)
      core::forEach(s.ownedBox(), [&](int i, int j, int k) {
        const double x = s.mesh().cellCenter(0, i);
        const Primitive e = ex.sample((x - c.x0) / c.t);
        double rho = 0;
        for (int m = 0; m < s.numMaterials(); ++m) rho += s.density(m, i, j, k);
        std::printf("%g %.6g %.6g %.6g  %.6g %.6g %.6g\n", x, rho, s.state().mat[0].vel(i, j, k, 0), s.pressure()(i, j, k),
                    e.rho, e.u, e.p);
      });
    r.completed = true;
  } catch (const std::exception& e) {
    r.error = e.what();
  }
  return r;
}

/// Least-squares slope of log(err) against log(1 / n).
inline double fittedOrder(const std::vector<int>& n, const std::vector<double>& err) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const int m = static_cast<int>(err.size());
  for (int i = 0; i < m; ++i) {
    const double x = std::log(static_cast<double>(n[static_cast<std::size_t>(i)])), y = std::log(err[static_cast<std::size_t>(i)]);
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  return -(m * sxy - sx * sy) / (m * sxx - sx * sx);
}

}  // namespace mpmice::test
