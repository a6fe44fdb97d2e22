#include "couplings/volume/schedule/explicit_schedule.h"

namespace mpmice::coupler {

StepReport ExplicitSchedule::step(const Sides& s, Transport& tr, double dt) {
  const bool parallel = core::isParallel(kind_) && !first_;
  first_ = false;
  if (parallel) {  // the fluid takes the solid's state of the last step; both then step at once
    exchange(s, tr, ExchangePoint::SolidState);
    exchange(s, tr, ExchangePoint::LagrangianMomentum);
  }
  if (s.solid) s.solid->fullStep(dt);
  if (!parallel) {  // serial: the fluid takes the solid's new state
    exchange(s, tr, ExchangePoint::SolidState);
    exchange(s, tr, ExchangePoint::LagrangianMomentum);
  }
  if (s.fluid) s.fluid->fullStep(dt);
  exchange(s, tr, ExchangePoint::PressureForce);
  exchange(s, tr, ExchangePoint::ExchangeIncrements);
  return {};
}

}  // namespace mpmice::coupler
