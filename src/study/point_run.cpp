#include "study/point_run.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <regex>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "coupler/cli/process.h"
#include "coupler/cli/stop_signals.h"

namespace mpmice::study {

RunCounts parseRunLog(const std::string& text) {
  RunCounts c;
  std::smatch m;
  static const std::regex coupling(R"(coupling: schedule \S+, (\d+) iterations in (\d+) steps \(([0-9.eE+-]+) per step\))");
  static const std::regex done(R"(done: (\d+) steps)");
  if (std::regex_search(text, m, coupling)) {
    c.steps = std::stol(m[2].str());
    c.iterationsPerStep = std::stod(m[3].str());
  } else if (std::regex_search(text, m, done)) {
    c.steps = std::stol(m[1].str());
  }
  return c;
}

std::string programNote(const std::string& text) {
  // Open MPI's own text: blocks between lines of dashes (the MPI_ABORT banner, "mpirun detected
  // that ..."), lines tagged [host:pid], and the launcher's own lines.
  static const std::regex rule(R"(^\s*-{10,}\s*$)");
  static const std::regex tagged(R"(^\[[^\]]*:\d+\])");
  static const std::regex launcher(R"(^(prterun|mpirun|orterun|Primary job|PRTE|--> ))");
  std::istringstream in(text);
  std::string line, last, ours;
  bool inBanner = false;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (std::regex_search(line, rule)) {
      inBanner = !inBanner;
      continue;
    }
    if (line.find_first_not_of(" \t") == std::string::npos) continue;
    last = line;
    if (!inBanner && !std::regex_search(line, tagged) && !std::regex_search(line, launcher)) ours = line;
  }
  return ours.empty() ? last : ours;
}

namespace {
double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}
}  // namespace

PointResult runPoint(const std::vector<std::string>& argv, const std::string& runDir, double timeLimit, int repeats,
                     const Reference& ref, const RunFiles& files) {
  PointResult r;
  coupler::TimedRun run;
  std::string log;
  for (int k = 1; k <= repeats; ++k) {
    log = runDir + (k == 1 ? std::string("/run.log") : "/run_" + std::to_string(k) + ".log");
    run = coupler::runToFileWithin(argv, log, timeLimit);
    r.walls.push_back(run.wallSeconds);
    r.cpus.push_back(run.cpuSeconds);
    r.peakRssMb = std::max(r.peakRssMb, double(run.peakRssKb) / 1024.0);
    if (run.timedOut || run.stoppedBy != 0 || run.status != 0) break;
  }
  r.stoppedBy = run.stoppedBy;
  r.exitCode = run.status;
  r.wallSeconds = median(r.walls);
  r.cpuSeconds = median(r.cpus);
  r.error = std::numeric_limits<double>::quiet_NaN();
  std::ifstream in(log);
  std::stringstream text;
  text << in.rdbuf();
  const RunCounts counts = parseRunLog(text.str());
  r.steps = counts.steps;
  r.iterationsPerStep = counts.iterationsPerStep;
  if (run.stoppedBy != 0) {
    r.status = "stopped";
    r.note = "stopped by " + coupler::signalName(run.stoppedBy);
    return r;
  }
  if (run.timedOut) {
    std::ostringstream limit;
    limit << timeLimit;
    r.status = "timeout";
    r.note = "stopped at the time limit of " + limit.str() + " s";
    return r;
  }
  if (run.status != 0) {
    r.status = "failed";
    r.note = programNote(text.str());
    return r;
  }
  try {
    r.error = ref.error(files);
    if (!std::isfinite(r.error)) throw std::runtime_error("the error is not finite");
    r.status = "ok";
  } catch (const std::exception& e) {
    r.error = std::numeric_limits<double>::quiet_NaN();
    r.status = "no_error";
    r.note = ref.name + ": " + e.what();
  }
  return r;
}

std::string resultYaml(const PointResult& r) {
  std::ostringstream err;
  err << std::setprecision(12) << r.error;
  YAML::Emitter e;
  e << YAML::BeginMap;
  e << YAML::Key << "status" << YAML::Value << r.status;
  e << YAML::Key << "exit_code" << YAML::Value << r.exitCode;
  e << YAML::Key << "wall_s" << YAML::Value << r.wallSeconds;
  e << YAML::Key << "walls_s" << YAML::Value << YAML::Flow << r.walls;
  e << YAML::Key << "cpu_s" << YAML::Value << r.cpuSeconds;
  e << YAML::Key << "cpus_s" << YAML::Value << YAML::Flow << r.cpus;
  e << YAML::Key << "peak_rss_mb" << YAML::Value << r.peakRssMb;
  e << YAML::Key << "steps" << YAML::Value << r.steps;
  e << YAML::Key << "iterations_per_step" << YAML::Value << r.iterationsPerStep;
  e << YAML::Key << "error" << YAML::Value << (std::isfinite(r.error) ? err.str() : std::string("nan"));
  e << YAML::Key << "note" << YAML::Value << r.note;
  e << YAML::EndMap;
  return std::string(e.c_str()) + "\n";
}

PointResult readResult(const std::string& file) {
  const YAML::Node n = YAML::LoadFile(file);
  PointResult r;
  r.status = n["status"].as<std::string>();
  r.exitCode = n["exit_code"].as<int>();
  r.wallSeconds = n["wall_s"].as<double>();
  r.walls = n["walls_s"] ? n["walls_s"].as<std::vector<double>>() : std::vector<double>{r.wallSeconds};
  // Results written before the CPU time was recorded have none: NaN, so they drop out of a CPU plot.
  r.cpuSeconds = n["cpu_s"] ? n["cpu_s"].as<double>() : std::numeric_limits<double>::quiet_NaN();
  r.cpus = n["cpus_s"] ? n["cpus_s"].as<std::vector<double>>() : std::vector<double>{r.cpuSeconds};
  r.peakRssMb = n["peak_rss_mb"].as<double>();
  r.steps = n["steps"].as<long>();
  r.iterationsPerStep = n["iterations_per_step"].as<double>();
  const std::string err = n["error"].as<std::string>();
  r.error = err == "nan" ? std::numeric_limits<double>::quiet_NaN() : std::stod(err);
  r.note = n["note"] ? n["note"].as<std::string>() : "";
  return r;
}

}  // namespace mpmice::study
