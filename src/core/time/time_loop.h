#pragma once
/// @brief The clock of every program: when a run has reached a time, how big the next step may
/// be, and when output is due. One definition, used by mpm_solver, ice_solver, mpmice and the
/// coupled participants alike.
///
/// A run's clock is a sum of steps and carries round-off: a time t has reached a target T when
/// t >= T (1 - kTimeTolerance). A run stops when its clock has reached time.end or it has taken
/// time.max_steps steps (if set), whichever comes first; the last step is shortened to land on
/// time.end.
///
/// Output (OutputSchedule): at t = 0, then after every step at which the clock has passed the
/// next multiple of output.interval (at most once per step, so an interval smaller than the
/// step writes every step), and after the last step of the run. output.interval 0: the start
/// and the last step only. Pinned by tests/unit/core/test_time_loop.cpp.
#include <vector>

namespace mpmice::core {

inline constexpr double kTimeTolerance = 1e-12;

/// True when the clock t has reached the target time (within the clock's round-off).
[[nodiscard]] constexpr bool reached(double t, double target) { return t >= target * (1 - kTimeTolerance); }

/// Whether a run at time t after `steps` steps takes another (time.end, time.max_steps; 0 = no limit).
[[nodiscard]] constexpr bool goesOn(double t, long steps, double end, long maxSteps) {
  return !reached(t, end) && !(maxSteps > 0 && steps >= maxSteps);
}

/// The step to take from t: dt, shortened so that the run lands on `end`.
[[nodiscard]] constexpr double landOn(double t, double dt, double end) { return t + dt > end ? end - t : dt; }

/// What set a coupled step, for the progress line: "time.end" (landOn shortened it), "time.dt_max",
/// or the side whose stable step it is ("solid", "fluid"). `solidStep` / `fluidStep`: the stable
/// steps of the sides this program runs (infinity for a side it does not run); a stable step
/// that is neither is the peer program's, i.e. the side this program does not run.
[[nodiscard]] constexpr const char* stepSetBy(double dt, double stable, double dtMax, double solidStep,
                                              double fluidStep, bool runsSolid) {
  if (dt < stable) return "time.end";
  if (stable == dtMax) return "time.dt_max";
  if (solidStep == stable) return "solid";
  if (fluidStep == stable) return "fluid";
  return runsSolid ? "fluid" : "solid";
}

class OutputSchedule {
 public:
  /// interval: output.interval (0 = start and end only); end: time.end.
  OutputSchedule(double interval, double end);
  /// Called once per step with the clock after it (and once at t = 0): true when output is due,
  /// and moves the next output time past t. `last`: this is the run's last step.
  bool due(double t, bool last = false);
  /// Where a solver that lands its steps on output times steps to next, from t with a stable
  /// step `step`: the next output time; `end` when that is nearer, or when the interval is below
  /// the step (output then follows every step and no step is shortened for it).
  [[nodiscard]] double landingTarget(double t, double step) const {
    return every_ < step || reached(t, next_) || next_ > end_ ? end_ : next_;
  }
  /// True when the step at time t was the last one written (so the end needs no extra write).
  [[nodiscard]] bool written(double t) const { return written_ == t; }
  /// Where the schedule stands (next output time, last time written), for a checkpoint;
  /// resume() returns to it.
  [[nodiscard]] std::vector<double> position() const { return {next_, written_}; }
  void resume(const std::vector<double>& p) {
    next_ = p.at(0);
    written_ = p.at(1);
  }

 private:
  double every_;
  double end_;
  double next_ = 0;
  double written_ = -1;
};

}  // namespace mpmice::core
