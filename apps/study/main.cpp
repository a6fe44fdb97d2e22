// study: the speed-accuracy trade of a scene (docs/tradeoffs.md). Runs the scene over a grid of
// settings (a study file: base scene, program, axes or points, reference), one bounded run per
// point in its own folder, and writes <study>.csv and the Pareto plot <study>_pareto.png.
//
// Sample runs:  study configs/studies/cylinder_trade.yaml --out studies/cylinder_trade
//               study configs/studies/cylinder_trade.yaml --out studies/cylinder_trade --resume
//               study configs/studies/cylinder_trade.yaml --out studies/x --dry-run
// Exit: 0 every point ok; 3 the CSV is written but some point failed, timed out or has no error;
// 2 a bad study file, key path or command line, or a refused study folder (nothing run).
#include <CLI/CLI.hpp>

#include <filesystem>
#include <iostream>
#include <string>

#include "core/version.h"
#include "study/study_run.h"

namespace {
/// The build folder: this program is <build>/study/study.
std::string defaultBinDir() {
  std::error_code ec;
  const auto self = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::string(".") : self.parent_path().parent_path().string();
}
}  // namespace

int main(int argc, char** argv) {
  std::string file;
  mpmice::study::StudyOptions o;
  o.binDir = defaultBinDir();
  o.mpirun = MPMICE_MPIRUN_PATH;
  CLI::App app("The speed-accuracy trade of a scene: runs it over a grid of settings (the study file), each "
               "point bounded in time in its own folder, and writes <study>.csv (settings, error against the "
               "reference, wall time, steps, iterations per step, peak RSS, status) and the Pareto plot "
               "<study>_pareto.png (error against wall time, log-log). docs/tradeoffs.md.",
               "study");
  app.set_help_flag("-h,--help", "print this help and exit");
  app.set_version_flag("-V,--version", mpmice::core::versionLine("study"), "print the version and exit");
  app.add_option("study.yaml", file, "the study file (docs/tradeoffs.md)")->required();
  app.add_option("--out", o.out, "the study folder (default: ./<study name>); an existing non-empty one is refused");
  app.add_flag("--resume", o.resume, "finish a study folder this tool started: points already ok are skipped");
  app.add_flag("--dry-run", o.dryRun, "print the points and their commands; run and create nothing");
  app.add_option("--bin-dir", o.binDir, "the build folder holding coupler/mpmice and coupler/coupler")
      ->capture_default_str();
  app.get_formatter()->label("Usage", "usage");
  app.footer("Sample runs:\n  study configs/studies/cylinder_trade.yaml --out studies/cylinder_trade\n"
             "  study configs/studies/cylinder_trade.yaml --out studies/cylinder_trade --resume\n"
             "Exit: 0 every point ok; 3 some point not ok (the CSV says which); 2 bad input, nothing run.");
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    std::cout << app.help();
    return 0;
  } catch (const CLI::CallForVersion& e) {
    std::cout << e.what() << "\n";
    return 0;
  } catch (const CLI::ParseError& e) {
    std::cerr << "study: " << e.what() << "\nusage: study study.yaml [--out DIR] [--resume] [--dry-run] [--bin-dir DIR]\n";
    return 2;
  }
  try {
    const auto s = mpmice::study::readStudy(file);
    if (o.out.empty()) o.out = s.name;
    return mpmice::study::runStudy(s, o, std::cout, std::cerr);
  } catch (const mpmice::study::StudyError& e) {
    std::cerr << "study: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "study: " << e.what() << "\n";
    return 1;
  }
}
