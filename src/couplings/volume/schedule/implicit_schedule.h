#pragma once
/// @brief The implicit partitioned schedules: the explicit step repeated from checkpoints of
/// both solvers until the acceptance checks pass (coupler/iteration/implicit_iteration.h).
///
/// Serial: the iterate is the fluid's output (pressure force, pressure, exchange increments)
/// that the solid steps with. Parallel: the iterate also holds the solid's state and Lagrangian
/// momentum, and both sides step from it at once (the first step in serial order). The solid
/// side holds the iterate and decides; a fluid side alone in its program repeats the step until
/// the solid's verdict says done. Without measures in the scene, the pressure force and the
/// exchange momentum (and the solid velocity in parallel) are measured relative, limit 1e-6, strict.
#include "couplings/volume/schedule/coupling_schedule.h"

namespace mpmice::coupler {

class ImplicitSchedule final : public CouplingSchedule {
 public:
  ImplicitSchedule(const core::CouplingSpec& spec, const core::Comm& comm);
  StepReport step(const Sides& sides, Transport& transport, double dt) override;
  [[nodiscard]] core::Schedule kind() const override { return kind_; }
  void save(core::CheckpointData& data, const std::string& prefix) const override;
  void load(const core::CheckpointData& data, const std::string& prefix) override;
  [[nodiscard]] std::vector<std::string> measuredFields() const override { return iteration_.measuredFields(); }

 private:
  /// The iterate: named views of the solid side's exchange fields.
  [[nodiscard]] std::vector<DataView> iterate(SolidSide& solid) const;
  core::Schedule kind_;
  ImplicitIteration iteration_;
  bool first_ = true;
};

/// The measures of coupling.convergence, or the defaults above; a field the schedule does not
/// iterate is an error naming the valid ones.
std::vector<core::ConvergenceSpec> volumeMeasures(const core::CouplingSpec& spec);

}  // namespace mpmice::coupler
