#include "couplings/volume/fluid/fluid_side.h"

namespace mpmice::coupler {

FluidSide::FluidSide(ice::IceSolver& ice, const core::Scene& scene)
    : ice_(ice), faceTransport_(scene.coupling.solid_transport == "mpm") {
  for (int m : scene.solids()) fields_.emplace_back(m, scene.materials[m].name, ice.ownedBox());
}

void FluidSide::consumeAProduceB(double dt) {
  if (!started_) start();
  setSolidStates();
  ice_.computeEquilibriumPressure();
  ice_.beginStep(dt);
  ice_.computeFaceVelocities();
  ice_.computePressureIncrement();
  ice_.computeFacePressure();
  for (auto& f : fields_) {
    const core::Field p = ice_.pressureForce(f.material);
    f.pressureForce.copyRegion(p, f.pressureForce.box(), f.pressureForce.box());
    f.pressure.copyRegion(ice_.pressure(), f.pressure.box(), f.pressure.box());
  }
}

void FluidSide::consumeCProduceD() {
  for (auto& f : fields_) {
    ice_.setExternalCouplingWork(f.material, all(f.couplingWork));
    ice_.setExternalVolumeChange(f.material, all(f.volumeChange));
  }
  ice_.computeSourcesAndLagrangian();
  for (auto& f : fields_) ice_.setExternalLagrangianMomentum(f.material, all(f.lagrangianMomentum));
  ice_.exchange();
  for (auto& f : fields_) {
    const core::Field& d = ice_.exchangeMomentum(f.material);
    f.exchangeMomentum.copyRegion(d, f.exchangeMomentum.box(), f.exchangeMomentum.box());
    f.exchangeEnergy.copyRegion(ice_.exchangeEnergy(f.material), f.exchangeEnergy.box(), f.exchangeEnergy.box());
  }
}

void FluidSide::finishStep() { ice_.advectFluids(); }

void FluidSide::setSolidStates() {
  for (auto& f : fields_) {
    ice_.setExternalMaterialState(f.material, all(f.mass), all(f.velocity), all(f.temperature),
                                  all(f.specificVolume));
    if (faceTransport_) ice_.setExternalFaceTransport(f.material, all(f.faceDensity), all(f.faceFlux));
  }
}

void FluidSide::start() {
  setSolidStates();
  ice_.fitFluidsToExternalVolume();
  started_ = true;
}

void FluidSide::primeOutput() {
  // The pressure the solids see before the fluid's first step (the explicit and implicit
  // schedules start the solid first) is the equilibrium pressure with the solids placed, not
  // the fluids' own from before the solids took their volume.
  ice_.computeEquilibriumPressure();
  for (auto& f : fields_) {
    f.pressure.copyRegion(ice_.pressure(), f.pressure.box(), f.pressure.box());
    f.pressureForce.fill(0.0);
    f.exchangeMomentum.fill(0.0);
    f.exchangeEnergy.fill(0.0);
  }
}

void FluidSide::fullStep(double dt) {
  consumeAProduceB(dt);
  consumeCProduceD();
  finishStep();
}

SideTotals FluidSide::totals() const {
  const ice::Totals t = ice_.totals();
  SideTotals s;
  s.mass = t.mass;
  s.momentum = t.momentum;
  s.kinetic = t.kinetic;
  s.internal = t.energy - t.kinetic;
  return s;
}

}  // namespace mpmice::coupler
