#pragma once
/// @brief Implicit partitioned coupling: a step is repeated from a checkpoint of both solvers
/// until the acceptance checks pass, its input accelerated between iterations.
///
/// Serial: the iterated quantity x is the fluid's output (B: pressure force and pressure, D:
/// exchange increments) that the solid steps with; one iteration is solid step -> A, C -> fluid
/// step -> x~. Parallel: x holds A, C, B, D and both sides step from it. Convergence measures
/// (coupling.convergence) compare x~ with x per field: "strict" ones must all hold, one
/// "suffices" that holds is enough; at least min_iterations. Without measures in the scene,
/// every iterated field is measured relative with limit 1e-6. Reaching max_iterations
/// unconverged is an error with the residuals, unless coupling.accept_unconverged.
#include "acceleration/acceleration.h"
#include "convergence/convergence_measure.h"
#include "mpmice/schedule/coupling_schedule.h"

namespace mpmice::coupler {

class ImplicitSchedule final : public CouplingSchedule {
 public:
  ImplicitSchedule(const core::CouplingSpec& spec, const core::Comm& comm, bool parallel);
  StepReport step(SolidSide& solid, FluidSide& fluid, double dt) override;
  const char* name() const override { return parallel_ ? "implicit_parallel" : "implicit_serial"; }
  std::vector<std::string> measuredFields() const override;

 private:
  struct Measured {
    std::string field;
    bool strict;
    std::unique_ptr<ConvergenceMeasure> measure;
  };
  /// The iterated fields of each solid, in a fixed order, as (name, field) pairs.
  std::vector<std::pair<std::string, core::Field*>> iterated(std::vector<SolidExchangeFields>& f) const;
  Eigen::VectorXd pack(std::vector<SolidExchangeFields>& f, const std::string& only = "") const;
  void unpack(const Eigen::VectorXd& x, std::vector<SolidExchangeFields>& f) const;

  core::CouplingSpec spec_;
  core::Comm comm_;
  bool parallel_;
  std::vector<Measured> measures_;
  std::unique_ptr<Acceleration> acceleration_;
  bool first_ = true;
};

}  // namespace mpmice::coupler
