#include "study/reference/piston.h"

#include <cmath>
#include <stdexcept>

#include "core/io/output_reader.h"
#include "study/reference/output_files.h"

namespace mpmice::study {

using core::Centering;
using core::OutputReader;

PistonSetup pistonSetup(const core::Scene& s) {
  PistonSetup e;
  const core::RegionSpec* piston = nullptr;
  for (const auto& r : s.geometry)
    if (s.material(r.fill.at(0).material)->kind == core::MaterialKind::Solid) piston = &r;
  if (piston == nullptr) throw std::runtime_error(s.file + ": no solid region (the piston)");
  const core::MaterialSpec* gas = nullptr;
  for (const auto& m : s.materials)
    if (m.kind == core::MaterialKind::Fluid) gas = &m;
  if (gas == nullptr || gas->eos.type != "ideal_gas")
    throw std::runtime_error(s.file + ": the piston needs an ideal-gas fluid");
  const core::RegionSpec* gasRegion = nullptr;
  for (const auto& r : s.geometry)
    if (r.pressure && gasRegion == nullptr) gasRegion = &r;
  if (gasRegion == nullptr) throw std::runtime_error(s.file + ": no fluid region gives the gas's pressure");
  e.gas = gas->name;
  e.xLo = piston->shape.lo[0];
  e.xHi = piston->shape.hi[0];
  e.v0 = piston->velocity[0];
  e.hL0 = e.xLo - s.mesh.origin()[0];
  e.h0 = s.mesh.upper(0) - e.xHi;
  e.M = s.material(piston->fill.at(0).material)->density * (e.xHi - e.xLo);
  e.gamma = gas->eos.get("gamma");
  e.p0 = *gasRegion->pressure;
  // The gas's mass per unit area (both columns, at the quiet state), for its inertia below.
  const double rhoGas = gasRegion->density ? *gasRegion->density
                                           : e.p0 / ((e.gamma - 1) * gas->specific_heat * gasRegion->temperature);
  e.gasMass = rhoGas * (e.h0 + e.hL0);
  return e;
}

PistonExact pistonExact(const PistonSetup& e, double t) {
  const auto pR = [&](double s) { return e.p0 * std::pow(e.h0 / (e.h0 - s), e.gamma); };
  const auto pL = [&](double s) { return e.p0 * std::pow(e.hL0 / (e.hL0 + s), e.gamma); };
  // The gas moves with a velocity linear from each wall to the piston (quasi-static): its kinetic
  // energy is that of a third of its mass at the piston's speed (Rayleigh's correction), so the
  // piston accelerates as if it weighed M + m_gas / 3. Against a Lagrangian solution of the gas
  // (docs/stability.md "The density-ratio-10 point") the pressure is within 0.02 % to 20 ms at a
  // density ratio of 10 (without the gas's inertia: 1.74 %), 0.001 % at 100 (0.2 %); at a ratio of
  // 1 it is 0.8 % off (the gas is not quasi-static there; without it, up to 3 %).
  const double Meff = e.M + e.gasMass / 3.0;
  const auto acc = [&](double s) { return -(pR(s) - pL(s)) / Meff; };
  const int n = 20000;
  const double h = t / n;
  double s = 0, v = e.v0;
  for (int k = 0; k < n; ++k) {
    const double k1s = v, k1v = acc(s);
    const double k2s = v + 0.5 * h * k1v, k2v = acc(s + 0.5 * h * k1s);
    const double k3s = v + 0.5 * h * k2v, k3v = acc(s + 0.5 * h * k2s);
    const double k4s = v + h * k3v, k4v = acc(s + h * k3s);
    s += h / 6 * (k1s + 2 * k2s + 2 * k3s + k4s);
    v += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
  }
  return {s, v, pR(s), pL(s)};
}

namespace {
/// The mass-weighted mean particle position along x of one output file.
double meanX(const OutputReader& r) {
  const auto x = r.readParticleArray("position"), m = r.readParticleArray("mass");
  double sum = 0, mass = 0;
  for (std::size_t q = 0; q < m.values.size(); ++q) {
    sum += m.values[q] * x.values[3 * q];
    mass += m.values[q];
  }
  if (mass <= 0) throw std::runtime_error("no particle mass in the output");
  return sum / mass;
}
}  // namespace

PistonError pistonError(const std::string& dir, const std::string& scene, const std::string& sceneFile) {
  const PistonSetup e = pistonSetup(core::loadScene(sceneFile));
  const OutputSpan files = outputSpan(dir, scene);
  const OutputReader first(files.firstParticles), last(files.last.particles), grid(files.last.grid);
  PistonError r;
  r.time = last.time();
  r.s = meanX(last) - meanX(first);
  r.exact = pistonExact(e, r.time);
  const auto mesh = grid.mesh();
  const auto p = grid.readGridField(Centering::Cell, "pressure");
  const auto theta = grid.readGridField(Centering::Cell, e.gas + "_volume_fraction");
  double sum = 0;
  int n = 0;
  for (int i = 0; i < mesh.cells()[0]; ++i)
    if (mesh.cellCenter(0, i) > e.xHi + r.s && theta.values[static_cast<std::size_t>(i)] > 0.999) {
      sum += p.values[static_cast<std::size_t>(i)];
      ++n;
    }
  if (n == 0) throw std::runtime_error(files.last.grid + ": no pure-gas cell ahead of the piston");
  r.p = sum / n;
  r.pressureError = std::abs(r.p / r.exact.p - 1);
  r.displacementError = std::abs(r.s / r.exact.s - 1);
  return r;
}

}  // namespace mpmice::study
