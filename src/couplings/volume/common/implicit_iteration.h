#pragma once
/// @brief The implicit coupling iteration of one step, whatever carries the fields.
///
/// Serial: the iterated quantity x is the fluid's output (B: pressure force and pressure, D:
/// exchange increments) that the solid steps with; one pass is solid step -> A, C -> fluid
/// step -> x~. Parallel: x holds A, C, B, D and both sides step from it (the first step in
/// serial order: the fluid needs a solid state). Convergence measures (coupling.convergence)
/// compare x~ with x per field: "strict" ones must all hold, one "suffices" that holds is enough;
/// at least min_iterations. Without measures in the scene, the fluid's outputs (and the solid
/// velocity in parallel) are measured relative with limit 1e-6. Reaching max_iterations
/// unconverged is an error with the residuals, unless coupling.accept_unconverged. Between
/// passes the input is accelerated (coupling.acceleration). Used by the in-memory schedule and
/// by the MPMD solid participant alike.
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "coupler/acceleration/acceleration.h"
#include "coupler/convergence/convergence_measure.h"
#include "couplings/volume/common/exchange_fields.h"
#include "core/scene/scene.h"

namespace mpmice::coupler {

/// What a step did: iterations, whether it was accepted as converged, and the residual of each
/// convergence measure at the last iteration.
struct StepReport {
  int iterations = 1;
  bool converged = true;
  std::vector<double> residuals;
};

class ImplicitIteration {
 public:
  ImplicitIteration(const core::CouplingSpec& spec, const core::Comm& comm, bool parallel);

  /// One step. The iterate lives in the solid's field set `sf`. pass(serialOrder) takes both
  /// sides through one pass from it and leaves the output there (A, C from the solid; B, D from
  /// the fluid); restore() returns both solvers to the step's start; verdict(done) is told after
  /// every pass (MPMD: the fluid side waits for it). t0: the step's start time (for messages).
  StepReport iterate(std::vector<SolidExchangeFields>& sf, double t0, const std::function<void(bool)>& pass,
                     const std::function<void()>& restore, const std::function<void(bool)>& verdict);
  [[nodiscard]] std::vector<std::string> measuredFields() const;
  [[nodiscard]] bool parallel() const { return parallel_; }

 private:
  struct Measured {
    std::string field;
    bool strict;
    std::unique_ptr<ConvergenceMeasure> measure;
  };
  std::vector<std::pair<std::string, core::Field*>> iterated(std::vector<SolidExchangeFields>& f) const;
  Eigen::VectorXd pack(std::vector<SolidExchangeFields>& f) const;
  void unpack(const Eigen::VectorXd& x, std::vector<SolidExchangeFields>& f) const;

  core::CouplingSpec spec_;
  core::Comm comm_;
  bool parallel_;
  std::vector<Measured> measures_;
  std::unique_ptr<Acceleration> acceleration_;
  bool first_ = true;
};

}  // namespace mpmice::coupler
