#pragma once
/// @brief A whole study: the variant scene of every point (checked by the scene schema before
/// anything is created), one run folder per point inside the study folder, each run bounded in
/// time, `<study>.csv` (one row per point) and the Pareto plot `<study>_pareto.png`.
#include <ostream>
#include <string>
#include <vector>

#include "study/study_file.h"

namespace mpmice::study {

struct StudyOptions {
  std::string out;      // the study folder (created; an existing non-empty one only with resume)
  bool resume = false;  // finish a study folder this tool made: skip the points whose run is ok
  bool dryRun = false;  // print the points and their commands, create nothing
  std::string binDir;   // the build folder: <bin>/coupler/mpmice, <bin>/coupler/coupler
  std::string mpirun;   // the launch helper for `ranks` > 1 with mpmice
};

/// The command of one point (its variant scene at `scene`).
std::vector<std::string> pointCommand(const Study& s, const Point& p, const std::string& scene, const StudyOptions& o);

/// Runs the study. Returns 0 when every point is ok, 3 when the CSV is written but some point
/// failed, timed out or could not be measured; throws StudyError on a bad study, a bad key path
/// or a refused study folder (nothing run); 128 + signal when SIGINT / SIGTERM stopped it (the
/// running point gets the signal and stays without a result).
int runStudy(const Study& s, const StudyOptions& o, std::ostream& out, std::ostream& err);

}  // namespace mpmice::study
