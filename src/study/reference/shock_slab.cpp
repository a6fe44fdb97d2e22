#include "study/reference/shock_slab.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "core/io/output_reader.h"
#include "study/reference/output_files.h"

namespace mpmice::study {

namespace {
const core::RegionSpec& regionNamed(const core::Scene& s, const std::string& name) {
  for (const auto& r : s.geometry)
    if (r.name == name) return r;
  throw std::runtime_error(s.file + ": no region '" + name + "' (the shock on a slab needs shocked, quiet, slab)");
}
}  // namespace

SlabExact slabExact(const core::Scene& s) {
  SlabExact e;
  const auto& shocked = regionNamed(s, "shocked");
  const auto& quiet = regionNamed(s, "quiet");
  const auto& slab = regionNamed(s, "slab");
  const core::MaterialSpec& gas = *s.material(quiet.fill.at(0).material);
  const core::MaterialSpec& solid = *s.material(slab.fill.at(0).material);
  if (gas.eos.type != "ideal_gas") throw std::runtime_error(s.file + ": the shock on a slab needs an ideal gas");
  if (!shocked.pressure || !shocked.density || !quiet.pressure)
    throw std::runtime_error(s.file + ": regions shocked (pressure, density) and quiet (pressure) must give their state");
  e.gas = gas.name;
  e.gamma = gas.eos.get("gamma");
  const double g = e.gamma, R = (g - 1) * gas.specific_heat;
  e.p1 = *quiet.pressure;
  const double rho1 = e.p1 / (R * quiet.temperature);
  e.p2 = *shocked.pressure;
  const double rho2 = *shocked.density, u2 = shocked.velocity[0];
  e.W = rho2 * u2 / (rho2 - rho1);  // mass conservation across the incident shock
  e.xShock = shocked.shape.hi[0];
  e.xWall = slab.shape.lo[0];
  // Reflected shock into state 2 bringing the gas to rest: u2 = (p5 - p2) sqrt(A / (p5 + B)).
  const double A = 2 / ((g + 1) * rho2), B = (g - 1) / (g + 1) * e.p2;
  double lo = e.p2, hi = 1e3 * e.p2;
  for (int k = 0; k < 200; ++k) {
    const double m = 0.5 * (lo + hi);
    ((m - e.p2) * std::sqrt(A / (m + B)) < u2 ? lo : hi) = m;
  }
  e.p5 = 0.5 * (lo + hi);
  const double r = e.p5 / e.p2;
  const double rho5 = rho2 * ((g + 1) * r + (g - 1)) / ((g - 1) * r + (g + 1));
  e.Wr = rho2 * u2 / (rho5 - rho2);
  const double K = solid.constitutive.get("bulk_modulus"), G = solid.constitutive.get("shear_modulus");
  e.cSolid = std::sqrt((K + 4 * G / 3) / solid.density);
  return e;
}

Plateau reflectedPlateau(const SlabExact& e, double t, double dx, const double* x, const double* p,
                         const double* theta, int n) {
  const double xr = e.xWall - e.Wr * (t - e.hitTime());
  Plateau out;
  double sum = 0;
  out.min = std::numeric_limits<double>::max();
  for (int i = 0; i < n; ++i) {
    if (x[i] < xr + 0.25 * (e.xWall - xr) || x[i] > e.xWall - 2 * dx || theta[i] < 0.999) continue;
    sum += p[i];
    out.min = std::min(out.min, p[i]);
    out.max = std::max(out.max, p[i]);
    ++out.cells;
  }
  out.mean = out.cells > 0 ? sum / out.cells : 0;
  return out;
}

double slabPressureError(const std::string& dir, const std::string& scene, const std::string& sceneFile) {
  const SlabExact e = slabExact(core::loadScene(sceneFile));
  const LastOutput files = lastOutput(dir, scene);
  const core::OutputReader grid(files.grid);
  const auto mesh = grid.mesh();
  const auto p = grid.readGridField(core::Centering::Cell, "pressure");
  const auto theta = grid.readGridField(core::Centering::Cell, e.gas + "_volume_fraction");
  const int n = mesh.cells()[0];
  std::vector<double> x(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) x[static_cast<std::size_t>(i)] = mesh.cellCenter(0, i);
  const Plateau pl = reflectedPlateau(e, grid.time(), mesh.dx(0), x.data(), p.values.data(), theta.values.data(), n);
  if (pl.cells < 6)
    throw std::runtime_error(files.grid + ": the reflected plateau is " + std::to_string(pl.cells) +
                             " pure-gas cells wide at t = " + std::to_string(grid.time()) + " (6 needed)");
  return std::abs(pl.mean / e.p5 - 1);
}

}  // namespace mpmice::study
