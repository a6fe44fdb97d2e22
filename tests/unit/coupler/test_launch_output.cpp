// `coupler run`'s reading of its launch's output (cli/launch_output.h): tagged pieces sorted by
// program and joined where mpirun cut them, the OpenFOAM solver's lines to its log file, and one
// labelled summary per side instead of the programs' closing lines.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <unistd.h>

#include "coupler/cli/launch_output.h"
#include "core/io/text_file.h"
#include "core/scene/scene.h"

using namespace mpmice;

namespace {

coupler::LaunchPlan mpmdPlan() {
  coupler::LaunchPlan plan;
  plan.programs = {"mpm_solver", "ice_solver"};
  plan.ranks = {2, 1};
  return plan;
}

const std::string kSolidClosing =
    "[7,0]<stdout>:coupling: schedule monolithic, 6 iterations in 3 steps (2 per step), 0 steps accepted unconverged\n"
    "[7,0]<stdout>:coupling (mpm_solver, coupled to 'ice'): computed 0.5 s, 0.25 s in exchange (rank to rank; ...)\n"
    "[7,0]<stdout>:done: 3 steps, t = 2.005e-05 s, wall 0.9 s, 3.3 steps/s, 1e+03 particle-steps/s\n";
const std::string kFluidClosing =
    "[7,2]<stdout>:coupling (ice_solver, coupled to 'mpm'): computed 0.125 s, 0.625 s in exchange (rank to rank)\n"
    "[7,2]<stdout>:done: 3 steps, t = 2.005e-05 s, wall 0.8 s, 3.7 steps/s, 5e+02 cell-steps/s\n";

/// Feeds `text` in pieces of `piece` bytes (cutting tags and lines anywhere).
void feedInPieces(coupler::LaunchOutput& o, const std::string& text, std::size_t piece) {
  for (std::size_t i = 0; i < text.size(); i += piece) o.feed(std::string_view(text).substr(i, piece));
}

}  // namespace

TEST(LaunchOutput, ShowsTheProgressAndOneLabelledSummaryPerSide) {
  for (std::size_t piece : {1000u, 1u, 7u, 13u}) {
    const auto plan = mpmdPlan();
    std::ostringstream terminal;
    coupler::LaunchOutput o(plan, terminal);
    // A progress line cut by mpirun into two tagged pieces; another rank's piece in between.
    feedInPieces(o, "[7,0]<stdout>:step 10  t = 1.0e-05 / 2.0e-05 s[7,2]<stderr>:ice note\n[7,0]<stdout>: (50.0%)\n", piece);
    feedInPieces(o, kSolidClosing + kFluidClosing + "mpirun: its own line\n", piece);
    o.finish(true);
    EXPECT_EQ(terminal.str(),
              "ice note\n"
              "step 10  t = 1.0e-05 / 2.0e-05 s (50.0%)\n"
              "mpirun: its own line\n"
              "coupler: mpm_solver (2 ranks): 3 steps to t = 2.005e-05 s, compute 0.5 s, wait 0.25 s, 6 coupling "
              "iterations (2 per step), wall 0.9 s\n"
              "coupler: ice_solver (1 rank): 3 steps to t = 2.005e-05 s, compute 0.125 s, wait 0.625 s, 6 coupling "
              "iterations (2 per step), wall 0.8 s\n")
        << "pieces of " << piece;
    // What explainFailure reads: every line, untagged.
    EXPECT_NE(o.text().find("done: 3 steps, t = 2.005e-05 s, wall 0.8 s"), std::string::npos);
    EXPECT_EQ(o.text().find("<stdout>"), std::string::npos);
  }
}

