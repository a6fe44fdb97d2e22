#pragma once
/// @brief One point of a study: its program started without a shell under a time limit, what it
/// measured (wall time, peak RSS, steps, coupling iterations per step, exit status) and its error
/// against the study's reference.
#include <string>
#include <vector>

#include "study/reference/references.h"

namespace mpmice::study {

/// Steps and coupling iterations from a run's terminal text: the coupled time loop's closing line
/// `coupling: schedule S, I iterations in N steps (R per step), ...` (else the progress line
/// `done: N steps, ...` for the steps). Absent values are -1.
struct RunCounts {
  long steps = -1;
  double iterationsPerStep = -1;
};
RunCounts parseRunLog(const std::string& text);

/// The line that says why a failed run ended: the last non-empty line of our programs' text,
/// skipping Open MPI's (its banners between lines of dashes after an MPI_Abort, lines tagged
/// [host:pid], the launcher's own prterun/mpirun lines); the last non-empty line when nothing else
/// is left.
std::string programNote(const std::string& text);

/// The outcome of one point.
struct PointResult {
  std::string status;  // ok, failed, timeout, no_error (the run ended 0 but the reference could not measure it)
  int exitCode = 0;
  double wallSeconds = 0;  // the median over the repeats
  std::vector<double> walls;  // every repeat's
  double cpuSeconds = 0;   // user + system time of the program and its children, the median over the repeats
  std::vector<double> cpus;   // every repeat's
  double peakRssMb = 0;
  long steps = -1;
  double iterationsPerStep = -1;
  double error = 0;    // NaN unless status is ok
  std::string note;    // why the error is missing (the reference's message), or programNote() of the log
  int stoppedBy = 0;   // the study got SIGINT / SIGTERM (forwarded to the run): no result
};

/// Runs `argv` `repeats` times (stopping at the first that does not end 0), each with its output
/// into `<runDir>/run.log` (then run_2.log, ...) within `timeLimit` seconds; the wall and CPU
/// times are the medians of the runs, the peak RSS their largest. Then measures the error of `files` (the
/// last run's output) with `ref` when every run ended 0.
PointResult runPoint(const std::vector<std::string>& argv, const std::string& runDir, double timeLimit, int repeats,
                     const Reference& ref, const RunFiles& files);

/// A result as YAML (`<run>/result.yaml`) and back (for --resume).
std::string resultYaml(const PointResult& r);
PointResult readResult(const std::string& file);

}  // namespace mpmice::study
