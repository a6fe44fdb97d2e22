#pragma once
/// @brief What the health checks of every program share (docs/ice.md, docs/mpm.md "Health check"):
/// the error a non-physical state or a collapsed time step raises, the agreement of the ranks on
/// it, the physical ranges, and the time-step collapse rule (time.dt_collapse_fraction).
///
/// Each solver finds the first violation in its own cells or particles (ice/solver/health_check.h,
/// mpm/solver/health_check.h); stopOnViolation() lets every rank of the solver's communicator
/// agree on the lowest rank's message and throw HealthError with it, so no rank is left waiting
/// and the program can end with a non-zero status (the communicator's root prints it).
#include <stdexcept>
#include <string>

#include "core/parallel/comm.h"

namespace mpmice::core {

/// Temperatures above this [K] are out of range (beyond any state the equations of state model;
/// a run that went wrong reaches 1e40 K and more).
inline constexpr double kMaxTemperature = 1e9;
/// Sound speeds must stay below the speed of light [m/s].
inline constexpr double kMaxSoundSpeed = 2.99792458e8;

/// A non-physical state or a collapsed time step. Every rank of the solver's communicator throws
/// it with the same message; reporter() is true on the one rank that should print it.
class HealthError : public std::runtime_error {
 public:
  HealthError(const std::string& what, bool reporter) : std::runtime_error(what), reporter_(reporter) {}
  [[nodiscard]] bool reporter() const { return reporter_; }

 private:
  bool reporter_;
};

/// Throws HealthError on every rank of comm when some rank's `violation` is not empty (with the
/// message of the lowest such rank). Collective; one integer reduction when all is well.
void stopOnViolation(const Comm& comm, const std::string& violation);

/// "(x, y, z)" of a point, the first dim coordinates, in the shortest exact-enough form.
[[nodiscard]] std::string formatPoint(const double* x, int dim);

/// The collapse rule: a stable step below fraction x the run's first stable step is an error
/// (time.dt_collapse_fraction; 0 turns it off). One per run.
class StepCollapse {
 public:
  explicit StepCollapse(double fraction) : fraction_(fraction) {}
  /// Records the first stable step it is given; true when `stable` has collapsed.
  bool collapsed(double stable) {
    if (!(first_ > 0)) first_ = stable;
    return fraction_ > 0 && !(stable >= fraction_ * first_);
  }
  /// The error of a collapse at time t before step `step`: the step, the rule, and `limit` (what
  /// set the step: the cell or particle and the bound).
  [[nodiscard]] std::string message(double stable, double t, long step, const std::string& limit) const;
  [[nodiscard]] double first() const { return first_; }
  /// A restart: the reference step recorded before the checkpoint (first()).
  void resumeFirst(double first) { first_ = first; }

 private:
  double fraction_;
  double first_ = 0;
};

}  // namespace mpmice::core
