#include "couplings/volume/schedule/coupling_schedule.h"

#include <stdexcept>

#include "couplings/volume/schedule/explicit_schedule.h"
#include "couplings/volume/schedule/implicit_schedule.h"
#include "couplings/volume/schedule/monolithic_schedule.h"

namespace mpmice::coupler {

std::unique_ptr<CouplingSchedule> makeSchedule(const core::Scene& scene, const core::Comm& comm) {
  const core::Schedule s = scene.coupling.schedule;
  switch (s) {
    case core::Schedule::Monolithic: return std::make_unique<MonolithicStyleSchedule>();
    case core::Schedule::ExplicitSerial:
    case core::Schedule::ExplicitParallel: return std::make_unique<ExplicitSchedule>(s);
    case core::Schedule::ImplicitSerial:
    case core::Schedule::ImplicitParallel: return std::make_unique<ImplicitSchedule>(scene.coupling, comm);
  }
  throw std::logic_error("makeSchedule: no such schedule");
}

void startCoupling(const Sides& sides, Transport& transport) {
  if (sides.solid) {
    sides.solid->beginStep(sides.solid->stableTimeStep());
    sides.solid->produceA();
  }
  exchange(sides, transport, ExchangePoint::SolidState, "initial");
  if (sides.fluid) {
    sides.fluid->start();
    sides.fluid->primeOutput();
  }
  exchange(sides, transport, ExchangePoint::PressureForce, "initial");
  exchange(sides, transport, ExchangePoint::ExchangeIncrements, "initial");
}

}  // namespace mpmice::coupler
