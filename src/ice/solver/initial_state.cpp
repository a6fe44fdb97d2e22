// IceSolver::initialize: materials, options, the initial state from the scene's regions, boundary
// states and energy sources. Every bad input is a std::invalid_argument naming the scene key.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "core/io/output_selection.h"
#include "ice/advection/limiter.h"
#include "ice/exchange/pointwise_exchange.h"
#include "ice/ice_constants.h"
#include "ice/solver/ice_solver.h"
#include "ice/solver/initial_regions.h"
#include "ice/solver/startup_check.h"

namespace mpmice::ice {

void IceSolver::initialize(const core::Scene& scene, bool coupledStart) {
  const int dim = mesh_.dim();
  owned_ = decomp_.cellBox(comm_.rank());
  const core::Box stored = decomp_.storedBox(comm_.rank(), core::Centering::Cell, kGhost);
  ghosts_ = std::make_unique<core::GhostExchange>(decomp_, comm_, core::Centering::Cell, kGhost);
  if (coupledStart) {
    initialPressure_ = core::Field("initial_pressure", core::Centering::Cell, owned_, 1, 0);
    solidCellFluids_.assign(static_cast<std::size_t>(owned_.numPts()), 0u);
  }

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
  soundFraction_ = o.semi_implicit_sound_fraction;
  semiTheta_ = o.semi_implicit_theta;
  stepRamp_ = semiImplicit_ && std::count_if(scene.materials.begin(), scene.materials.end(), [](const core::MaterialSpec& m) {
                return m.kind == core::MaterialKind::Fluid;
              }) >= 2;
  if (o.equilibrium != "fixed_energy" && o.equilibrium != "with_work")
    throw std::invalid_argument("ice.equilibrium: unknown value '" + o.equilibrium + "'; valid: fixed_energy, with_work");
  equilibriumWork_ = o.equilibrium == "with_work";
  q1_ = o.shock_viscosity_linear;
  q2_ = o.shock_viscosity_quadratic;
  if (o.face_pressure != "auto" && o.face_pressure != "riemann" && o.face_pressure != "riemann_low_mach" &&
      o.face_pressure != "average")
    throw std::invalid_argument("ice.face_pressure: unknown value '" + o.face_pressure +
                                "'; valid: auto, riemann, riemann_low_mach, average");
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
  preconditionerReuse_ = o.preconditioner_reuse;
  cfl_ = scene.time.cfl;
  tEnd_ = scene.time.end;
  dtMax_ = scene.time.dt_max;
  dtMin_ = scene.time.dt_min;
  dtInitial_ = scene.time.dt_initial;
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
    m.eos = makeMaterialEos(ms);
    m.viscosity = ms.viscosity;
    m.conductivity = ms.thermal_conductivity;
    anyExternal_ |= m.external;
    anyViscous_ |= !m.external && ms.viscosity > 0;
    anyConduction_ |= !m.external && ms.thermal_conductivity > 0;
    eos.push_back(m.eos.get());
  }
  // auto: the Riemann face pressure for fluids alone; with solids the average, since the Riemann
  // term's acoustic dissipation rho c |du| at every fluid face damps the low-Mach flows and
  // acoustics coupled scenes are mostly about (the added-mass column's period -0.18 -> -1.11 %,
  // its amplitude -10 % per period). A shock scene with solids asks for riemann (configs/shock_slab.yaml).
  riemannFacePressure_ = o.face_pressure == "riemann" || o.face_pressure == "riemann_low_mach" ||
                         (o.face_pressure == "auto" && !anyExternal_);
  riemannLowMach_ = o.face_pressure == "riemann_low_mach";
  for (int r = 0; r < nm; ++r)
    if (semiImplicit_ && st_.mat[r].eos->cavitates())
      badInput(scene.materials[r].cavitation.where,
               "materials." + st_.mat[r].name + ".cavitation: not available with ice.pressure_solver: semi_implicit "
               "(a cavitated cell's infinite compressibility is not in its linear system); use explicit");
  // The per-cell equilibrium iteration counts only where the output writes them.
  const bool keepIterations =
      scene.output.enabled && core::outputSelected(scene.output.fields, "pressure_iterations");
  st_.allocate(owned_, stored, dim, semiImplicit_, keepIterations);
  std::vector<bool> fluid;
  for (const MaterialState& m : st_.mat) fluid.push_back(!m.external);
  equil_ = std::make_unique<EquilibriumPressure>(eos, o.pressure_tolerance, o.max_pressure_iterations, fluid,
                                                 o.trace_mass_fraction);
  ownedCells_ = OwnedCells(owned_, stored);

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
  const RegionPlan plan = planRegions(scene, eos);
  const std::vector<BackgroundState>& bg = plan.background;
  // Each fluid region's state of each material it holds (planRegions resolved it).
  auto stateOf = [&](const core::RegionSpec* reg, int r) -> const BackgroundState& {
    return plan.state[static_cast<std::size_t>(reg - scene.geometry.data())][static_cast<std::size_t>(r)];
  };

