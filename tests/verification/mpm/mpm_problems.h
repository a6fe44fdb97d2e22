#pragma once
/// @brief The MPM verification problems (benchmarks.md) as scenes built in C++, with their exact
/// solutions and error measures; shared by tests/verification/mpm and benchmarks/mpm.
///
///   vibrating bar   plane strain, roller sides, fixed at x = 0: centre-of-mass velocity error
///   Lame cylinder   quarter annulus under internal pressure, damped to rest: Eq. 13 error
///   colliding disks Sulsky's two elastic disks: kinetic + strain energy over the collision
/// Same values as configs/mpm_vibrating_bar.yaml, mpm_lame_cylinder.yaml, mpm_colliding_disks.yaml.
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "core/scene/scene.h"
#include "../../support/observed_order.h"  // also built into benchmarks/mpm
#include "mpm/solver/mpm_solver.h"

namespace mpmice::mpm::problems {

inline core::ModelSpec elastic(const std::string& type, double E, double nu) {
  core::ModelSpec m;
  m.type = type;
  m.params = {{"youngs_modulus", E}, {"poissons_ratio", nu},
              {"bulk_modulus", E / (3 * (1 - 2 * nu))}, {"shear_modulus", E / (2 * (1 + nu))}};
  return m;
}

inline core::MaterialSpec solid(const std::string& name, double rho, core::ModelSpec model) {
  core::MaterialSpec m;
  m.name = name;
  m.kind = core::MaterialKind::Solid;
  m.density = rho;
  m.constitutive = std::move(model);
  return m;
}

inline core::RegionSpec region(const std::string& name, core::ShapeSpec shape,
                               const std::string& material, core::IntVect ppc) {
  core::RegionSpec r;
  r.name = name;
  r.shape = std::move(shape);
  r.fill = {{material, 1.0}};
  r.particles_per_cell = ppc;
  return r;
}

// ---- vibrating bar --------------------------------------------------------------------------
struct Bar {
  double L = 25, E = 100, rho = 1, v0 = 0.1;
  [[nodiscard]] double beta() const { return std::numbers::pi / (2 * L); }
  [[nodiscard]] double omega() const { return beta() * std::sqrt(E / rho); }
  [[nodiscard]] double period() const { return 2 * std::numbers::pi / omega(); }
  [[nodiscard]] double vcm(double t) const { return 2 * v0 / std::numbers::pi * std::cos(omega() * t); }
};

/// A small elastic block (1000 kg/m^3, E 1 MPa) at rest in an 8 x 8 box of no-slip walls, 2 x 3
/// particles per cell (the unit tests' solver).
inline core::Scene smallBlock() {
  core::Scene s;
  s.mesh = core::Mesh(2, {0, 0, 0}, {0.25, 0.25, 1}, {8, 8, 1});
  for (auto& f : s.boundary) f.type = core::BoundaryType::NoSlipWall;
  s.materials = {solid("block", 1000, elastic("linear_elastic", 1e6, 0.25))};
  core::ShapeSpec box;
  box.type = "box";
  box.lo = {0.5, 0.5, 0};
  box.hi = {1.5, 1.0, 0};
  s.geometry = {region("block", box, "block", {2, 3, 1})};
  return s;
}

/// Bar of `cells` cells along its length (2 more cells of free space beyond x = L), one cell
/// across with roller sides; dim 2 or 3.
inline core::Scene barScene(int cells, const std::string& shape, const std::string& update = "usl",
                            int dim = 2, double cfl = 0.2) {
  Bar b;
  const double h = b.L / cells;
  core::Scene s;
  s.name = "mpm_vibrating_bar";
  s.mesh = core::Mesh(dim, {0, 0, 0}, {h, h, dim == 3 ? h : 1.0}, {cells + 2, 1, 1});
  for (auto& f : s.boundary) f.type = core::BoundaryType::Symmetry;
  s.boundary[0].type = core::BoundaryType::NoSlipWall;
  s.boundary[1].type = core::BoundaryType::Free;
  s.time.cfl = cfl;
  s.time.end = b.period();
  s.materials = {solid("bar", b.rho, elastic("linear_elastic", b.E, 0.0))};
  core::ShapeSpec box;
  box.type = "box";
  box.lo = {0, 0, 0};
  box.hi = {b.L, h, dim == 3 ? h : 0};
  s.geometry = {region("bar", box, "bar", {2, 2, 2})};
  s.mpm.shape_function = shape;
  s.mpm.update = update;
  return s;
}

/// Sets v = v0 sin(beta x) on every particle (the bar's initial state).
inline void initBar(MpmSolver& solver) {
  Bar b;
  auto& p = solver.particles();
  for (std::size_t i = 0; i < p.size(); ++i) p.v[0][i] = b.v0 * std::sin(b.beta() * p.x[0][i]);
}

struct BarResult {
  double error = 0;        // max_t |v_cm - exact| / (2 v0 / pi)
  double energyDrift = 0;  // max_t |E(t) - E(0)| / E(0)
  long steps = 0;
  long long particles = 0;
};

inline BarResult runBar(const core::Scene& s, const core::Comm& comm) {
  Bar b;
  MpmSolver solver(s, comm);
  initBar(solver);
  BarResult r;
  r.particles = solver.globalParticleCount();
  const double e0 = solver.energies().total();
  auto sample = [&] {
    const double err = std::fabs(solver.centerOfMassVelocity()[0] - b.vcm(solver.time())) /
                       (2 * b.v0 / std::numbers::pi);
    r.error = std::max(r.error, err);
    r.energyDrift = std::max(r.energyDrift, std::fabs(solver.energies().total() - e0) / e0);
  };
  sample();
  while (solver.time() < s.time.end * (1 - 1e-12)) {
    solver.advance(s.time.end);
    sample();
  }
  r.steps = solver.stepCount();
  return r;
}

// ---- Lame cylinder ---------------------------------------------------------------------------
struct Lame {
  double ri = 0.5, ro = 1.0, P = 19.4e6, K = 117.0e9, G = 43.8e9, rho = 8900;
  [[nodiscard]] double sumExact() const { return 2 * P * ri * ri / (ro * ro - ri * ri); }
};

/// Quarter annulus on [0, 1.2]^2 with spacing dx, 2x2 particles per cell, pressure ramped over
/// `ramp` seconds on the inner particle layer, then held to `end`; damping `damping` 1/s.
/// Defaults: the quasi-static state converged in time (docs/mpm.md: hold to 2.5 ms with 5000 1/s
/// left 5 % of the dx = 0.00625 error in the residual motion; 4 ms with 10^4 1/s changes the
/// result by < 1 % more when held to 6 ms).
inline core::Scene lameScene(double dx, const std::string& shape, double ramp = 1.0e-3,
                             double end = 4.0e-3, double damping = 1.0e4, int ppc = 2) {
  Lame l;
  core::Scene s;
  s.name = "mpm_lame_cylinder";
  const int n = static_cast<int>(std::lround(1.2 / dx));
  s.mesh = core::Mesh(2, {0, 0, 0}, {dx, dx, 1}, {n, n, 1});
  for (auto& f : s.boundary) f.type = core::BoundaryType::Free;
  s.boundary[0].type = core::BoundaryType::Symmetry;
  s.boundary[2].type = core::BoundaryType::Symmetry;
  s.time.cfl = 0.4;
  s.time.end = end;
  core::ModelSpec m;
  m.type = "linear_elastic";
  m.params = {{"bulk_modulus", l.K}, {"shear_modulus", l.G},
              {"youngs_modulus", 9 * l.K * l.G / (3 * l.K + l.G)},
              {"poissons_ratio", (3 * l.K - 2 * l.G) / (2 * (3 * l.K + l.G))}};
  s.materials = {solid("steel", l.rho, m)};
  core::ShapeSpec ann;
  ann.type = "annulus";
  ann.inner_radius = l.ri;
  ann.outer_radius = l.ro;
  s.geometry = {region("cylinder", ann, "steel", {ppc, ppc, 1})};
  core::LoadSpec load;
  load.type = core::LoadType::Pressure;
  load.material = "steel";
  load.shape = ann;
  load.shape.outer_radius = l.ri + dx / ppc;  // the inner particle layer
  load.pressure = l.P;
  load.ramp = ramp;
  s.loads = {load};
  s.mpm.shape_function = shape;
  s.mpm.damping = damping;
  return s;
}

/// Eq. 13: particle average of |(s_r + s_t) - 2P/3| / (2P/3); s_r + s_t = s_xx + s_yy.
inline double lameError(const MpmSolver& solver) {
  Lame l;
  const auto& p = solver.particles();
  double sum = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    sum += std::fabs(p.stress[kXX][i] + p.stress[kYY][i] - l.sumExact()) / l.sumExact();
  const double n = static_cast<double>(solver.globalParticleCount());
  return solver.comm().sum(sum) / n;
}

struct LameResult {
  double error = 0;
  long steps = 0;
  long long particles = 0;
};

inline LameResult runLame(const core::Scene& s, const core::Comm& comm) {
  MpmSolver solver(s, comm);
  while (solver.time() < s.time.end * (1 - 1e-12)) solver.advance(s.time.end);
  return {lameError(solver), solver.stepCount(), solver.globalParticleCount()};
}

// ---- colliding disks -------------------------------------------------------------------------
inline core::Scene disksScene(int cells, const std::string& update, double flip,
                              const std::string& shape = "linear", double end = 3.0) {
  core::Scene s;
  s.name = "mpm_colliding_disks";
  const double h = 1.0 / cells;
  s.mesh = core::Mesh(2, {0, 0, 0}, {h, h, 1}, {cells, cells, 1});
  for (auto& f : s.boundary) f.type = core::BoundaryType::NoSlipWall;
  s.time.cfl = 0.2;
  s.time.end = end;
  s.materials = {solid("disk", 1000, elastic("linear_elastic", 1000, 0.3))};
  core::ShapeSpec c1, c2;
  c1.type = c2.type = "sphere";
  c1.radius = c2.radius = 0.2;
  c1.center = {0.25, 0.25, 0};
  c2.center = {0.75, 0.75, 0};
  auto r1 = region("disk1", c1, "disk", {2, 2, 1});
  auto r2 = region("disk2", c2, "disk", {2, 2, 1});
  r1.velocity = {0.1, 0.1, 0};
  r2.velocity = {-0.1, -0.1, 0};
  s.geometry = {r1, r2};
  s.mpm.update = update;
  s.mpm.flip = flip;
  s.mpm.shape_function = shape;
  return s;
}

struct EnergySample {
  double t, kinetic, strain;
};

inline std::vector<EnergySample> runDisks(const core::Scene& s, const core::Comm& comm) {
  MpmSolver solver(s, comm);
  std::vector<EnergySample> out;
  auto e = solver.energies();
  out.push_back({0, e.kinetic, e.strain});
  while (solver.time() < s.time.end * (1 - 1e-12)) {
    solver.advance(s.time.end);
    e = solver.energies();
    out.push_back({solver.time(), e.kinetic, e.strain});
  }
  return out;
}

/// Observed order from errors at spacings h (tests/support/observed_order.h).
using mpmice::test::observedOrder;

}  // namespace mpmice::mpm::problems
