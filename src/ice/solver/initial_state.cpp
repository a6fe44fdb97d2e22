// IceSolver::initialize: materials, options, the initial state from the scene's regions, boundary
// states and energy sources. Every bad input is a std::invalid_argument naming the scene key.
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "ice/advection/limiter.h"
#include "ice/exchange/pointwise_exchange.h"
#include "ice/ice_constants.h"
#include "ice/solver/ice_solver.h"

namespace mpmice::ice {

namespace {

std::string num(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

[[noreturn]] void bad(const core::SourceLoc& where, const std::string& msg) {
  throw std::invalid_argument((where.line ? where.str() + ": " : std::string()) + msg);
}

/// Material density and specific energy of material `eos` from a state (pressure, temperature,
/// optional density).
void resolveState(const Eos& eos, double p, double T, std::optional<double> rho, double* rhoOut, double* eOut) {
  if (rho) {
    *rhoOut = *rho;
    *eOut = eos.internalEnergy(*rho, p);
  } else {
    *rhoOut = eos.densityFromPT(p, T);
    *eOut = eos.energyFromTemperature(*rhoOut, T);
  }
}

}  // namespace

void IceSolver::initialize(const core::Scene& scene) {
  const int dim = mesh_.dim();
  owned_ = decomp_.cellBox(comm_.rank());
  const core::Box stored = decomp_.storedBox(comm_.rank(), core::Centering::Cell, kGhost);
  ghosts_ = std::make_unique<core::GhostExchange>(decomp_, comm_, core::Centering::Cell, kGhost);
  initialPressure_ = core::Field("initial_pressure", core::Centering::Cell, owned_, 1, 0);

  // ---- options
  const core::IceOptions& o = scene.ice;
  if (o.advection != "first_order" && o.advection != "second_order")
    throw std::invalid_argument("ice.advection: unknown value '" + o.advection + "'; valid: first_order, second_order");
  secondOrder_ = o.advection == "second_order";
  limiter_ = static_cast<int>(limiterFromName(o.limiter));
  if (o.pressure_solver != "explicit" && o.pressure_solver != "semi_implicit")
    throw std::invalid_argument("ice.pressure_solver: unknown value '" + o.pressure_solver +
                                "'; valid: explicit, semi_implicit");
  semiImplicit_ = o.pressure_solver == "semi_implicit";
  q1_ = o.shock_viscosity_linear;
  q2_ = o.shock_viscosity_quadratic;
  if (o.linear_solver == "cg") linearSolver_ = LinearSolver::Cg;
  else if (o.linear_solver == "bicgstab") linearSolver_ = LinearSolver::Bicgstab;
  else if (o.linear_solver == "pfmg_pcg") linearSolver_ = LinearSolver::PfmgPcg;
  else if (o.linear_solver == "smg_pcg") linearSolver_ = LinearSolver::SmgPcg;
  else
    throw std::invalid_argument("ice.linear_solver: unknown value '" + o.linear_solver +
                                "'; valid: cg, bicgstab, pfmg_pcg, smg_pcg");
  linearSolverName_ = o.linear_solver;
  if (semiImplicit_ && linearSolver_ == LinearSolver::Bicgstab && comm_.size() > 1)
    throw std::invalid_argument("ice.linear_solver: bicgstab (Eigen, assembled) runs on one rank; use cg in parallel");
  solverTol_ = o.solver_tolerance;
  solverMaxIt_ = o.solver_max_iterations;
  cfl_ = scene.time.cfl;
  tEnd_ = scene.time.end;
  dtMax_ = scene.time.dt_max;
  dtMin_ = scene.time.dt_min;
  collapse_ = core::StepCollapse(scene.time.dt_collapse_fraction);
  gravity_ = scene.gravity;
  anyGravity_ = gravity_[0] != 0 || gravity_[1] != 0 || gravity_[2] != 0;

  // ---- materials
  const int nm = static_cast<int>(scene.materials.size());
  if (nm == 0) throw std::invalid_argument("materials: the scene has no material");
  if (nm > kMaxMaterials) throw std::invalid_argument("materials: at most " + std::to_string(kMaxMaterials) + " materials");
  st_.mat.resize(static_cast<std::size_t>(nm));
  std::vector<const Eos*> eos;
  int firstFluid = -1;
  for (int r = 0; r < nm; ++r) {
    const core::MaterialSpec& ms = scene.materials[r];
    MaterialState& m = st_.mat[r];
    m.name = ms.name;
    m.external = ms.kind == core::MaterialKind::Solid;
    if (!m.external && firstFluid < 0) firstFluid = r;
    try {
      m.eos = makeEos(ms.eos, ms.specific_heat);
    } catch (const std::exception& e) {
      bad(ms.eos.where, "materials." + ms.name + ".eos: " + e.what());
    }
    m.viscosity = ms.viscosity;
    m.conductivity = ms.thermal_conductivity;
    anyExternal_ |= m.external;
    anyViscous_ |= !m.external && ms.viscosity > 0;
    anyConduction_ |= !m.external && ms.thermal_conductivity > 0;
    eos.push_back(m.eos.get());
  }
  st_.allocate(owned_, stored, dim);
  equil_ = std::make_unique<EquilibriumPressure>(eos, o.pressure_tolerance, o.max_pressure_iterations);
  forEach(owned_, [&](int i, int j, int k) { ownedCells_.push_back(stored.index(i, j, k)); });

  // ---- exchange coefficients
  K_.assign(static_cast<std::size_t>(nm * nm), o.exchange_momentum);
  H_.assign(static_cast<std::size_t>(nm * nm), o.exchange_heat);
  for (const core::ExchangePair& p : o.exchange_pairs) {
    const int a = scene.materialIndex(p.a), b = scene.materialIndex(p.b);
    if (a < 0 || b < 0) throw std::invalid_argument("ice.exchange_pairs: unknown material '" + (a < 0 ? p.a : p.b) + "'");
    K_[a * nm + b] = K_[b * nm + a] = p.momentum;
    H_[a * nm + b] = H_[b * nm + a] = p.heat;
  }
  for (int r = 0; r < nm; ++r) K_[r * nm + r] = H_[r * nm + r] = 0;
  for (int q = 0; q < nm * nm; ++q) {
    if (K_[q] < 0 || H_[q] < 0) throw std::invalid_argument("ice.exchange: coefficients must be >= 0");
    anyK_ |= K_[q] > 0;
    anyH_ |= H_[q] > 0;
  }

  // ---- regions: validate, then each material's background state (first region that fills it)
  struct Bg {
    bool set = false;
    double rho = 1, e = 1;
  };
  std::vector<Bg> bg(static_cast<std::size_t>(nm));
  std::vector<const core::RegionSpec*> fluidRegions, solidRegions;
  for (const core::RegionSpec& reg : scene.geometry) {
    if (reg.fill.empty()) bad(reg.where, "geometry." + reg.name + ".fill: no material");
    double sum = 0;
    bool fluid = false;
    for (const core::FillSpec& f : reg.fill) {
      const int r = scene.materialIndex(f.material);
      if (r < 0) bad(reg.where, "geometry." + reg.name + ".fill: unknown material '" + f.material + "'");
      if (f.volume_fraction < 0 || f.volume_fraction > 1)
        bad(reg.where, "geometry." + reg.name + ".fill." + f.material + ".volume_fraction = " + num(f.volume_fraction) +
                           " must lie in [0, 1]");
      sum += f.volume_fraction;
      fluid |= !st_.mat[r].external;
    }
    if (!fluid) {
      solidRegions.push_back(&reg);
      continue;
    }
    if (std::abs(sum - 1.0) > 1e-9)
      bad(reg.where, "geometry." + reg.name + ".fill: volume fractions sum to " + num(sum) +
                         "; they must sum to 1 (fix the volume_fraction values)");
    if (!reg.pressure) bad(reg.where, "geometry." + reg.name + ".pressure: required for fluid regions");
    if (!(*reg.pressure > 0))
      bad(reg.where, "geometry." + reg.name + ".pressure = " + num(*reg.pressure) + " must be > 0");
    if (reg.density && !(*reg.density > 0))
      bad(reg.where, "geometry." + reg.name + ".density = " + num(*reg.density) + " must be > 0");
    if (!(reg.temperature > 0))
      bad(reg.where, "geometry." + reg.name + ".temperature = " + num(reg.temperature) + " must be > 0");
    for (const core::FillSpec& f : reg.fill) {
      const int r = scene.materialIndex(f.material);
      if (st_.mat[r].external || bg[r].set) continue;
      resolveState(*st_.mat[r].eos, *reg.pressure, reg.temperature, reg.density, &bg[r].rho, &bg[r].e);
      if (!(bg[r].rho > 0) || !std::isfinite(bg[r].e))
        bad(reg.where, "geometry." + reg.name + ": material '" + f.material + "' has no valid state at p = " +
                           num(*reg.pressure) + ", T = " + num(reg.temperature));
      bg[r].set = true;
    }
    fluidRegions.push_back(&reg);
  }
  for (int r = 0; r < nm; ++r)
    if (!st_.mat[r].external && !bg[r].set) {  // never placed: an absent material at 1 atm, 300 K
      bg[r].rho = st_.mat[r].eos->densityFromPT(kReferencePressure, kReferenceTemperature);
      bg[r].e = st_.mat[r].eos->energyFromTemperature(bg[r].rho, kReferenceTemperature);
      bg[r].set = bg[r].rho > 0;
    }

  // ---- the initial state, cell by cell (later regions override earlier ones)
  const double V = mesh_.cellVolume();
  forEach(owned_, [&](int i, int j, int k) {
    const core::RealVect x{mesh_.cellCenter(0, i), dim > 1 ? mesh_.cellCenter(1, j) : 0.0,
                           dim > 2 ? mesh_.cellCenter(2, k) : 0.0};
    const core::RegionSpec* reg = nullptr;
    for (const core::RegionSpec* rg : fluidRegions)
      if (rg->shape.contains(x, dim)) reg = rg;
    // Cells whose centre lies in a solid object (declared after the fluid region) hold no fluid:
    // the solid's mass arrives through setExternalMaterialState.
    bool inSolid = false;
    for (const core::RegionSpec* rg : solidRegions)
      if (rg->shape.contains(x, dim) && (!reg || rg > reg)) inSolid = true;
    if (!reg && !inSolid && firstFluid >= 0)
      throw std::invalid_argument("geometry: cell " + std::to_string(i) + "," + std::to_string(j) + "," +
                                  std::to_string(k) + " is covered by no fluid region (add a background region)");

    for (int r = 0; r < nm; ++r) {
      MaterialState& m = st_.mat[r];
      for (int d = 0; d < 3; ++d) m.vel(i, j, k, d) = reg ? reg->velocity[d] : 0.0;
      if (m.external) {
        m.mass(i, j, k) = 0;
        m.spvol(i, j, k) = 1.0 / m.eos->densityFromPT(reg ? *reg->pressure : kReferencePressure, kReferenceTemperature);
        m.eint(i, j, k) = m.eos->cv() * kReferenceTemperature;
        continue;
      }
      // A cell inside a solid still holds a trace of each fluid (volume fraction kTraceFraction at
      // the background state): the equilibrium pressure of a cell the solid fills only partly
      // (its surface layer) then has a root, and no fluid has zero mass anywhere.
      double frac = inSolid ? kTraceFraction : 0.0, rho = bg[r].rho, e = bg[r].e;
      if (reg)
        for (const core::FillSpec& f : reg->fill)
          if (f.material == m.name && !inSolid) {
            frac = f.volume_fraction;
            resolveState(*m.eos, *reg->pressure, reg->temperature, reg->density, &rho, &e);
          }
      m.mass(i, j, k) = frac * rho * V;
      m.eint(i, j, k) = e;
      m.spvol(i, j, k) = 1.0 / rho;
      m.theta(i, j, k) = frac;
    }
    st_.press(i, j, k) = reg ? *reg->pressure : fluidRegions.empty() ? kReferencePressure : *fluidRegions.front()->pressure;
    initialPressure_(i, j, k) = st_.press(i, j, k);
  });

  // ---- boundaries
  for (int s = 0; s < 6; ++s) {
    const core::BoundarySpec& b = scene.boundary[s];
    if (b.type != core::BoundaryType::Inflow || s / 2 >= dim) continue;
    InflowState& in = inflow_[s];
    in.material = b.material.empty() ? firstFluid : scene.materialIndex(b.material);
    if (in.material < 0 || st_.mat[in.material].external)
      bad(b.where, std::string("boundary.") + core::boundaryFaceName(s) + ".material: '" + b.material +
                       "' is not a fluid of the scene");
    if (!b.density && !b.pressure)
      bad(b.where, std::string("boundary.") + core::boundaryFaceName(s) + ": inflow needs a density or a pressure");
    const Eos& e = *st_.mat[in.material].eos;
    in.velocity = b.velocity;
    in.fixedPressure = b.pressure.has_value();
    if (b.density && b.pressure) {
      in.rho = *b.density;
      in.p = *b.pressure;
      in.e = e.internalEnergy(in.rho, in.p);
    } else if (b.density) {
      in.rho = *b.density;
      in.e = e.energyFromTemperature(in.rho, b.temperature);
      in.p = e.pressure(in.rho, in.e);
    } else {
      in.p = *b.pressure;
      resolveState(e, in.p, b.temperature, std::nullopt, &in.rho, &in.e);
    }
  }
  bc_ = IceBoundary(scene.boundary, mesh_, owned_, scene.periodic(), inflow_);

  // ---- energy sources
  for (const core::SourceSpec& s : scene.sources) {
    Source src{scene.materialIndex(s.material), s.power_density, s.start, s.end, {}};
    if (src.material < 0 || st_.mat[src.material].external)
      bad(s.where, "sources: '" + s.material + "' is not a fluid of the scene");
    forEach(owned_, [&](int i, int j, int k) {
      const core::RealVect x{mesh_.cellCenter(0, i), dim > 1 ? mesh_.cellCenter(1, j) : 0.0,
                             dim > 2 ? mesh_.cellCenter(2, k) : 0.0};
      if (s.shape.contains(x, dim)) src.cells.push_back(stored.index(i, j, k));
    });
    sources_.push_back(std::move(src));
  }

  fillMaterialGhosts(false);
  computeEquilibriumPressure();
}

}  // namespace mpmice::ice
