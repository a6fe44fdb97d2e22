#include "couplings/volume/schedule/explicit_schedules.h"

namespace mpmice::coupler {

StepReport MonolithicStyleSchedule::step(SolidSide& solid, FluidSide& fluid, double dt) {
  auto& sf = solid.fields();
  auto& ff = fluid.fields();
  solid.beginStep(dt);
  solid.produceA();
  transfer(sf, ff, 'A');
  fluid.consumeAProduceB(dt);
  transfer(ff, sf, 'B');
  solid.consumeBProduceC();
  transfer(sf, ff, 'C');
  fluid.consumeCProduceD();
  transfer(ff, sf, 'D');
  solid.consumeDFinishStep();
  fluid.finishStep();
  return {};
}

StepReport ExplicitSchedule::step(SolidSide& solid, FluidSide& fluid, double dt) {
  // Serial: the solid first (with the fluid's B, D of the last step), then the fluid with the
  // solid's new A, C. Parallel: both with the other's values of the last step.
  const bool parallel = parallel_ && !first_;
  first_ = false;
  solid.fullStep(dt);
  if (!parallel) {
    transfer(solid.fields(), fluid.fields(), 'A');
    transfer(solid.fields(), fluid.fields(), 'C');
  }
  fluid.fullStep(dt);
  if (parallel) {
    transfer(solid.fields(), fluid.fields(), 'A');
    transfer(solid.fields(), fluid.fields(), 'C');
  }
  transfer(fluid.fields(), solid.fields(), 'B');
  transfer(fluid.fields(), solid.fields(), 'D');
  return {};
}

}  // namespace mpmice::coupler
