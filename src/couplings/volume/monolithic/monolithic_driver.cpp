#include "couplings/volume/monolithic/monolithic_driver.h"

#include <algorithm>
#include <stdexcept>

namespace mpmice::coupler {


MonolithicDriver::MonolithicDriver(const core::Scene& scene, const core::Comm& comm) : scene_(scene) {
  mpm_ = std::make_unique<mpm::MpmSolver>(scene, comm);
  ice_ = std::make_unique<ice::IceSolver>(scene, comm);
  if (!(mpm_->decomposition().cellBox(comm.rank()) == ice_->ownedBox()))
    throw std::logic_error("mpmice: the MPM and ICE decompositions differ");
  solid_ = std::make_unique<SolidSide>(*mpm_);
  fluid_ = std::make_unique<FluidSide>(*ice_, scene);
  schedule_ = makeSchedule(scene, comm);
  // Start: the fluid takes the solids' initial cell state and fits its fluids to the volume they
  // leave free (before any checkpoint, so implicit schedules repeat steps from that state).
  // Partitioned schedules step the solid first with the fluid's last output: start it from the
  // fluid's initial pressure (no force yet).
  solid_->beginStep(solid_->stableTimeStep());
  solid_->produceA();
  transfer(solid_->fields(), fluid_->fields(), 'A');
  fluid_->start();
  fluid_->primeOutput();
  transfer(fluid_->fields(), solid_->fields(), 'B');
}

MonolithicDriver::~MonolithicDriver() = default;

double MonolithicDriver::nextTimeStep(double until) const {
  double dt = std::min({solid_->stableTimeStep(), fluid_->stableTimeStep(), scene_.time.dt_max});
  if (t_ + dt > until) dt = until - t_;
  return dt;
}

void MonolithicDriver::step(double dt) {
  last_ = schedule_->step(*solid_, *fluid_, dt);
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
