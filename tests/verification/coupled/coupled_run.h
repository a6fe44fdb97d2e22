#pragma once
// A coupled MPM-ICE run inside a test: the scene's two solvers, their coupling sides and the
// scene's schedule over an in-memory transport (what mpmice runs), stepped by the test so it can
// sample the state after every step. No output is written. Every step is health-checked as the
// programs do (a non-physical state throws core::HealthError naming it).
#include <algorithm>
#include <functional>
#include <memory>
#include <string>

#include "core/health/health.h"
#include "core/parallel/comm.h"
#include "core/scene/scene.h"
#include "coupler/transport/in_memory_transport.h"
#include "couplings/volume/schedule/coupling_schedule.h"
#include "ice/solver/health_check.h"
#include "mpm/solver/health_check.h"
#include "observed_order.h"

namespace mpmice::test {

struct CoupledRun {
  core::Scene scene;
  core::Comm comm{MPI_COMM_SELF};
  mpm::MpmSolver mpm;
  ice::IceSolver ice;
  coupler::SolidSide solid;
  coupler::FluidSide fluid;
  coupler::InMemoryTransport transport;
  long steps = 0;

  explicit CoupledRun(core::Scene s)
      : scene(std::move(s)), mpm(scene, comm), ice(scene, comm), solid(mpm), fluid(ice, scene) {
    coupler::startCoupling(sides(), transport);
  }
  [[nodiscard]] coupler::Sides sides() { return {&solid, &fluid}; }
  [[nodiscard]] double time() const { return mpm.time(); }

  /// Steps to `until` (the last step lands on it); `afterStep` sees the state after each step.
  void runTo(double until, const std::function<void()>& afterStep = {}) {
    const auto schedule = coupler::makeSchedule(scene, comm);
    while (time() < until * (1 - 1e-12)) {
      double dt = std::min(solid.stableTimeStep(), fluid.stableTimeStep());
      dt = std::min(dt, until - time());
      schedule->step(sides(), transport, dt);
      ++steps;
      std::string bad = mpm::findViolation(mpm);
      if (bad.empty()) bad = ice::findViolation(ice);
      if (!bad.empty()) throw core::HealthError(bad, true);
      if (afterStep) afterStep();
    }
  }
};

}  // namespace mpmice::test
