#pragma once
/// @brief The study file (docs/tradeoffs.md): the base scene, the program, the reference, the
/// time limit per run, settings applied to every point, and the axes (a full grid) or an explicit
/// list of points. Every error names the study file and the key.
#include <stdexcept>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "study/grid.h"

namespace mpmice::study {

class StudyError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// How each point runs.
enum class Program { Mpmice, CouplerRun };

/// The cost axis of the Pareto plot: the wall time of each run, or its CPU time (user + system of
/// the program and every process it started; steadier than the wall time on a shared machine,
/// and it counts every rank of a parallel run).
enum class Cost { Wall, Cpu };

struct Study {
  std::string file;        // the study file as given
  std::string name;        // `study`, default: the file's stem
  std::string scene;       // the base scene, resolved against the study file's folder
  Program program = Program::Mpmice;
  std::string reference;   // a name of the reference registry (study/reference/references.h)
  std::string referenceCurve;   // `reference_curve`, resolved against the study file's folder (probe_curve)
  std::string referenceColumn;  // `reference_column`: the probe column compared (probe_curve)
  double timeLimit = 3600; // [s] per run
  int repeats = 1;         // runs per point: the wall time is their median (the machine is noisy)
  Cost cost = Cost::Wall;  // `cost: wall | cpu`, the Pareto plot's time axis
  std::vector<std::pair<std::string, YAML::Node>> set;  // applied to every point, before its own settings
  std::vector<Axis> axes;  // the full grid, or empty with `points`
  std::vector<Point> points;  // expanded: the grid or the explicit list
  std::vector<std::string> columns;  // the settings' keys, in order of first appearance
};

/// Reads and checks a study file (unknown keys, types, the reference name, `ranks` only with
/// mpmice). Throws StudyError naming the file and the key.
Study readStudy(const std::string& path);

/// The base scene with the study's `set` and the point's settings applied (every key but
/// `ranks`), `output.directory` set to `runDir`. Throws StudyError naming the study file and the
/// key path when a path does not fit the scene.
YAML::Node variantScene(const Study& s, const YAML::Node& base, const Point& p, const std::string& runDir);

/// The point's `ranks` setting (1 when the point has none).
int pointRanks(const Point& p);

}  // namespace mpmice::study
