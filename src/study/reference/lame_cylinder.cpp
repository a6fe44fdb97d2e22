#include "study/reference/lame_cylinder.h"

#include <cmath>
#include <stdexcept>

#include "core/io/output_reader.h"
#include "core/scene/scene.h"

namespace mpmice::study {

using core::Centering;
using core::OutputReader;

Annulus annulusFromScene(const std::string& file) { return annulusOf(core::loadScene(file), file); }

Annulus annulusOf(const core::Scene& s, const std::string& file) {
  Annulus a;
  a.fromScene = true;
  int solid = -1;
  for (const auto& r : s.geometry)
    for (const auto& f : r.fill)
      if (s.material(f.material)->kind == core::MaterialKind::Solid && r.shape.type == "annulus") {
        a.ri = r.shape.inner_radius;
        a.ro = r.shape.outer_radius;
        solid = s.materialIndex(f.material);
      }
  if (solid < 0) throw std::runtime_error(file + ": no solid annulus in the geometry");
  a.fluids.clear();
  for (const auto& m : s.materials)
    if (m.kind == core::MaterialKind::Fluid) a.fluids.push_back(m.name);
  a.pRef = s.materials[static_cast<std::size_t>(solid)].eos.get("threshold_pressure", 101325.0);
  a.pAmbient = -1;
  for (const auto& b : s.boundary)
    if (b.type == core::BoundaryType::Outflow && b.pressure) a.pAmbient = *b.pressure;
  if (a.pAmbient < 0)
    for (const auto& r : s.geometry)
      if (r.shape.type != "annulus" && s.material(r.fill.at(0).material)->kind == core::MaterialKind::Fluid &&
          r.pressure)
        a.pAmbient = *r.pressure;
  if (a.pAmbient < 0) throw std::runtime_error(file + ": no outflow boundary or fluid region gives the ambient pressure");
  return a;
}

double lameSum(const Annulus& a, double P) {
  return 2 * ((P - a.pRef) * a.ri * a.ri - (a.pAmbient - a.pRef) * a.ro * a.ro) / (a.ro * a.ro - a.ri * a.ri);
}

LameError lameError(const std::string& dir, const std::string& scene, const Annulus& geo) {
  const double kRi = geo.ri, kRo = geo.ro;
  const LastOutput files = lastOutput(dir, scene);
  const OutputReader pr(files.particles), gr(files.grid);
  LameError r;
  r.particlesFile = files.particles;
  r.step = pr.step();
  r.time = pr.time();
  // P: mean pressure of the cells well inside the inner radius.
  const auto mesh = gr.mesh();
  r.dx = mesh.dx(0);
  const auto p = gr.readGridField(Centering::Cell, "pressure");
  double psum = 0;
  long pn = 0;
  for (int j = 0; j < mesh.cells()[1]; ++j)
    for (int i = 0; i < mesh.cells()[0]; ++i)
      if (std::hypot(mesh.cellCenter(0, i), mesh.cellCenter(1, j)) < 0.8 * kRi) {
        psum += p.values[static_cast<std::size_t>(i + mesh.cells()[0] * j)];
        ++pn;
      }
  if (pn == 0) throw std::runtime_error(files.grid + ": no cell inside 0.8 r_i to measure the pressure");
  r.P = psum / double(pn);
  // Lame: sigma_r = A - B / r^2, sigma_theta = A + B / r^2 (from the stress-free reference).
  r.A = 0.5 * lameSum(geo, r.P);
  r.B = (r.P - geo.pAmbient) * kRi * kRi * kRo * kRo / (kRo * kRo - kRi * kRi);
  r.sum = 2 * r.A;
  // Particles.
  const auto x = pr.readParticleArray("position"), s = pr.readParticleArray("stress");
  const auto n = static_cast<std::size_t>(x.shape[0]);
  const auto sc = static_cast<std::size_t>(s.shape.size() > 1 ? s.shape[1] : 1);
  r.particles = n;
  r.stressComponents = sc;
  // The error by band: particles within one cell of either surface, and the interior.
  double err = 0;
  for (std::size_t q = 0; q < n; ++q) {
    const double e = std::abs(s.values[sc * q] + s.values[sc * q + 1] - r.sum) / r.sum;
    const double rad = std::hypot(x.values[3 * q], x.values[3 * q + 1]);
    err += e;
    if (rad < kRi + mesh.dx(0) || rad > kRo - mesh.dx(0)) {
      r.bandError += e;
      ++r.bandParticles;
    } else {
      r.coreError += e;
    }
  }
  r.error = err / double(n);
  r.x = x.values;
  r.stress = s.values;
  return r;
}

namespace {
/// The fluids' mass of one output step inside r_i and in the wall's cells.
void fluidMassByRegion(const std::string& file, const Annulus& geo, double& inside, double& wall) {
  const OutputReader r(file);
  const auto mesh = r.mesh();
  const double V = mesh.cellVolume();
  const int nx = mesh.cells()[0], ny = mesh.cells()[1];
  inside = wall = 0;
  long nInside = 0;
  for (const std::string& fluid : geo.fluids) {
    if (!r.hasGridField(Centering::Cell, fluid + "_density"))
      throw std::runtime_error(file + ": no cell field '" + fluid + "_density' (the fluid's mass per cell volume)");
    const auto rho = r.readGridField(Centering::Cell, fluid + "_density");  // mass / cell volume
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const double rad = std::hypot(mesh.cellCenter(0, i), mesh.cellCenter(1, j));
        const double m = rho.values[static_cast<std::size_t>(i + nx * j)] * V;
        if (rad < geo.ri) {
          inside += m;
          ++nInside;
        } else if (rad < geo.ro) {
          wall += m;
        }
      }
  }
  if (nInside == 0) throw std::runtime_error(file + ": no cell centre inside r_i to measure the gas leak");
}
}  // namespace

GasLeak gasLeak(const std::string& dir, const std::string& scene, const Annulus& geo) {
  const OutputSpan files = outputSpan(dir, scene);
  if (files.firstGrid.empty()) throw std::runtime_error("no fluid output of scene '" + scene + "' in " + dir);
  GasLeak g;
  g.firstGrid = files.firstGrid;
  g.lastGrid = files.last.grid;
  {
    const OutputReader first(files.firstGrid), last(files.last.grid);
    g.firstStep = first.step();
    g.firstTime = first.time();
    g.lastStep = last.step();
    g.lastTime = last.time();
  }
  fluidMassByRegion(files.firstGrid, geo, g.inside0, g.wall0);
  fluidMassByRegion(files.last.grid, geo, g.inside, g.wall);
  return g;
}

}  // namespace mpmice::study
