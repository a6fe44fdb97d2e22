#include "couplings/volume/schedule/monolithic_schedule.h"

namespace mpmice::coupler {

StepReport MonolithicStyleSchedule::step(const Sides& s, Transport& tr, double dt) {
  if (s.solid) {  // particles to grid; the solid's cell state
    s.solid->beginStep(dt);
    s.solid->produceA();
  }
  exchange(s, tr, ExchangePoint::SolidState);
  if (s.fluid) s.fluid->consumeAProduceB(dt);  // equilibrium pressure ... face pressure; force on each solid
  exchange(s, tr, ExchangePoint::PressureForce);
  if (s.solid) s.solid->consumeBProduceC();  // internal + pressure forces; grid update
  exchange(s, tr, ExchangePoint::LagrangianMomentum);
  if (s.fluid) s.fluid->consumeCProduceD();  // Lagrangian values; exchange over all materials
  exchange(s, tr, ExchangePoint::ExchangeIncrements);
  if (s.solid) s.solid->consumeDFinishStep();  // increments to nodes; particles updated
  if (s.fluid) s.fluid->finishStep();          // fluids advected
  return {};
}

}  // namespace mpmice::coupler
