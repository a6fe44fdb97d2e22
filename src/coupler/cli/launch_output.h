#pragma once
/// @brief What `coupler run` makes of its launch's output (mpirun --tag-output: each piece of
/// output arrives as "[<job>,<world rank>]<stdout>:text").
///
/// - The lines are sorted by world rank into their program (LaunchPlan) and joined again where
///   mpirun cut a line into pieces.
/// - An OpenFOAM solver's lines go to its log file (<output>/log.<solver>, core/io/log_file.h),
///   not to the terminal; the last of them are shown when the launch fails.
/// - The closing lines of each volume-coupled program ("coupling (...): computed ...",
///   "coupling: schedule ...", "done: ...") are held back; when the launch succeeds, one labelled
///   summary per side replaces them:
///     coupler: mpm_solver (2 ranks): 30 steps to t = 1.5e-04 s, compute 1.2 s, wait 0.3 s,
///              30 coupling iterations (1 per step), wall 1.6 s
///   (both sides take the same coupling iterations: the solid's verdict ends each step on both).
///   When it fails, the held lines are shown as they were, each prefixed with its program.
/// - A program's progress lines ("step 120  t = ... / ... s (80.0%)  dt = ...  wall ... s  ETA ... s
///   iters=1 iters_total=120", core/util/progress.h; in a coupled launch only the solid side prints
///   them) become the launch's one coupled progress line:
///     coupler: step 120  t = 1.200e-04 / 1.500e-04 s (80.0%)  ETA 0.4 s  coupling iterations 1 (1 per step)
///   On a terminal (inPlace) each one overwrites the last ("\r", erase to the end of the line), so the
///   run shows a single line that moves; elsewhere (a pipe, a file) each is a line of its own.
/// - Everything else (errors, mpirun's own messages) reaches the terminal as it was written. Each
///   program keeps its full output in its own log file.
#include <map>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/io/log_file.h"
#include "coupler/cli/run_command.h"

namespace mpmice::coupler {

/// One side's closing figures, read from its closing lines.
struct SideSummary {
  std::optional<long> steps, iterations;
  std::optional<double> time, wall, compute, wait;
  std::vector<std::string> held;  // the closing lines as written
};

class LaunchOutput {
 public:
  /// fluidLog: where the lines of the program at fluidProgram go (null: an MPM-ICE launch).
  /// inPlace: the terminal is a terminal (isatty), the progress line is rewritten in place.
  LaunchOutput(const LaunchPlan& plan, std::ostream& terminal, std::unique_ptr<core::LogFile> fluidLog = nullptr,
               int fluidProgram = -1, bool inPlace = false);
  /// A piece of the launch's output, as read from the pipe.
  void feed(std::string_view chunk);
  /// The end of the output: what is still pending, then the summaries (succeeded) or the held lines.
  void finish(bool succeeded);
  /// The output with the tags removed (the text explainFailure reads), its last MiB.
  [[nodiscard]] const std::string& text() const { return text_; }
  [[nodiscard]] const std::map<int, SideSummary>& summaries() const { return sides_; }

  /// Reads a closing line into `s`; false when it is none.
  static bool readClosingLine(const std::string& line, SideSummary& s);
  /// The coupled progress line made of a program's progress line; none when `line` is not one.
  static std::optional<std::string> coupledProgressLine(const std::string& line);
  /// The labelled summary line of `program` on `ranks` ranks (empty when figures are missing).
  static std::string summaryLine(const std::string& program, int ranks, const SideSummary& s,
                                 std::optional<long> iterations);

 private:
  void line(int program, const std::string& text);
  void show(const std::string& text, bool progress = false);  // to the terminal
  [[nodiscard]] int programOf(int worldRank) const;
  const LaunchPlan& plan_;
  std::ostream& terminal_;
  std::unique_ptr<core::LogFile> fluidLog_;
  int fluidProgram_;
  bool inPlace_, progressShown_ = false;  // a progress line waits on the terminal without its newline
  std::string pending_, text_;
  int current_ = -2;                      // the program of the piece being read (-1: untagged, -2: none)
  std::map<std::pair<int, int>, std::string> partial_;  // (world rank, stream) -> its unfinished line
  std::pair<int, int> currentKey_{-1, 0};
  std::map<int, SideSummary> sides_;
  std::vector<std::string> fluidTail_;
};

}  // namespace mpmice::coupler
