#include "couplings/volume/solid/solid_side.h"

namespace mpmice::coupler {

SolidSide::SolidSide(mpm::MpmSolver& mpm)
    : mpm_(mpm), faceTransport_(mpm.scene().coupling.solid_transport == "mpm") {
  mpm_.useGridStressWorkByDefault();  // mpm.stress_work auto: the energy budget closes
  const core::Box owned = mpm.decomposition().cellBox(mpm.comm().rank());
  for (int m : mpm.scene().solids()) fields_.emplace_back(m, mpm.scene().materials[m].name, owned);
}

void SolidSide::beginStep(double dt) { mpm_.beginStep(dt); }

void SolidSide::produceA() {
  mpm_.particlesToGrid();
  for (auto& f : fields_) {
    const mpm::SolidCellState& s = mpm_.cells().cellState(f.material);  // with the absent-solid state
    const core::Box& b = f.mass.box();
    f.mass.copyRegion(s.mass, b, b);
    f.velocity.copyRegion(s.velocity, b, b);
    f.temperature.copyRegion(s.temperature, b, b);
    f.specificVolume.copyRegion(s.specificVolume, b, b);
    if (faceTransport_) mpm_.cells().solidFaceTransport(f.material, f.faceDensity, f.faceFlux);
  }
}

void SolidSide::consumeBProduceC() {
  mpm::NodeCellOperators& cells = mpm_.cells();
  mpm_.computeInternalForces();
  if (!fields_.empty()) cells.addCellPressureStress(fields_.front().pressure);  // p_ref: the solids' EOS
  for (auto& f : fields_) cells.addCellForce(f.material, f.pressureForce);
  mpm_.updateGrid();
  for (auto& f : fields_) {
    cells.cellLagrangianMomentum(f.material, f.lagrangianMomentum);
    cells.cellCouplingWork(f.material, f.couplingWork, mpm_.stepSize(), &f.volumeChange);
  }
}

void SolidSide::consumeDFinishStep() {
  mpm::NodeCellOperators& cells = mpm_.cells();
  for (auto& f : fields_) {
    cells.applyCellMomentumIncrement(f.material, f.exchangeMomentum);
    // The exchange heat, then what the nodes did not take (one pass over the particles for both).
    cells.addCellEnergy(f.material, {&f.exchangeEnergy, &cells.kineticDeficit(f.material)});
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
  const mpm::Energies e = mpm_.energies();
  t.kinetic = e.kinetic;
  t.internal = e.strain;
  t.heat = e.heat;
  t.transfer = e.transfer;
  t.integration = e.integration;
  t.damping = e.damping;
  t.massOut = mpm_.outflow().mass;  // collective
  t.energyOut = e.outflow;
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
  out.addScalar("plastic_strain", span(p.column(p.eqps)));
  out.addVector("velocity", {span(p.v[0]), span(p.v[1]), span(p.v[2])});
  std::vector<std::span<const double>> st;
  for (int c = 0; c < 6; ++c) st.push_back(span(p.column(p.stress[c])));
  out.addVector("stress", st);
  materialOut_.assign(p.material.begin(), p.material.end());
  idOut_.resize(n);
  for (std::size_t i = 0; i < n; ++i) idOut_[i] = static_cast<double>(p.id[i]);
  out.addScalar("material", span(materialOut_)).addScalar("id", span(idOut_));
  return out;
}

}  // namespace mpmice::coupler
