#pragma once
/// @brief The one-pass schedules: the seed's monolithic-style step and the partitioned explicit
/// ones (serial: Gauss-Seidel; parallel: Jacobi).
#include "couplings/volume/schedule/coupling_schedule.h"

namespace mpmice::coupler {

class MonolithicStyleSchedule final : public CouplingSchedule {
 public:
  StepReport step(SolidSide& solid, FluidSide& fluid, double dt) override;
  const char* name() const override { return "monolithic"; }
};

class ExplicitSchedule final : public CouplingSchedule {
 public:
  explicit ExplicitSchedule(bool parallel) : parallel_(parallel) {}
  StepReport step(SolidSide& solid, FluidSide& fluid, double dt) override;
  const char* name() const override { return parallel_ ? "explicit_parallel" : "explicit_serial"; }

 private:
  bool parallel_;
  bool first_ = true;  // the first step runs in serial order: the fluid needs the solid's state
};

}  // namespace mpmice::coupler
