#pragma once
/// @brief Acceptance checks of an implicit coupling iteration for one exchanged field.
///
/// A measure compares the field's values of two successive iterations of the same step
/// (the coupling data are distributed: norms are summed over the ranks of a communicator).
///   absolute:          ||new - old|| <= limit
///   relative:          ||new - old|| <= limit * ||new||
///   residual_relative: ||new - old|| <= limit * ||first residual of this step||
/// Each measure is either "strict" (must hold for the step to be accepted) or "suffices"
/// (if it holds the step is accepted whatever the others say). Chosen by name in the scene's
/// coupling.convergence list.
#include <Eigen/Dense>
#include <memory>
#include <string>
#include <vector>

#include "core/parallel/comm.h"

namespace mpmice::coupler {

class ConvergenceMeasure {
 public:
  virtual ~ConvergenceMeasure() = default;
  /// Called at the start of every coupling step (time window).
  virtual void newStep() {}
  /// Compares two iterates; returns whether this measure is satisfied.
  virtual bool measure(const Eigen::VectorXd& oldValues, const Eigen::VectorXd& newValues,
                       const core::Comm& comm) = 0;
  /// The last residual norm ||new - old|| and the value it was compared with.
  [[nodiscard]] double residual() const { return residual_; }
  [[nodiscard]] double threshold() const { return threshold_; }
  [[nodiscard]] virtual const char* name() const = 0;

 protected:
  double residual_ = 0, threshold_ = 0;
};

/// Creates a measure by its scene name; an unknown name throws, listing the valid names.
std::unique_ptr<ConvergenceMeasure> makeConvergenceMeasure(const std::string& type, double limit);
const std::vector<std::string>& convergenceMeasureNames();

/// Global 2-norm of a distributed vector.
double globalNorm(const Eigen::VectorXd& v, const core::Comm& comm);

}  // namespace mpmice::coupler
