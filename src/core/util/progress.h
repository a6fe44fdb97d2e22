#pragma once
/// @brief The run's progress line: a start banner, periodic step lines with an ETA, an end summary.
///
/// Rank 0 of the Comm prints to the given stream; other ranks stay silent (and make no calls to
/// the clock that could diverge). A step line reads
///   `step 1200  t = 1.200e-03 / 4.000e-03 s (30.0%)  dt = 1.0e-06  wall 12.3 s  ETA 28.7 s  iters=3`
/// and is printed when at least `everySeconds` of wall time passed since the last line or when the
/// step number is a multiple of `everySteps` (either may be 0 = off; both 0 = every step).
/// The fraction done is the larger of the simulated time's, (t - t_start) / (t_end - t_start), and,
/// when time.max_steps ends the run, the steps' (step - step_start) / (max_steps - step_start), so a
/// run cut by max_steps with a far time.end shows a true percentage and ETA;
/// ETA = elapsed wall * (1 - done) / done. The wall clock is injectable (seconds, any
/// origin) so tests decide the elapsed time; the default is std::chrono::steady_clock.
#include <functional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "core/parallel/comm.h"

namespace mpmice::core {

struct ProgressOptions {
  double everySeconds = 10.0;
  int everySteps = 0;
  long maxSteps = 0;   ///< time.max_steps (0 = none): the run may end by steps before t_end
  long stepStart = 0;  ///< the step the run starts from (a restart's)
};

class Progress {
 public:
  using Clock = std::function<double()>;
  /// Extra key=value fields appended to a step line, e.g. {{"iters", 3}}.
  using Extras = std::vector<std::pair<std::string, double>>;

  Progress(std::ostream& os, const Comm& comm, double tStart, double tEnd, ProgressOptions opts = {},
           Clock clock = {});

  /// Prints the banner and starts the wall clock.
  void start(const std::string& scene, const std::string& meshDescription, int ranks);
  /// Reports a finished step; prints when due (or when force). Returns true when a line was printed.
  /// `tail` (e.g. "dt_by=solid"), when given, ends the line.
  bool step(int step, double t, double dt, const Extras& extras = {}, bool force = false, const std::string& tail = "");
  /// Prints the summary: steps, simulated time, wall time, steps/s and work/s (work = steps *
  /// workPerStep, named `workUnit`, e.g. cells per step -> "cell-steps").
  void finish(int steps, double t, double workPerStep = 0.0, const std::string& workUnit = "cell-steps");

  /// Wall seconds since start() (0 on ranks that do not print).
  [[nodiscard]] double elapsed() const;

  /// The step line for given values (pure; what step() prints).
  static std::string formatLine(int step, double t, double tStart, double tEnd, double dt, double wall,
                                const Extras& extras = {}, long maxSteps = 0, long stepStart = 0,
                                const std::string& tail = "");
  /// Fraction of the run done (0..1): the larger of the time's and the steps' (see above).
  static double fractionDone(double t, double tStart, double tEnd, long step = 0, long maxSteps = 0,
                             long stepStart = 0);
  /// ETA in seconds for a fraction done, or a negative value when nothing is done yet.
  static double etaFromFraction(double done, double wall);
  /// ETA in seconds by the simulated time alone, or a negative value when no simulated time has passed yet.
  static double eta(double t, double tStart, double tEnd, double wall);

 private:
  std::ostream& os_;
  bool printer_;
  double tStart_, tEnd_;
  ProgressOptions opts_;
  Clock clock_;
  double wallStart_ = 0.0, lastPrint_ = 0.0;
};

}  // namespace mpmice::core
