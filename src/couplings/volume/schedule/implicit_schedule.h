#pragma once
/// @brief Implicit partitioned coupling in memory: the step repeated from checkpoints of both
/// solvers until the acceptance checks pass (common/implicit_iteration.h does the iterating).
#include "couplings/volume/common/implicit_iteration.h"
#include "couplings/volume/schedule/coupling_schedule.h"

namespace mpmice::coupler {

class ImplicitSchedule final : public CouplingSchedule {
 public:
  ImplicitSchedule(const core::CouplingSpec& spec, const core::Comm& comm, bool parallel)
      : iteration_(spec, comm, parallel) {}
  StepReport step(SolidSide& solid, FluidSide& fluid, double dt) override;
  const char* name() const override { return iteration_.parallel() ? "implicit_parallel" : "implicit_serial"; }
  std::vector<std::string> measuredFields() const override { return iteration_.measuredFields(); }

 private:
  ImplicitIteration iteration_;
};

}  // namespace mpmice::coupler