TEST(LaunchOutput, AFailedLaunchShowsTheHeldLinesLabelledByProgram) {
  const auto plan = mpmdPlan();
  std::ostringstream terminal;
  coupler::LaunchOutput o(plan, terminal);
  o.feed("[7,2]<stderr>:ice_solver: error: ice: non-physical state\n" + kFluidClosing);
  o.finish(false);
  EXPECT_EQ(terminal.str(),
            "ice_solver: error: ice: non-physical state\n"
            "ice_solver: coupling (ice_solver, coupled to 'mpm'): computed 0.125 s, 0.625 s in exchange (rank to rank)\n"
            "ice_solver: done: 3 steps, t = 2.005e-05 s, wall 0.8 s, 3.7 steps/s, 5e+02 cell-steps/s\n");
  const auto failed = coupler::explainFailure(plan, o.text());
  ASSERT_FALSE(failed.empty());
  EXPECT_EQ(failed[0], "coupler: ice_solver failed: ice: non-physical state");
}

TEST(LaunchOutput, TheOpenFoamSolversLinesGoToItsLogAndItsTailShowsOnFailure) {
  const auto dir = std::filesystem::temp_directory_path() / ("mpmice_launch_output_" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  core::Scene scene = core::parseScene(
      "scene: flap\nmesh: {dim: 2, lower: [0, 0], upper: [1, 1], cells: [4, 4]}\ntime: {end: 1}\n"
      "materials:\n  - {name: air, kind: fluid, eos: {type: ideal_gas, gamma: 1.4}}\n"
      "geometry:\n  - {shape: {type: box, lo: [0, 0], hi: [1, 1]}, material: air, pressure: 1}\n",
      "flap.yaml");
  scene.output.directory = dir.string();
  coupler::LaunchPlan plan;
  plan.programs = {"mpm_solver", "pimpleFoam"};
  plan.ranks = {1, 1};
  const std::string log = core::logFilePath(scene, "pimpleFoam");
  std::ostringstream terminal;
  {
    coupler::LaunchOutput o(plan, terminal, std::make_unique<core::LogFile>(log, "pimpleFoam", scene, "coupler"), 1);
    o.feed("[3,1]<stdout>:Time = 0.01\n[3,0]<stdout>:window 1\n[3,1]<stdout>:Courant Number mean: 0.1\n");
    o.feed("[3,1]<stderr>:--> FOAM FATAL ERROR: unknown patch\n");
    o.finish(false);
  }
  EXPECT_EQ(terminal.str(), "window 1\ncoupler: the last lines of " + log +
                                ":\n  Time = 0.01\n  Courant Number mean: 0.1\n  --> FOAM FATAL ERROR: unknown patch\n");
  const std::string text = core::readTextFile(log);
  EXPECT_NE(text.find("==== pimpleFoam (launched by coupler 0."), std::string::npos) << text;
  EXPECT_NE(text.find("\nTime = 0.01\nCourant Number mean: 0.1\n--> FOAM FATAL ERROR: unknown patch\n"),
            std::string::npos)
      << text;
  std::filesystem::remove_all(dir);
}

TEST(LaunchOutput, ReadsTheClosingLinesOfEachSide) {
  coupler::SideSummary s;
  EXPECT_TRUE(coupler::LaunchOutput::readClosingLine("done: 1 step, t = 1e-06 s, wall 0.0 s, 1 steps/s", s));
  EXPECT_EQ(*s.steps, 1);
  EXPECT_FALSE(coupler::LaunchOutput::readClosingLine("step 1  t = 1.0e-06", s));
  EXPECT_FALSE(coupler::LaunchOutput::readClosingLine("warning: done: nothing", s));
  // Without the compute/wait split there is no summary: the held lines are shown instead.
  EXPECT_EQ(coupler::LaunchOutput::summaryLine("mpm_solver", 1, s, std::nullopt), "");
}

// The solid's progress lines become the launch's one coupled progress line: step, simulated time,
// the estimate of the time left and the coupling iterations (this step, and per step so far).
TEST(LaunchOutput, TheSolidsProgressBecomesOneCoupledProgressLine) {
  const std::string progress =
      "[7,0]<stdout>:step 120  t = 1.200e-04 / 1.500e-04 s (80.0%)  dt = 1.0e-06  wall 1.6 s  ETA 0.4 s  iters=3  "
      "iters_total=300  lin_iters=12\n";
  EXPECT_EQ(*coupler::LaunchOutput::coupledProgressLine(progress.substr(14, progress.size() - 15)),
            "coupler: step 120  t = 1.200e-04 / 1.500e-04 s (80.0%)  ETA 0.4 s  coupling iterations 3 (2.5 per step)");
  EXPECT_EQ(*coupler::LaunchOutput::coupledProgressLine("step 1  t = 0.000e+00 / 1.0e+00 s (0.0%)  dt = 1.0e-06  wall 0.0 s  ETA --"),
            "coupler: step 1  t = 0.000e+00 / 1.0e+00 s (0.0%)  ETA --");
  // What set the step (dt_by=, volume_run.cpp) is carried over.
  EXPECT_EQ(*coupler::LaunchOutput::coupledProgressLine(
                "step 4  t = 4.000e-06 / 1.0e+00 s (0.0%)  dt = 1.0e-06  wall 0.1 s  ETA --  iters=1  iters_total=4  "
                "dt_by=fluid"),
            "coupler: step 4  t = 4.000e-06 / 1.0e+00 s (0.0%)  ETA --  coupling iterations 1 (1 per step)  dt set by "
            "the fluid side");
  EXPECT_EQ(*coupler::LaunchOutput::coupledProgressLine(
                "step 4  t = 4.000e-06 / 1.0e+00 s (0.0%)  dt = 1.0e-06  wall 0.1 s  ETA --  dt_by=time.end"),
            "coupler: step 4  t = 4.000e-06 / 1.0e+00 s (0.0%)  ETA --  dt set by time.end");
  EXPECT_FALSE(coupler::LaunchOutput::coupledProgressLine("step 10  t = 1.0e-05 / 2.0e-05 s (50.0%)"));
  EXPECT_FALSE(coupler::LaunchOutput::coupledProgressLine("done: 3 steps, t = 2.005e-05 s, wall 0.9 s"));

  for (const bool inPlace : {false, true}) {
    const auto plan = mpmdPlan();
    std::ostringstream terminal;
    coupler::LaunchOutput o(plan, terminal, nullptr, -1, inPlace);
    const std::string later =
        "[7,0]<stdout>:step 150  t = 1.500e-04 / 1.500e-04 s (100.0%)  dt = 1.0e-06  wall 2.0 s  ETA 0.0 s  iters=1  "
        "iters_total=330\n";
    feedInPieces(o, progress + later + "[7,2]<stderr>:ice note\n" + progress + kSolidClosing + kFluidClosing, 5);
    o.finish(true);
    const std::string first =
        "coupler: step 120  t = 1.200e-04 / 1.500e-04 s (80.0%)  ETA 0.4 s  coupling iterations 3 (2.5 per step)";
    const std::string second =
        "coupler: step 150  t = 1.500e-04 / 1.500e-04 s (100.0%)  ETA 0.0 s  coupling iterations 1 (2.2 per step)";
    const std::string summaries =
        "coupler: mpm_solver (2 ranks): 3 steps to t = 2.005e-05 s, compute 0.5 s, wait 0.25 s, 6 coupling "
        "iterations (2 per step), wall 0.9 s\n"
        "coupler: ice_solver (1 rank): 3 steps to t = 2.005e-05 s, compute 0.125 s, wait 0.625 s, 6 coupling "
        "iterations (2 per step), wall 0.8 s\n";
    if (inPlace)  // one line, rewritten; a line of another kind first ends it
      EXPECT_EQ(terminal.str(), "\r" + first + "\033[K\r" + second + "\033[K\nice note\n\r" + first + "\033[K\n" + summaries);
    else
      EXPECT_EQ(terminal.str(), first + "\n" + second + "\nice note\n" + first + "\n" + summaries);
    EXPECT_NE(o.text().find("step 150  t = 1.500e-04"), std::string::npos) << "the text explainFailure reads";
  }
}
