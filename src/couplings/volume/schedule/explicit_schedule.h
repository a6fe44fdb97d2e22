#pragma once
/// @brief The explicit partitioned schedules: each side takes a whole step once, serial
/// (Gauss-Seidel: the solid first, the fluid with its new state) or parallel (Jacobi: both with
/// the other's values of the last step; the first step runs in serial order, since the fluid
/// needs a solid state).
#include "couplings/volume/schedule/coupling_schedule.h"

namespace mpmice::coupler {

class ExplicitSchedule final : public CouplingSchedule {
 public:
  explicit ExplicitSchedule(core::Schedule kind) : kind_(kind) {}
  StepReport step(const Sides& sides, Transport& transport, double dt) override;
  [[nodiscard]] core::Schedule kind() const override { return kind_; }
  void save(core::CheckpointData& data, const std::string& prefix) const override;
  void load(const core::CheckpointData& data, const std::string& prefix) override;

 private:
  core::Schedule kind_;
  bool first_ = true;
};

}  // namespace mpmice::coupler
