#include "mpmice/monolithic/monolithic_driver.h"

#include <algorithm>
#include <stdexcept>

namespace mpmice::coupler {

namespace {
void copyAll(const std::vector<const core::Field*>& from, const std::vector<core::Field*>& to) {
  for (std::size_t i = 0; i < from.size(); ++i) to[i]->copyRegion(*from[i], from[i]->box(), to[i]->box());
}
}  // namespace

MonolithicDriver::MonolithicDriver(const core::Scene& scene, const core::Comm& comm) : scene_(scene) {
  mpm_ = std::make_unique<mpm::MpmSolver>(scene, comm);
  ice_ = std::make_unique<ice::IceSolver>(scene, comm);
  if (!(mpm_->decomposition().cellBox(comm.rank()) == ice_->ownedBox()))
    throw std::logic_error("mpmice: the MPM and ICE decompositions differ");
  solid_ = std::make_unique<SolidSide>(*mpm_);
  fluid_ = std::make_unique<FluidSide>(*ice_, scene);
}

MonolithicDriver::~MonolithicDriver() = default;

double MonolithicDriver::nextTimeStep(double until) const {
  double dt = std::min({solid_->stableTimeStep(), fluid_->stableTimeStep(), scene_.time.dt_max});
  if (t_ + dt > until) dt = until - t_;
  return dt;
}

void MonolithicDriver::step(double dt) {
  auto& sf = solid_->fields();
  auto& ff = fluid_->fields();
  solid_->beginStep(dt);
  solid_->produceA();
  for (std::size_t s = 0; s < sf.size(); ++s) copyAll(std::as_const(sf[s]).a(), ff[s].a());
  fluid_->consumeAProduceB(dt);
  for (std::size_t s = 0; s < sf.size(); ++s) copyAll(std::as_const(ff[s]).b(), sf[s].b());
  solid_->consumeBProduceC();
  for (std::size_t s = 0; s < sf.size(); ++s) copyAll({&sf[s].lagrangianMomentum}, {&ff[s].lagrangianMomentum});
  fluid_->consumeCProduceD();
  for (std::size_t s = 0; s < sf.size(); ++s) copyAll({&ff[s].exchangeMomentum}, {&sf[s].exchangeMomentum});
  solid_->consumeDFinishStep();
  fluid_->finishStep();
  t_ += dt;
  ++n_;
}

void MonolithicDriver::run(double until, const std::function<void()>& afterStep) {
  while (t_ < until * (1 - 1e-12)) {
    if (scene_.time.max_steps > 0 && n_ >= scene_.time.max_steps) break;
    const double dt = nextTimeStep(until);
    if (scene_.time.dt_min > 0 && dt < scene_.time.dt_min)
      throw std::runtime_error("mpmice: time step " + std::to_string(dt) + " s at t = " + std::to_string(t_) +
                               " s fell below time.dt_min = " + std::to_string(scene_.time.dt_min) + " s");
    step(dt);
    if (afterStep) afterStep();
  }
}

}  // namespace mpmice::coupler
