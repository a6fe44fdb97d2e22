#include "couplings/volume/schedule/implicit_schedule.h"

namespace mpmice::coupler {

StepReport ImplicitSchedule::step(SolidSide& solid, FluidSide& fluid, double dt) {
  auto& sf = solid.fields();
  auto& ff = fluid.fields();
  const auto cpSolid = solid.solver().checkpoint();
  const auto cpFluid = fluid.solver().checkpoint();
  auto pass = [&](bool serialOrder) {
    if (serialOrder) {
      solid.fullStep(dt);
      transfer(sf, ff, 'A');
      transfer(sf, ff, 'C');
      fluid.fullStep(dt);
    } else {
      transfer(sf, ff, 'A');
      transfer(sf, ff, 'C');
      solid.fullStep(dt);
      fluid.fullStep(dt);
    }
    transfer(ff, sf, 'B');
    transfer(ff, sf, 'D');
  };
  auto restore = [&] {
    solid.solver().restore(cpSolid);
    fluid.solver().restore(cpFluid);
  };
  return iteration_.iterate(sf, solid.solver().time(), pass, restore, [](bool) {});
}

}  // namespace mpmice::coupler