  // ---- the initial state, cell by cell: each fluid region's share of the cell (cellShares;
  // later regions override earlier ones point by point) gives each fluid its volume fraction, mass,
  // energy and momentum; the cell's pressure starts at the shares' mean (the equilibrium at the
  // end of initialize() sets it where regions of different pressures share a cell).
  const double V = mesh_.cellVolume();
  std::vector<RegionShare> shares;
  forEach(owned_, [&](int i, int j, int k) {
    const core::RealVect x{mesh_.cellCenter(0, i), dim > 1 ? mesh_.cellCenter(1, j) : 0.0,
                           dim > 2 ? mesh_.cellCenter(2, k) : 0.0};
    const CellCover cover = coverAt(plan, x, dim);
    requireCovered(plan, cover, i, j, k);
    const bool inSolid = cover.inSolid;
    const int ijk[3] = {i, j, k};
    cellShares(plan, mesh_, ijk, cover, &shares);
    const core::RealVect uCentre = cover.fluid ? cover.fluid->velocityAt(x) : core::RealVect{0, 0, 0};

    for (int r = 0; r < nm; ++r) {
      MaterialState& m = st_.mat[r];
      if (m.external) {
        for (int d = 0; d < m.vel.ncomp(); ++d) m.vel(i, j, k, d) = uCentre[static_cast<std::size_t>(d)];
        m.mass(i, j, k) = 0;
        m.spvol(i, j, k) =
            1.0 / m.eos->densityFromPT(cover.fluid ? *cover.fluid->pressure : kReferencePressure, kReferenceTemperature);
        m.eint(i, j, k) = m.eos->cv() * kReferenceTemperature;
        continue;
      }
      if (inSolid) {
        // A cell inside a solid still holds a trace of each fluid (volume fraction kTraceFraction
        // at the background state; the region's fluids at its state): the equilibrium pressure of
        // a cell the solid fills only partly (its surface layer) then has a root, and no fluid has
        // zero mass anywhere. The region's fluids fill the solid's free volume later
        // (fitFluidsToExternalVolume).
        double rho = bg[r].rho, e = bg[r].e;
        if (cover.fluid)
          for (const core::FillSpec& f : cover.fluid->fill)
            if (f.material == m.name) {
              if (coupledStart && f.volume_fraction > 0)
                solidCellFluids_[static_cast<std::size_t>(owned_.index(i, j, k))] |= 1u << r;
              rho = stateOf(cover.fluid, r).rho;
              e = stateOf(cover.fluid, r).e;
            }
        for (int d = 0; d < m.vel.ncomp(); ++d) m.vel(i, j, k, d) = uCentre[static_cast<std::size_t>(d)];
        m.mass(i, j, k) = kTraceFraction * rho * V;
        m.eint(i, j, k) = e;
        m.spvol(i, j, k) = 1.0 / rho;
        m.theta(i, j, k) = kTraceFraction;
        continue;
      }
      // The regions' sums (volume fraction, mass, total energy, momentum); a cell of one region takes
      // its state as it is (bit for bit the whole-cell fill), a shared cell the sums' means: it moves
      // at the mass-weighted velocity, and the kinetic energy that velocity does not carry (regions
      // moving differently) is its internal energy, as when the streams mix; the cell holds the
      // drawn total energy.
      double frac = 0, mass = 0, energy = 0, mom[3] = {0, 0, 0};
      for (const RegionShare& s : shares) {
        if (!s.region) continue;
        for (const core::FillSpec& f : s.region->fill)
          if (f.material == m.name && f.volume_fraction > 0) {
            const BackgroundState& st = stateOf(s.region, r);
            const double vf = s.share * f.volume_fraction, dm = vf * st.rho * V;
            const core::RealVect u = s.region == cover.fluid ? uCentre : s.region->velocityAt(x);
            frac += vf;
            mass += dm;
            energy += dm * (st.e + 0.5 * (u[0] * u[0] + u[1] * u[1] + u[2] * u[2]));
            for (int d = 0; d < 3; ++d) mom[d] += dm * u[static_cast<std::size_t>(d)];
          }
      }
      core::RealVect u = uCentre;
      double v, e;  // specific volume, specific energy
      if (mass > 0 && shares.size() == 1) {
        const BackgroundState& st = stateOf(shares[0].region, r);
        if (shares[0].region != cover.fluid) u = shares[0].region->velocityAt(x);
        v = 1.0 / st.rho, e = st.e, mass = frac * st.rho * V;
      } else if (mass > 0) {
        for (int d = 0; d < 3; ++d) u[static_cast<std::size_t>(d)] = mom[d] / mass;
        v = frac * V / mass, e = energy / mass - 0.5 * (u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
      } else {  // absent here: volume fraction 0 at the centre region's state if it names it, else the background's
        const BackgroundState* st = &bg[r];
        if (cover.fluid)
          for (const core::FillSpec& f : cover.fluid->fill)
            if (f.material == m.name) st = &stateOf(cover.fluid, r);
        v = 1.0 / st->rho, e = st->e;
      }
      for (int d = 0; d < m.vel.ncomp(); ++d) m.vel(i, j, k, d) = u[static_cast<std::size_t>(d)];
      m.mass(i, j, k) = mass;
      m.eint(i, j, k) = e;
      m.spvol(i, j, k) = v;
      m.theta(i, j, k) = frac;
    }
    double p = 0;
    for (const RegionShare& s : shares)
      if (s.region) p += s.share * *s.region->pressure;
    st_.press(i, j, k) = cover.fluid ? (inSolid ? *cover.fluid->pressure : p)
                                     : plan.fluid.empty() ? kReferencePressure : *plan.fluid.front()->pressure;
    if (coupledStart) initialPressure_(i, j, k) = st_.press(i, j, k);
  });

  // ---- boundaries
  for (int s = 0; s < 6; ++s) {
    const core::BoundarySpec& b = scene.boundary[s];
    if (b.type != core::BoundaryType::Inflow || s / 2 >= dim) continue;
    InflowState& in = inflow_[s];
    in.material = b.material.empty() ? firstFluid : scene.materialIndex(b.material);
    if (in.material < 0 || st_.mat[in.material].external)
      badInput(b.where, std::string("boundary.") + core::boundaryFaceName(s) + ".material: '" + b.material +
                       "' is not a fluid of the scene");
    if (!b.density && !b.pressure)
      badInput(b.where, std::string("boundary.") + core::boundaryFaceName(s) + ": inflow needs a density or a pressure");
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
    Source src{scene.materialIndex(s.material), s.power_density, s.start, s.end, {}, {}};
    if (src.material < 0 || st_.mat[src.material].external)
      badInput(s.where, "sources: '" + s.material + "' is not a fluid of the scene");
    // Each cell takes the fraction of its volume inside the shape (midpoint rule on
    // kSourceSamples^dim sub-cells where the corners and the centre disagree), not all or nothing
    // by its centre: a cell the shape's edge cuts heats in proportion to its part inside, so the
    // heated region's edge follows the shape instead of a staircase of cell centres (the seed
    // cylinder's inner load sat on that staircase, docs/coupling.md).
    forEach(owned_, [&](int i, int j, int k) {
      const int c[3] = {i, j, k};
      auto at = [&](const double (&u)[3]) {
        core::RealVect x{0.0, 0.0, 0.0};
        for (int d = 0; d < dim; ++d) x[d] = mesh_.origin()[d] + (c[d] + u[d]) * mesh_.dx(d);
        return s.shape.contains(x, dim);
      };
      const double mid[3] = {0.5, 0.5, 0.5};
      const bool centre = at(mid);
      bool mixed = false;
      for (int q = 0; q < (1 << dim) && !mixed; ++q) {
        const double u[3] = {double(q & 1), double((q >> 1) & 1), double((q >> 2) & 1)};
        mixed = at(u) != centre;
      }
      double share = centre ? 1.0 : 0.0;
      if (mixed) {
        constexpr int n = kSourceSamples;
        const int nz = dim > 2 ? n : 1, ny = dim > 1 ? n : 1;
        int in = 0;
        for (int a = 0; a < n; ++a)
          for (int b = 0; b < ny; ++b)
            for (int e = 0; e < nz; ++e) {
              const double u[3] = {(a + 0.5) / n, (b + 0.5) / n, (e + 0.5) / n};
              in += at(u) ? 1 : 0;
            }
        share = double(in) / double(n * ny * nz);
      }
      if (share > 0) {
        src.cells.push_back(stored.index(i, j, k));
        src.share.push_back(share);
      }
    });
    sources_.push_back(std::move(src));
  }

  fillMaterialGhosts(false);
  computeEquilibriumPressure();
}

}  // namespace mpmice::ice
