#include "ice/solver/initial_regions.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "core/scene/yaml_reader.h"
#include "ice/ice_constants.h"

namespace mpmice::ice {

namespace {

using core::scene_detail::formatNumber;

}  // namespace

void badInput(const core::SourceLoc& where, const std::string& msg) {
  throw std::invalid_argument((where.line ? where.str() + ": " : std::string()) + msg);
}

void resolveState(const Eos& eos, double p, double T, std::optional<double> rho, double* rhoOut, double* eOut) {
  if (rho) {
    *rhoOut = *rho;
    *eOut = eos.internalEnergy(*rho, p);
  } else {
    *rhoOut = eos.densityFromPT(p, T);
    *eOut = eos.energyFromTemperature(*rhoOut, T);
  }
}

RegionPlan planRegions(const core::Scene& scene, const std::vector<const Eos*>& eos) {
  const int nm = static_cast<int>(scene.materials.size());
  RegionPlan plan;
  plan.background.resize(static_cast<std::size_t>(nm));
  plan.state.resize(scene.geometry.size());
  auto external = [&](int r) { return scene.materials[r].kind == core::MaterialKind::Solid; };
  for (int r = 0; r < nm && plan.firstFluid < 0; ++r)
    if (!external(r)) plan.firstFluid = r;
  for (const core::RegionSpec& reg : scene.geometry) {
    if (reg.fill.empty()) badInput(reg.where, "geometry." + reg.name + ".fill: no material");
    double sum = 0;
    bool fluid = false;
    for (const core::FillSpec& f : reg.fill) {
      const int r = scene.materialIndex(f.material);
      if (r < 0) badInput(reg.where, "geometry." + reg.name + ".fill: unknown material '" + f.material + "'");
      if (f.volume_fraction < 0 || f.volume_fraction > 1)
        badInput(reg.where, "geometry." + reg.name + ".fill." + f.material + ".volume_fraction = " + formatNumber(f.volume_fraction) +
                           " must lie in [0, 1]");
      sum += f.volume_fraction;
      fluid |= !external(r);
    }
    if (!fluid) {
      plan.solid.push_back(&reg);
      continue;
    }
    if (std::abs(sum - 1.0) > 1e-9)
      badInput(reg.where, "geometry." + reg.name + ".fill: volume fractions sum to " + formatNumber(sum) +
                         "; they must sum to 1 (fix the volume_fraction values)");
    if (!reg.pressure) badInput(reg.where, "geometry." + reg.name + ".pressure: required for fluid regions");
    if (!(*reg.pressure > 0))
      badInput(reg.where, "geometry." + reg.name + ".pressure = " + formatNumber(*reg.pressure) + " must be > 0");
    if (reg.density && !(*reg.density > 0))
      badInput(reg.where, "geometry." + reg.name + ".density = " + formatNumber(*reg.density) + " must be > 0");
    if (!(reg.temperature > 0))
      badInput(reg.where, "geometry." + reg.name + ".temperature = " + formatNumber(reg.temperature) + " must be > 0");
    for (const core::FillSpec& f : reg.fill) {  // a cavitating liquid starts above its cut-off
      const int r = scene.materialIndex(f.material);
      const Eos& law = *eos[static_cast<std::size_t>(r)];
      if (!external(r) && law.cavitates() && f.volume_fraction > 0 && !(*reg.pressure > law.cavitationPressure()))
        badInput(scene.materials[static_cast<std::size_t>(r)].cavitation.where,
                 "materials." + f.material + ".cavitation.pressure = " + formatNumber(law.cavitationPressure()) +
                     " Pa is not below the pressure " + formatNumber(*reg.pressure) + " Pa of geometry." + reg.name +
                     " where it starts; the cut-off (a vapour pressure or a tensile limit) must lie below the liquid's " +
                     "ambient pressure");
    }
    // Each fluid's start state in this region lies above 0 K: a pressure below a JWL products'
    // or a stiffened gas's cold curve at the given density gives e below the cold energy, which
    // the first steps found (products at -11708 K, by e / cv, named in a cell of the foam beside them).
    std::vector<BackgroundState>& states = plan.state[static_cast<std::size_t>(&reg - scene.geometry.data())];
    states.assign(static_cast<std::size_t>(nm), BackgroundState{});
    for (const core::FillSpec& f : reg.fill) {  // each fluid's state here, resolved once
      const int r = scene.materialIndex(f.material);
      if (external(r)) continue;
      BackgroundState& st = states[static_cast<std::size_t>(r)];
      resolveState(*eos[static_cast<std::size_t>(r)], *reg.pressure, reg.temperature, reg.density, &st.rho, &st.e);
      st.set = true;
    }
    for (const core::FillSpec& f : reg.fill) {
      const int r = scene.materialIndex(f.material);
      if (external(r) || !(f.volume_fraction > 0)) continue;
      const Eos& law = *eos[static_cast<std::size_t>(r)];
      const double rho = states[static_cast<std::size_t>(r)].rho, e = states[static_cast<std::size_t>(r)].e;
      const double T = rho > 0 ? law.temperature(rho, e) : 0.0;
      auto g = [](double v) {
        char b[32];
        std::snprintf(b, sizeof b, "%.6g", v);
        return std::string(b);
      };
      // T = 0 exactly is a law's reference state without a reference temperature (a Mie-Grueneisen
      // liquid at rho0 and p0: e = 0); below it the state lies under the cold curve.
      if (rho > 0 && std::isfinite(e) && T < 0)
        badInput(reg.where, "geometry." + reg.name + ": material '" + f.material + "' at pressure " +
                               g(*reg.pressure) + " Pa and density " + g(rho) + " kg/m^3 starts at T = " + g(T) +
                               " K (specific energy " + g(e) + " J/kg by its equation of state, whose pressure at 0 K " +
                               "and this density is " + g(law.pressure(rho, law.coldEnergy(rho))) +
                               " Pa); expected T >= 0: raise geometry." + reg.name + ".pressure or lower its density");
    }
    for (const core::FillSpec& f : reg.fill) {
      const int r = scene.materialIndex(f.material);
      BackgroundState& bg = plan.background[static_cast<std::size_t>(r)];
      if (external(r) || bg.set) continue;
      bg.rho = states[static_cast<std::size_t>(r)].rho, bg.e = states[static_cast<std::size_t>(r)].e;
      if (!(bg.rho > 0) || !std::isfinite(bg.rho) || !std::isfinite(bg.e))
        badInput(reg.where, "geometry." + reg.name + ": material '" + f.material + "' has no valid state at p = " +
                           formatNumber(*reg.pressure) + " Pa, T = " + formatNumber(reg.temperature) + " K (its equation of state gives " +
                           "density " + formatNumber(bg.rho) + " kg/m^3, specific energy " + formatNumber(bg.e) +
                           " J/kg); expected a finite density > 0 and a finite energy");
      bg.set = true;
    }
    plan.fluid.push_back(&reg);
  }
  for (int r = 0; r < nm; ++r) {
    BackgroundState& bg = plan.background[static_cast<std::size_t>(r)];
    if (!external(r) && !bg.set) {  // never placed: an absent material at 1 atm, 300 K
      const Eos& e = *eos[static_cast<std::size_t>(r)];
      bg.rho = e.densityFromPT(kReferencePressure, kReferenceTemperature);
      bg.e = e.energyFromTemperature(bg.rho, kReferenceTemperature);
      bg.set = bg.rho > 0;
    }
  }
  return plan;
}

CellCover coverAt(const RegionPlan& plan, const core::RealVect& x, int dim) {
  CellCover c;
  for (const core::RegionSpec* rg : plan.fluid)
    if (rg->shape.contains(x, dim)) c.fluid = rg;
  // Cells whose centre lies in a solid object (declared after the fluid region) hold no fluid:
  // the solid's mass arrives through setExternalMaterialState.
  for (const core::RegionSpec* rg : plan.solid)
    if (rg->shape.contains(x, dim) && (!c.fluid || rg > c.fluid)) c.inSolid = true;
  return c;
}

void requireCovered(const RegionPlan& plan, const CellCover& cover, int i, int j, int k) {
  if (!cover.fluid && !cover.inSolid && plan.firstFluid >= 0)
    throw std::invalid_argument("geometry: cell " + std::to_string(i) + "," + std::to_string(j) + "," +
                                std::to_string(k) + " is covered by no fluid region (add a background region)");
}

void cellShares(const RegionPlan& plan, const core::Mesh& mesh, const int ijk[3], const CellCover& centre,
                std::vector<RegionShare>* out) {
  out->clear();
  out->push_back({centre.fluid, 1.0});
  if (centre.inSolid) return;
  const int dim = mesh.dim();
  // The region a point's fluid comes from (null: in a solid declared after its region, or none).
  auto winner = [&](const core::RealVect& x) -> const core::RegionSpec* {
    const CellCover c = coverAt(plan, x, dim);
    return c.inSolid ? nullptr : c.fluid;
  };
  bool one = true;
  for (int corner = 0; corner < (1 << dim) && one; ++corner) {
    core::RealVect c{0, 0, 0};
    for (int d = 0; d < dim; ++d) c[d] = mesh.node(d, ijk[d] + ((corner >> d) & 1));
    one = winner(c) == centre.fluid;
  }
  if (one) return;
  int n[3] = {1, 1, 1};
  for (int d = 0; d < dim; ++d) n[d] = kFillSamples;
  std::vector<RegionShare> counts;
  double total = 0;
  mesh.forSubcellCentres(ijk, n, [&](const core::RealVect& p, const int*) {
    const core::RegionSpec* r = winner(p);
    if (!r) return;
    total += 1;
    for (RegionShare& s : counts)
      if (s.region == r) {
        s.share += 1;
        return;
      }
    counts.push_back({r, 1.0});
  });
  if (!(total > 0)) return;
  for (RegionShare& s : counts) s.share /= total;
  *out = std::move(counts);
}

}  // namespace mpmice::ice
