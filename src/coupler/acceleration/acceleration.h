#pragma once
/// @brief Acceleration of implicit coupling iterations (a fixed-point iteration x = H(x)).
///
/// Each iteration of a coupling step feeds an input x^k to the solvers and receives their
/// output x~^k = H(x^k). performAcceleration turns (x^k, x~^k) into the next input x^{k+1}.
/// Data are distributed over the ranks of a communicator; inner products are global.
/// Families, chosen by name in the scene's coupling.acceleration.type:
///   none      x^{k+1} = x~^k
///   constant  x^{k+1} = x^k + w r^k,  r^k = x~^k - x^k
///   aitken    the same with w updated by Aitken's delta-squared rule every iteration
///   iqn_ils   interface quasi-Newton, inverse Jacobian from least squares over past iterations
///             (reused over `reuse` past steps, QR filter dropping near-dependent columns)
#include <Eigen/Dense>
#include <memory>
#include <string>
#include <vector>

#include "core/io/checkpoint.h"
#include "core/parallel/comm.h"

namespace mpmice::coupler {

struct AccelerationParams {
  std::string type = "none";
  double relaxation = 0.5;
  int reuse = 8;
  double filter = 1e-2;
  bool precondition = false;  // iqn_ils: the residual-sum preconditioner over the iterate's segments
};

/// A named piece of the iterate: elements [offset, offset + size) belong to group `group` (one
/// group per field name; a preconditioner weighs each group alike).
struct Segment {
  Eigen::Index offset = 0, size = 0;
  int group = 0;
};

class Acceleration {
 public:
  virtual ~Acceleration() = default;
  /// The iterate's layout (called before a step's first iteration; the same layout is a no-op).
  virtual void setSegments(const std::vector<Segment>& /*segments*/) {}
  /// x: the input of this iteration; xTilde: the solvers' output. Returns the next input.
  virtual Eigen::VectorXd performAcceleration(const Eigen::VectorXd& x, const Eigen::VectorXd& xTilde) = 0;
  /// The step's iterations converged: the next call starts a new step.
  virtual void iterationsConverged() = 0;
  [[nodiscard]] virtual const char* name() const = 0;
  /// What it has learned (IQN-ILS: the columns, their QR, the weights; Aitken: the relaxation)
  /// under `prefix`, for a checkpoint between steps; load() returns a fresh one to it. Local.
  virtual void save(core::CheckpointData& /*data*/, const std::string& /*prefix*/) const {}
  virtual void load(const core::CheckpointData& /*data*/, const std::string& /*prefix*/) {}
};

/// Creates an acceleration by its scene name; an unknown name throws, listing the valid names.
std::unique_ptr<Acceleration> makeAcceleration(const AccelerationParams& p, const core::Comm& comm);
const std::vector<std::string>& accelerationNames();

}  // namespace mpmice::coupler
