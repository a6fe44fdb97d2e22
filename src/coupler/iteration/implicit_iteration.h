#pragma once
/// @brief The implicit coupling iteration of one step (time window), whatever is coupled.
///
/// The iterate is a list of named data views (DataView: a field's values on this rank, e.g.
/// "pressure_force" of each solid, or "interface_displacement" of a patch). One pass of the
/// solvers turns the input x into an output x~ = H(x) in the same views. The scene's
/// convergence measures (core::ConvergenceSpec: field, type, limit, strict) compare x~ with x
/// field by field; the verdict is stepAccepted (acceptance.h: strict overrules suffices, at
/// least min_iterations). At max_iterations unconverged the step is an error naming every
/// residual, unless coupling.accept_unconverged. Between passes the input is accelerated
/// (coupling.acceleration). The volume (MPM-ICE) and the surface (MPM + OpenFOAM) couplings
/// both iterate through this class.
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "coupler/acceleration/acceleration.h"
#include "coupler/convergence/convergence_measure.h"
#include "core/parallel/comm.h"
#include "core/scene/scene.h"

namespace mpmice::coupler {

/// One named piece of an iterate: values this rank holds (several views may share a name:
/// a field of several solids; a measure then sees them concatenated).
struct DataView {
  std::string name;
  std::span<double> values;
};

/// What a step did: iterations, whether it was accepted as converged, and the residual of each
/// convergence measure at the last iteration.
struct StepReport {
  int iterations = 1;
  bool converged = true;
  std::vector<double> residuals;
};

/// The values of every view called `name`, concatenated (an empty vector if none).
Eigen::VectorXd gather(const std::vector<DataView>& views, const std::string& name);
/// All views, concatenated in order, and back.
Eigen::VectorXd pack(const std::vector<DataView>& views);
void unpack(const Eigen::VectorXd& x, const std::vector<DataView>& views);

class ImplicitIteration {
 public:
  /// measures: the fields to measure (already defaulted and checked by the coupling).
  ImplicitIteration(const core::CouplingSpec& spec, std::vector<core::ConvergenceSpec> measures,
                    const core::Comm& comm);

  /// A whole step over `views`: pass() turns the input in the views into the output;
  /// restore() returns the solvers to the step's start; verdict(done) is told after every pass
  /// (MPMD: the peer follows it). `when` names the step in errors ("the step at t = 0.1").
  StepReport iterate(const std::vector<DataView>& views, const std::string& when, const std::function<void()>& pass,
                     const std::function<void()>& restore, const std::function<void(bool)>& verdict);

  // The same, piece by piece, for a loop driven from elsewhere (the surface coupling answers
  // a fluid that decides when to send):
  /// Starts a step (the measures' per-step state).
  void beginStep();
  /// Judges iteration k from each measure's (before, after) values, in the order of
  /// measuredFields() (an empty `before`: not measurable yet, does not hold). Returns whether
  /// the step is done; throws the iteration-limit error when it is done unconverged and the
  /// scene does not accept that. Fills `report`.
  bool judge(int k, const std::vector<std::pair<Eigen::VectorXd, Eigen::VectorXd>>& values, const std::string& when,
             StepReport& report);
  /// The next input from this iteration's input and output.
  Eigen::VectorXd accelerate(const Eigen::VectorXd& x, const Eigen::VectorXd& xTilde);
  /// The step converged: the acceleration keeps what it learned and starts a new step.
  void endStep();

  [[nodiscard]] std::vector<std::string> measuredFields() const;

  /// What the acceleration has learned, for a checkpoint between steps (Acceleration::save).
  void save(core::CheckpointData& data, const std::string& prefix) const {
    if (acceleration_) acceleration_->save(data, prefix);
  }
  void load(const core::CheckpointData& data, const std::string& prefix) {
    if (acceleration_) acceleration_->load(data, prefix);
  }

 private:
  struct Measured {
    core::ConvergenceSpec spec;
    std::unique_ptr<ConvergenceMeasure> measure;
  };
  core::CouplingSpec spec_;
  core::Comm comm_;
  std::vector<Measured> measures_;
  std::unique_ptr<Acceleration> acceleration_;
};

}  // namespace mpmice::coupler
