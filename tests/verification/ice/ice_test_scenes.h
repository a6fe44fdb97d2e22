#pragma once
// Scenes of the ICE tests, built in C++ (the same shape a scene file gives).
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "riemann_exact.h"
#include "core/scene/scene.h"
#include "ice/solver/ice_solver.h"

namespace mpmice::test {

/// An EOS (or other model) spec: type and parameters.
inline core::ModelSpec modelSpec(const std::string& type, std::map<std::string, double> params) {
  core::ModelSpec s;
  s.type = type;
  s.params = std::move(params);
  return s;
}

inline core::MaterialSpec idealGas(const std::string& name, double gamma = 1.4, double cv = 717.5) {
  core::MaterialSpec m;
  m.name = name;
  m.eos.type = "ideal_gas";
  m.eos.params = {{"gamma", gamma}};
  m.specific_heat = cv;
  return m;
}

inline core::MaterialSpec stiffenedGas(const std::string& name, double gamma, double pinf, double cv = 4186.0) {
  core::MaterialSpec m;
  m.name = name;
  m.eos.type = "stiffened_gas";
  m.eos.params = {{"gamma", gamma}, {"p_inf", pinf}};
  m.specific_heat = cv;
  return m;
}

/// Steel as ICE sees a solid: an external material with the solid_bulk EOS (K = 117 GPa,
/// threshold 101325 Pa, rho0 = 8900 kg/m^3, cv = 450 J/kg/K).
inline core::MaterialSpec externalSteel() {
  core::MaterialSpec steel;
  steel.name = "steel";
  steel.kind = core::MaterialKind::Solid;
  steel.eos.type = "solid_bulk";
  steel.eos.params = {{"bulk_modulus", 117e9}, {"threshold_pressure", 101325}, {"reference_density", 8900}};
  steel.specific_heat = 450;
  return steel;
}

inline core::ShapeSpec box(core::RealVect lo, core::RealVect hi) {
  core::ShapeSpec s;
  s.type = "box";
  s.lo = lo;
  s.hi = hi;
  return s;
}

inline core::RegionSpec region(const std::string& name, core::ShapeSpec shape, std::vector<core::FillSpec> fill,
                               double p, double rho, core::RealVect u = {0, 0, 0}) {
  core::RegionSpec r;
  r.name = name;
  r.shape = shape;
  r.fill = std::move(fill);
  r.pressure = p;
  r.density = rho;
  r.velocity = u;
  return r;
}

struct TubeOptions {
  std::string advection = "second_order", pressure = "explicit", limiter = "van_leer", facePressure = "riemann";
  std::string equilibrium = "fixed_energy";  // ice.equilibrium
  double cfl = 0.4;
  double semiTheta = 1.0;  // ice.semi_implicit_theta
};

/// A 1D shock tube on [0, 1] with n cells, one ideal gas, states L | R at x0.
inline core::Scene shockTube(int n, Primitive L, Primitive R, double x0, double tEnd, TubeOptions o = {},
                             double gamma = 1.4) {
  core::Scene s;
  s.name = "shock_tube";
  s.mesh = core::Mesh(1, {0, 0, 0}, {1.0 / n, 1, 1}, {n, 1, 1});
  for (auto& b : s.boundary) b.type = core::BoundaryType::Outflow;
  s.time.end = tEnd;
  s.time.cfl = o.cfl;
  s.materials = {idealGas("gas", gamma)};
  s.geometry = {region("left", box({0, 0, 0}, {1, 1, 1}), {{"gas", 1.0}}, L.p, L.rho, {L.u, 0, 0}),
                region("right", box({x0, -1, -1}, {2, 2, 2}), {{"gas", 1.0}}, R.p, R.rho, {R.u, 0, 0})};
  s.ice.advection = o.advection;
  s.ice.pressure_solver = o.pressure;
  s.ice.limiter = o.limiter;
  s.ice.face_pressure = o.facePressure;
  s.ice.equilibrium = o.equilibrium;
  s.ice.semi_implicit_theta = o.semiTheta;
  return s;
}

/// Runs to the scene's end time.
inline void runToEnd(ice::IceSolver& s, double tEnd, long maxSteps = 10000000) {
  while (s.time() < tEnd * (1 - 1e-12) && s.steps() < maxSteps) s.step();
}

/// L1 error of material m's density (sum over materials when m < 0) against rho(x) on a 1D mesh
/// (owned cells; sums over ranks).
template <class F>
double l1Density(const ice::IceSolver& s, F&& exact, int m = -1) {
  double err = 0;
  const auto& mesh = s.mesh();
  core::forEach(s.ownedBox(), [&](int i, int j, int k) {
    double rho = 0;
    for (int r = 0; r < s.numMaterials(); ++r)
      if (m < 0 || r == m) rho += s.density(r, i, j, k);
    err += std::abs(rho - exact(mesh.cellCenter(0, i))) * mesh.dx(0);
  });
  return s.comm().sum(err);
}

}  // namespace mpmice::test
