#include "couplings/volume/solid/solid_side.h"

namespace mpmice::coupler {

SolidSide::SolidSide(mpm::MpmSolver& mpm) : mpm_(mpm) {
  const core::Box owned = mpm.decomposition().cellBox(mpm.comm().rank());
  for (int m : mpm.scene().solids()) fields_.emplace_back(m, mpm.scene().materials[m].name, owned);
  dv_ = core::Field("dv", core::Centering::Cell, owned, 3, 0);
  // The pressure at which the solids are stress-free: their EOS threshold (p(rho0) = p_ref).
  if (!fields_.empty())
    pRef_ = mpm.scene().materials[fields_.front().material].eos.get("threshold_pressure", 101325.0);
}

void SolidSide::beginStep(double dt) { mpm_.beginStep(dt); }

void SolidSide::produceA() {
  mpm_.particlesToGrid();
  for (auto& f : fields_) {
    const mpm::SolidCellState& s = mpm_.cellState(f.material);
    const core::Box& b = f.mass.box();
    f.mass.copyRegion(s.mass, b, b);
    f.velocity.copyRegion(s.velocity, b, b);
    f.temperature.copyRegion(s.temperature, b, b);
    f.specificVolume.copyRegion(s.specificVolume, b, b);
    // Cells the solid does not reach: an absent material still needs a valid state for the
    // equilibrium pressure (its volume fraction is zero): reference specific volume, its
    // neighbours' temperature is not known here, so the scene's reference 300 K.
    const double v0 = 1.0 / mpm_.scene().materials[f.material].density;
    core::forEach(b, [&](int i, int j, int k) {
      if (f.mass(i, j, k) > 0 && f.specificVolume(i, j, k) > 0) return;
      f.mass(i, j, k) = 0.0;
      for (int d = 0; d < 3; ++d) f.velocity(i, j, k, d) = 0.0;
      f.specificVolume(i, j, k) = v0;
      if (!(f.temperature(i, j, k) > 0)) f.temperature(i, j, k) = 300.0;
    });
  }
}

void SolidSide::consumeBProduceC() {
  mpm_.computeInternalForces();
  if (!fields_.empty()) mpm_.addCellPressureStress(fields_.front().pressure, pRef_);
  for (auto& f : fields_) mpm_.addCellForce(f.material, f.pressureForce);
  mpm_.updateGrid();
  for (auto& f : fields_) mpm_.cellLagrangianMomentum(f.material, f.lagrangianMomentum);
}

void SolidSide::consumeDFinishStep() {
  for (auto& f : fields_) {
    const core::Box& b = f.mass.box();
    core::forEach(b, [&](int i, int j, int k) {
      const double m = f.mass(i, j, k);
      for (int d = 0; d < 3; ++d) dv_(i, j, k, d) = m > 0 ? f.exchangeMomentum(i, j, k, d) / m : 0.0;
    });
    mpm_.applyCellVelocityIncrement(f.material, dv_);
    mpm_.addCellEnergy(f.material, f.exchangeEnergy);
  }
  mpm_.gridToParticles();
  mpm_.endStep();
}

void SolidSide::fullStep(double dt) {
  beginStep(dt);
  produceA();
  consumeBProduceC();
  consumeDFinishStep();
}

SideTotals SolidSide::totals() const {
  const auto& p = mpm_.particles();
  std::vector<double> s(4, 0.0);
  for (std::size_t i = 0; i < p.size(); ++i) {
    s[0] += p.mass[i];
    for (int d = 0; d < 3; ++d) s[1 + d] += p.mass[i] * p.v[d][i];
  }
  mpm_.comm().sumInPlace(s);
  SideTotals t;
  t.mass = s[0];
  t.momentum = {s[1], s[2], s[3]};
  t.energy = mpm_.energies().total();
  return t;
}

core::ParticleOutput SolidSide::particleOutput() const {
  const auto& p = mpm_.particles();
  const auto n = p.size();
  auto span = [n](const std::vector<double>& c) { return std::span<const double>(c.data(), n); };
  core::ParticleOutput out;
  out.count = static_cast<std::int64_t>(n);
  for (int d = 0; d < 3; ++d) out.position[d] = span(p.x[d]);
  out.addScalar("mass", span(p.mass)).addScalar("volume", span(p.vol)).addScalar("temperature", span(p.temperature));
  out.addScalar("plastic_strain", span(p.eqps));
  out.addVector("velocity", {span(p.v[0]), span(p.v[1]), span(p.v[2])});
  std::vector<std::span<const double>> st;
  for (int c = 0; c < 6; ++c) st.push_back(span(p.stress[c]));
  out.addVector("stress", st);
  return out;
}

}  // namespace mpmice::coupler
